//! The schema as data: what a complex type may contain and what its attributes are.

use std::collections::BTreeMap;

/// One OpenSCENARIO schema version.
#[derive(Debug)]
pub struct Schema {
    pub minor: u16,
    /// The allowed document elements (`OpenSCENARIO`; the schemas also declare `OpenScenario`).
    pub roots: Vec<ElementDecl>,
    pub complex: BTreeMap<String, ComplexType>,
    pub simple: BTreeMap<String, SimpleKind>,
}

/// A complex type: its content model and attributes.
#[derive(Debug, Clone)]
pub struct ComplexType {
    pub name: String,
    /// `None` for a type with no child elements.
    pub content: Option<Particle>,
    pub attributes: Vec<AttributeDecl>,
    /// The element carries text (XSD simpleContent), e.g. `CustomCommandAction`.
    pub has_text: bool,
    pub deprecated: bool,
}

#[derive(Debug, Clone)]
pub struct AttributeDecl {
    pub name: String,
    /// A simple type name: the schema's own (`Double`, `Rule`, …) or a built-in (`xsd:string`).
    pub type_name: String,
    pub required: bool,
    pub deprecated: bool,
}

#[derive(Debug, Clone)]
pub struct ElementDecl {
    pub name: String,
    pub type_name: String,
    pub deprecated: bool,
}

/// A term with its occurrence bounds; `max == None` means unbounded.
#[derive(Debug, Clone)]
pub struct Particle {
    pub term: Term,
    pub min: u32,
    pub max: Option<u32>,
}

#[derive(Debug, Clone)]
pub enum Term {
    Element(ElementDecl),
    Sequence(Vec<Particle>),
    Choice(Vec<Particle>),
    All(Vec<Particle>),
    /// A named `xsd:group`, resolved through [`Schema::group`] at match time.
    Group(String),
}

/// The value space of an attribute, reduced to what a checker needs.
#[derive(Debug, Clone, PartialEq)]
pub struct SimpleKind {
    pub primitive: Primitive,
    /// Allowed literals of an enumeration (`None`: any value of the primitive).
    pub literals: Option<Vec<Literal>>,
    /// `$name` references are allowed.
    pub allows_parameter: bool,
    /// `${...}` expressions are allowed.
    pub allows_expression: bool,
    pub deprecated: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Literal {
    pub value: String,
    pub deprecated: bool,
}

/// XSD built-in types used by OpenSCENARIO.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Primitive {
    String,
    Boolean,
    Double,
    Int,
    UnsignedInt,
    UnsignedShort,
    DateTime,
}

impl Primitive {
    /// The XSD name, as messages quote it.
    pub fn xsd_name(self) -> &'static str {
        match self {
            Primitive::String => "string",
            Primitive::Boolean => "boolean",
            Primitive::Double => "double",
            Primitive::Int => "int",
            Primitive::UnsignedInt => "unsignedInt",
            Primitive::UnsignedShort => "unsignedShort",
            Primitive::DateTime => "dateTime",
        }
    }

    pub(crate) fn from_xsd(name: &str) -> Option<Primitive> {
        Some(match name.strip_prefix("xsd:").unwrap_or(name) {
            "string" => Primitive::String,
            "boolean" => Primitive::Boolean,
            "double" => Primitive::Double,
            "int" => Primitive::Int,
            "unsignedInt" => Primitive::UnsignedInt,
            "unsignedShort" => Primitive::UnsignedShort,
            "dateTime" => Primitive::DateTime,
            _ => return None,
        })
    }
}

impl Schema {
    pub fn complex_type(&self, name: &str) -> Option<&ComplexType> {
        self.complex.get(name)
    }

    /// The value space of a simple type name (schema-defined or built-in).
    pub fn simple_kind(&self, type_name: &str) -> Option<SimpleKind> {
        if let Some(kind) = self.simple.get(type_name) {
            return Some(kind.clone());
        }
        Primitive::from_xsd(type_name).map(|primitive| SimpleKind {
            primitive,
            literals: None,
            allows_parameter: false,
            allows_expression: false,
            deprecated: false,
        })
    }

    /// The content of a named group (stored as a complex type with a reserved name).
    pub fn group(&self, name: &str) -> Option<&Particle> {
        self.complex.get(&group_key(name)).and_then(|t| t.content.as_ref())
    }

    /// Every element declaration reachable from a type's content model, in schema order.
    pub fn child_elements<'s>(&'s self, ty: &'s ComplexType) -> Vec<&'s ElementDecl> {
        let mut out = Vec::new();
        if let Some(p) = &ty.content {
            self.collect_elements(p, &mut out, 0);
        }
        out
    }

    fn collect_elements<'s>(&'s self, p: &'s Particle, out: &mut Vec<&'s ElementDecl>, depth: usize) {
        if depth > 64 {
            return;
        }
        match &p.term {
            Term::Element(e) => out.push(e),
            Term::Sequence(items) | Term::Choice(items) | Term::All(items) => {
                for i in items {
                    self.collect_elements(i, out, depth + 1);
                }
            }
            Term::Group(name) => {
                if let Some(g) = self.group(name) {
                    self.collect_elements(g, out, depth + 1);
                }
            }
        }
    }

    /// Complex types proper (named groups excluded), in name order.
    pub fn types(&self) -> impl Iterator<Item = &ComplexType> {
        self.complex.values().filter(|t| !t.name.starts_with(GROUP_PREFIX))
    }
}

pub(crate) const GROUP_PREFIX: &str = "group:";

pub(crate) fn group_key(name: &str) -> String {
    format!("{GROUP_PREFIX}{name}")
}
