//! Reading an XSD into [`Schema`] tables. Only the XSD features the OpenSCENARIO schemas use are
//! understood (complexType with sequence/choice/all/group and attributes, simpleContent extension,
//! simpleType restriction/enumeration/union, `appinfo` "deprecated"); anything else is an error,
//! so a new schema version that needs more cannot be read half-way.

use crate::model::{group_key, AttributeDecl, ComplexType, ElementDecl, Literal, Particle, Primitive, Schema, SimpleKind, Term};
use roxmltree::Node;
use std::collections::BTreeMap;

pub(crate) fn parse(minor: u16, text: &str) -> Result<Schema, String> {
    let doc = roxmltree::Document::parse(text).map_err(|e| e.to_string())?;
    let top = doc.root_element();
    let mut complex = BTreeMap::new();
    let mut simple_nodes = BTreeMap::new();
    let mut roots = Vec::new();
    for node in elements(top) {
        let name = node.attribute("name").unwrap_or_default().to_string();
        match node.tag_name().name() {
            "element" => roots.push(element_decl(node)?),
            "complexType" => {
                complex.insert(name.clone(), complex_type(node, &name)?);
            }
            "group" => {
                let content = elements(node).find(|n| is_model(n)).map(|n| particle(n)).transpose()?;
                let key = group_key(&name);
                complex.insert(key.clone(), ComplexType { name: key, content, attributes: vec![], has_text: false, deprecated: false });
            }
            "simpleType" => {
                simple_nodes.insert(name, node);
            }
            "annotation" => {}
            other => return Err(format!("unexpected top-level xsd:{other}")),
        }
    }
    let mut simple = BTreeMap::new();
    for (name, node) in &simple_nodes {
        simple.insert(name.clone(), simple_kind(*node, &simple_nodes, 0)?);
    }
    if roots.is_empty() {
        return Err("the schema declares no document element".into());
    }
    Ok(Schema { minor, roots, complex, simple })
}

fn elements<'a, 'i>(node: Node<'a, 'i>) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(|n| n.is_element())
}

fn is_model(n: &Node) -> bool {
    matches!(n.tag_name().name(), "sequence" | "choice" | "all" | "group")
}

fn deprecated(node: Node) -> bool {
    elements(node)
        .filter(|n| n.tag_name().name() == "annotation")
        .flat_map(elements)
        .any(|n| n.tag_name().name() == "appinfo" && n.text().is_some_and(|t| t.trim() == "deprecated"))
}

fn occurs(node: Node, attr: &str) -> Result<Option<u32>, String> {
    match node.attribute(attr) {
        None => Ok(Some(1)),
        Some("unbounded") => Ok(None),
        Some(v) => v.parse().map(Some).map_err(|_| format!("bad {attr}=\"{v}\"")),
    }
}

fn bounds(node: Node) -> Result<(u32, Option<u32>), String> {
    let min = occurs(node, "minOccurs")?.ok_or("minOccurs cannot be unbounded")?;
    Ok((min, occurs(node, "maxOccurs")?))
}

fn element_decl(node: Node) -> Result<ElementDecl, String> {
    let name = node.attribute("name").ok_or("xsd:element without a name")?;
    let type_name = node.attribute("type").ok_or_else(|| format!("element {name} has no type"))?;
    Ok(ElementDecl { name: name.to_string(), type_name: type_name.to_string(), deprecated: deprecated(node) })
}

fn particle(node: Node) -> Result<Particle, String> {
    let (min, max) = bounds(node)?;
    let term = match node.tag_name().name() {
        "element" => Term::Element(element_decl(node)?),
        "group" => Term::Group(node.attribute("ref").ok_or("xsd:group without ref")?.to_string()),
        kind @ ("sequence" | "choice" | "all") => {
            let items = elements(node).filter(|n| n.tag_name().name() != "annotation").map(particle).collect::<Result<Vec<_>, _>>()?;
            match kind {
                "sequence" => Term::Sequence(items),
                "choice" => Term::Choice(items),
                _ => Term::All(items),
            }
        }
        other => return Err(format!("unexpected xsd:{other} in a content model")),
    };
    Ok(Particle { term, min, max })
}

fn attribute(node: Node) -> Result<AttributeDecl, String> {
    let name = node.attribute("name").ok_or("xsd:attribute without a name")?;
    let type_name = node.attribute("type").ok_or_else(|| format!("attribute {name} has no type"))?;
    Ok(AttributeDecl {
        name: name.to_string(),
        type_name: type_name.to_string(),
        required: node.attribute("use") == Some("required"),
        deprecated: deprecated(node),
    })
}

fn complex_type(node: Node, name: &str) -> Result<ComplexType, String> {
    let mut ty = ComplexType { name: name.to_string(), content: None, attributes: vec![], has_text: false, deprecated: deprecated(node) };
    for child in elements(node) {
        match child.tag_name().name() {
            "annotation" => {}
            "attribute" => ty.attributes.push(attribute(child)?),
            "simpleContent" => {
                ty.has_text = true;
                for ext in elements(child) {
                    for a in elements(ext).filter(|n| n.tag_name().name() == "attribute") {
                        ty.attributes.push(attribute(a)?);
                    }
                }
            }
            _ if is_model(&child) => ty.content = Some(particle(child)?),
            other => return Err(format!("complexType {name}: unexpected xsd:{other}")),
        }
    }
    Ok(ty)
}

/// Folds a simple type into one [`SimpleKind`]: unions merge their members (OpenSCENARIO's unions
/// are always "one primitive or enumeration, plus `parameter` and/or `expression`").
fn simple_kind(node: Node, named: &BTreeMap<String, Node>, depth: usize) -> Result<SimpleKind, String> {
    let p = partial(node, named, depth)?;
    Ok(SimpleKind {
        primitive: p.primitive.unwrap_or(Primitive::String),
        literals: p.literals,
        allows_parameter: p.parameter,
        allows_expression: p.expression,
        deprecated: p.deprecated,
    })
}

#[derive(Default)]
struct Partial {
    primitive: Option<Primitive>,
    literals: Option<Vec<Literal>>,
    parameter: bool,
    expression: bool,
    deprecated: bool,
}

impl Partial {
    fn merge(&mut self, other: Partial) {
        self.primitive = self.primitive.or(other.primitive);
        if other.literals.is_some() {
            self.literals = other.literals;
        }
        self.parameter |= other.parameter;
        self.expression |= other.expression;
    }
}

fn by_name(name: &str, named: &BTreeMap<String, Node>, depth: usize) -> Result<Partial, String> {
    match name {
        "parameter" => Ok(Partial { parameter: true, ..Partial::default() }),
        "expression" => Ok(Partial { expression: true, ..Partial::default() }),
        _ => match Primitive::from_xsd(name) {
            Some(p) => Ok(Partial { primitive: Some(p), ..Partial::default() }),
            None => {
                let n = named.get(name).ok_or_else(|| format!("unknown simple type {name}"))?;
                partial(*n, named, depth + 1)
            }
        },
    }
}

fn partial(node: Node, named: &BTreeMap<String, Node>, depth: usize) -> Result<Partial, String> {
    if depth > 16 {
        return Err("simple types nested too deep".into());
    }
    let mut out = Partial { deprecated: deprecated(node), ..Partial::default() };
    for child in elements(node) {
        match child.tag_name().name() {
            "annotation" => {}
            "union" => {
                for m in child.attribute("memberTypes").unwrap_or_default().split_whitespace() {
                    out.merge(by_name(m, named, depth)?);
                }
                for inner in elements(child).filter(|n| n.tag_name().name() == "simpleType") {
                    out.merge(partial(inner, named, depth + 1)?);
                }
            }
            "restriction" => {
                if elements(child).any(|n| n.tag_name().name() == "pattern") {
                    // The `parameter` and `expression` types themselves; named uses resolve above.
                    continue;
                }
                let base = child.attribute("base").ok_or("restriction without base")?;
                out.merge(by_name(base, named, depth)?);
                let literals: Vec<Literal> = elements(child)
                    .filter(|n| n.tag_name().name() == "enumeration")
                    .map(|n| Literal { value: n.attribute("value").unwrap_or_default().to_string(), deprecated: deprecated(n) })
                    .collect();
                if !literals.is_empty() {
                    out.literals = Some(literals);
                }
            }
            other => return Err(format!("unexpected xsd:{other} in a simple type")),
        }
    }
    Ok(out)
}
