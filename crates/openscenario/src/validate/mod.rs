//! Checking an OpenSCENARIO file against the schema of its declared version, and against the
//! rules the schema cannot express, reporting every problem at once.
//!
//! This is `osc2cr check`'s first pass. Unlike the reader (which stops at the first hard error
//! because it builds a model), it walks the whole positioned tree: unknown or misplaced elements,
//! missing children and attributes, values that are not of their type, parameters and variables
//! that are not declared or whose values do not fit where they are used, expressions that cannot
//! be evaluated, ValueConstraints that fail, value ranges of the standard, and deprecated
//! elements, attributes and literals. An element the declared version does not know but a later
//! one does is a warning (esmini and our reader accept such mixtures), not an error.

mod declarations;
mod names;
mod operators;
pub mod overrides;
mod rules;
mod values;

use crate::error::{ErrorKind, Location};
use crate::params::{self, ResolveError};
use crate::xml::{self, Attr, Elem};
use rules::{range_rules, Replacement, DEPRECATED_WITH_REPLACEMENT};
use schema::content::{match_children, ContentProblem};
use schema::simple::{check_literal, check_primitive, LiteralCheck};
use schema::{Primitive, Schema, SimpleKind};
use serde::Serialize;
use std::path::Path;
use std::sync::Arc;

/// How bad a finding is. `Error`: the file is wrong; `Warning`: legal but deprecated or
/// version-mixed; `Info`: legal, said for completeness (a parameter converted to another type).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
    Info,
}

/// One problem, positioned.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    pub severity: Severity,
    pub location: Location,
    pub message: String,
}

/// Validates one file. Never fails: an unreadable or malformed file is itself a finding.
/// `injected` are `--param NAME=VALUE` overrides of global parameters, checked as such.
pub fn validate_file(path: &Path, injected: &[(String, String)]) -> Vec<Finding> {
    validate_readable_file(path, injected).unwrap_or_else(|e| vec![Finding { severity: Severity::Error, location: e.location, message: e.message }])
}

/// Like [`validate_file`], but a file that cannot be read or is not well-formed XML (empty,
/// cut off, too large) is the `Err`: no reading, lenient or not, can go on from it, so a caller
/// that lets `--lenient` pass the schema's findings says it as what it is.
pub fn validate_readable_file(path: &Path, injected: &[(String, String)]) -> Result<Vec<Finding>, crate::Error> {
    xml::read_file(path).map(|doc| validate_doc(&doc, injected))
}

/// Validates text as if it were the file `path`.
pub fn validate_str(path: &Path, text: &str, injected: &[(String, String)]) -> Vec<Finding> {
    match xml::parse_str(path, text) {
        Ok(doc) => validate_doc(&doc, injected),
        Err(e) => vec![Finding { severity: Severity::Error, location: e.location, message: e.message }],
    }
}

fn validate_doc(doc: &xml::Doc, injected: &[(String, String)]) -> Vec<Finding> {
    let (minor, version_note) = declared_minor(&doc.root);
    let in_catalog = doc.root.children_unmarked().iter().any(|c| c.name == "Catalog");
    let mut w = Walker {
        file: doc.file.clone(),
        findings: Vec::new(),
        scopes: Vec::new(),
        variables: Vec::new(),
        declared: minor,
        injected: injected.to_vec(),
        in_catalog,
        at_root: true,
    };
    if let Some((pos, note)) = version_note {
        w.push(Severity::Warning, pos, note);
    }
    let Some(schema) = schema::for_minor(minor) else { return w.findings };
    let root = &doc.root;
    // the schemas also declare a global <OpenScenario>, but a document's root is <OpenSCENARIO>
    let decl = all_schemas(minor).find_map(|s| s.roots.iter().find(|r| r.name == root.name).map(|r| (s, r))).filter(|_| root.name == "OpenSCENARIO");
    let Some(decl) = decl else {
        w.push(Severity::Error, root.pos, format!("<{}> is not an OpenSCENARIO document (its root element must be <OpenSCENARIO>)", root.name));
        return w.findings;
    };
    w.element(root, schema, &decl.1.type_name.clone());
    w.findings.sort_by_key(|f| (f.location.line, f.location.col));
    w.findings
}

/// The schema version a file declares (FileHeader revMinor), and a note when it is not one we have.
fn declared_minor(root: &Elem) -> (u16, Option<(xml::Pos, String)>) {
    let Some(header) = root.child("FileHeader") else { return (schema::NEWEST_MINOR, None) };
    let major = header.attr("revMajor").and_then(|a| a.value.trim().parse::<u32>().ok());
    let minor = header.attr("revMinor").and_then(|a| a.value.trim().parse::<u32>().ok());
    match (major, minor) {
        (Some(1), Some(m)) if m <= u32::from(schema::NEWEST_MINOR) => (m as u16, None),
        (Some(ma), Some(mi)) => (
            schema::NEWEST_MINOR,
            Some((header.pos, format!("the file declares OpenSCENARIO {ma}.{mi}; it is checked against the 1.{} schema", schema::NEWEST_MINOR))),
        ),
        _ => (schema::NEWEST_MINOR, None),
    }
}

/// The declared version's schema first, then the others, newest first.
fn all_schemas(first: u16) -> impl Iterator<Item = &'static Schema> {
    std::iter::once(first).chain((0..=schema::NEWEST_MINOR).rev().filter(move |m| *m != first)).filter_map(schema::for_minor)
}

/// A declared parameter or variable as the checks need it.
#[derive(Debug, Clone)]
struct Declared {
    name: String,
    primitive: Primitive,
    /// The resolved value; `None` when the declaration itself is wrong (already reported).
    value: Option<String>,
    line: u32,
}

struct Walker {
    file: Arc<Path>,
    findings: Vec<Finding>,
    scopes: Vec<Vec<Declared>>,
    variables: Vec<Declared>,
    declared: u16,
    /// Overrides of global parameters, applied (and then cleared) at the document element.
    injected: Vec<(String, String)>,
    /// The file is a catalog: its entries may use parameters of the scenarios that refer to
    /// them, so a parameter it does not declare is a warning, not an error.
    in_catalog: bool,
    /// The walk is at the document element (until it has been entered).
    at_root: bool,
}

impl Walker {
    fn push(&mut self, severity: Severity, pos: xml::Pos, message: impl Into<String>) {
        let location = Location { file: self.file.clone(), line: pos.line, col: pos.col };
        self.findings.push(Finding { severity, location, message: message.into() });
    }

    fn lookup(&self, name: &str) -> Option<&Declared> {
        self.scopes.iter().rev().flat_map(|s| s.iter().rev()).find(|d| d.name == name)
    }

    fn element(&mut self, el: &Elem, schema: &'static Schema, type_name: &str) {
        let Some(ty) = schema.complex_type(type_name) else { return };
        let scoped = match el.child("ParameterDeclarations") {
            Some(block) => {
                self.scopes.push(Vec::new());
                self.declare_parameters(block);
                true
            }
            None => false,
        };
        if !self.injected.is_empty() {
            let at = el.child("ParameterDeclarations").map_or(el.pos, |b| b.pos);
            self.inject(at);
        }
        // variables are declared after the global parameters, whose values they may use
        if std::mem::take(&mut self.at_root) {
            if let Some(vars) = el.child("VariableDeclarations") {
                self.declare_variables(vars);
            }
        }
        self.attributes(el, schema, type_name);
        self.cross_attribute_rules(el, type_name);
        self.unique_names(el);
        if matches!(el.name.as_str(), "VariableAction" | "VariableCondition") {
            self.variable_use(el);
        }

        // Content: against the declared version; an element another version accepts is a warning.
        let names: Vec<&str> = el.children_unmarked().iter().map(|c| c.name.as_str()).collect();
        let mut content_schema = schema;
        let problems = match_children(schema, ty, &names);
        if !problems.is_empty() {
            let other = all_schemas(schema.minor).skip(1).find(|s| s.complex_type(type_name).is_some_and(|t| match_children(s, t, &names).is_empty()));
            match other {
                Some(s) => {
                    let since = first_newer_with(schema.minor, |n| n.complex_type(type_name).is_some_and(|t| match_children(n, t, &names).is_empty()));
                    self.push(
                        Severity::Warning,
                        el.pos,
                        format!("the children of <{}> are OpenSCENARIO 1.{} (the file declares 1.{})", el.name, since.unwrap_or(s.minor), self.declared),
                    );
                    content_schema = s;
                }
                None => self.content_problems(el, &problems),
            }
        }
        let Some(content_ty) = content_schema.complex_type(type_name) else { return };
        let children = content_schema.child_elements(content_ty);
        for child in el.children_unmarked() {
            let Some(decl) = children.iter().find(|d| d.name == child.name) else { continue };
            if decl.deprecated {
                let since =
                    deprecated_since(|s| s.complex_type(type_name).is_some_and(|t| s.child_elements(t).iter().any(|d| d.name == child.name && d.deprecated)));
                self.push(Severity::Warning, child.pos, format!("element <{}> is deprecated since OpenSCENARIO 1.{since}", child.name));
            }
            let child_type = decl.type_name.clone();
            self.element(child, content_schema, &child_type);
        }
        if scoped {
            self.scopes.pop();
        }
    }

    fn content_problems(&mut self, el: &Elem, problems: &[ContentProblem]) {
        for p in problems {
            match p {
                ContentProblem::Unknown { child } => {
                    let c = &el.children_unmarked()[*child];
                    self.push(Severity::Error, c.pos, format!("unknown element <{}> in <{}>", c.name, el.name));
                }
                ContentProblem::NotAllowedHere { child } => {
                    let c = &el.children_unmarked()[*child];
                    self.push(
                        Severity::Error,
                        el.pos,
                        format!("<{}> at line {} is not allowed here: out of order, or more of it than <{}> may hold", c.name, c.pos.line, el.name),
                    );
                }
                ContentProblem::Missing { expected, .. } => {
                    let what = if expected.len() == 1 { format!("<{}>", expected[0]) } else { format!("one of <{}>", expected.join(">, <")) };
                    self.push(Severity::Error, el.pos, format!("<{}> is missing a child element: {what} is required", el.name));
                }
            }
        }
    }

    fn attributes(&mut self, el: &Elem, schema: &'static Schema, type_name: &str) {
        let Some(ty) = schema.complex_type(type_name) else { return };
        for attr in &el.attrs {
            if attr.name.contains(':') || attr.name.starts_with("xmlns") {
                continue;
            }
            let decl = match ty.attributes.iter().find(|a| a.name == attr.name) {
                Some(d) => (schema, d),
                None => {
                    let other = all_schemas(schema.minor)
                        .skip(1)
                        .find_map(|s| s.complex_type(type_name)?.attributes.iter().find(|a| a.name == attr.name).map(|d| (s, d)));
                    match other {
                        Some((s, d)) => {
                            let since =
                                first_newer_with(schema.minor, |n| n.complex_type(type_name).is_some_and(|t| t.attributes.iter().any(|a| a.name == attr.name)));
                            self.push(
                                Severity::Warning,
                                attr.pos,
                                format!(
                                    "attribute '{}' of <{}> is OpenSCENARIO 1.{} (the file declares 1.{})",
                                    attr.name,
                                    el.name,
                                    since.unwrap_or(s.minor),
                                    self.declared
                                ),
                            );
                            (s, d)
                        }
                        None => {
                            self.push(Severity::Error, attr.pos, format!("unknown attribute '{}' on <{}>", attr.name, el.name));
                            continue;
                        }
                    }
                }
            };
            let (decl_schema, decl) = decl;
            let Some(kind) = decl_schema.simple_kind(&decl.type_name) else { continue };
            if decl.deprecated || kind.deprecated {
                let since = deprecated_since(|s| {
                    s.complex_type(type_name).is_some_and(|t| {
                        t.attributes.iter().any(|a| a.name == attr.name && (a.deprecated || s.simple_kind(&a.type_name).is_some_and(|k| k.deprecated)))
                    })
                });
                self.push(Severity::Warning, attr.pos, format!("attribute '{}' of <{}> is deprecated since OpenSCENARIO 1.{since}", attr.name, el.name));
            }
            // Declarations are checked as declarations (their values may name the type).
            if attr.name == "value" && matches!(el.name.as_str(), "ParameterDeclaration" | "VariableDeclaration") {
                continue;
            }
            if let Some(value) = self.attribute_value(el, attr, &kind) {
                self.range_check(el, attr, type_name, &value);
            }
        }
        for decl in ty.attributes.iter().filter(|a| a.required) {
            if el.attr(&decl.name).is_none() {
                self.push(Severity::Error, el.pos, format!("<{}> needs the attribute '{}'", el.name, decl.name));
            }
        }
    }

    /// Checks one attribute value and returns its final text (parameters and expressions
    /// resolved) when it is valid.
    fn attribute_value(&mut self, el: &Elem, attr: &Attr, kind: &SimpleKind) -> Option<String> {
        let what = || format!("attribute '{}' of <{}>", attr.name, el.name);
        // `parameterRef` names a parameter of the referenced catalog entry; esmini files write it
        // with the `$` of a reference, and it is not resolved here.
        if el.name == "ParameterAssignment" && attr.name == "parameterRef" {
            return Some(attr.value.clone());
        }
        let mut check = check_literal(kind, &attr.value);
        if check == LiteralCheck::Parameter && attr.value.starts_with("${") {
            // A string-valued expression (esmini concatenates text with `+`): evaluate it.
            check = LiteralCheck::Expression;
        }
        match check {
            LiteralCheck::Valid => Some(attr.value.clone()),
            LiteralCheck::DeprecatedLiteral => {
                let since = deprecated_literal_since(&attr.value);
                self.push(Severity::Warning, attr.pos, format!("{}: the value '{}' is deprecated since OpenSCENARIO 1.{since}", what(), attr.value));
                Some(attr.value.clone())
            }
            LiteralCheck::Invalid(why) if el.name == "FileHeader" && attr.name == "date" => {
                // Nothing reads the header date; a malformed one is worth saying, not failing.
                self.push(Severity::Warning, attr.pos, format!("{}: {why}", what()));
                None
            }
            LiteralCheck::Invalid(why) => {
                self.push(Severity::Error, attr.pos, format!("{}: {why}", what()));
                None
            }
            LiteralCheck::Parameter => {
                let name = attr.value.trim().trim_start_matches('$');
                let Some(d) = self.lookup(name).cloned() else {
                    self.undeclared(attr.pos, &format!("{}: parameter '${name}'", what()));
                    return None;
                };
                let Some(value) = d.value else {
                    self.push(
                        Severity::Error,
                        attr.pos,
                        format!("{}: parameter '${name}' cannot be used, its declaration at line {} is wrong", what(), d.line),
                    );
                    return None;
                };
                match self.fits(kind, &value) {
                    Ok(()) => {
                        if kind.literals.is_none() && d.primitive != kind.primitive && kind.primitive != Primitive::String {
                            self.push(
                                Severity::Info,
                                attr.pos,
                                format!(
                                    "{}: parameter '${name}' is declared {} and used as {}; its value '{value}' converts",
                                    what(),
                                    values::parameter_type_name(d.primitive),
                                    kind.primitive.xsd_name()
                                ),
                            );
                        }
                        Some(value)
                    }
                    Err(why) => {
                        // in a catalog the value is a default the referring scenario may replace
                        self.push(
                            if self.in_catalog { Severity::Warning } else { Severity::Error },
                            attr.pos,
                            format!("{}: parameter '${name}' (declared {}): {why}", what(), values::parameter_type_name(d.primitive)),
                        );
                        None
                    }
                }
            }
            LiteralCheck::Expression => {
                let value = match self.evaluate(&attr.value) {
                    Ok(v) => v,
                    Err(e) => {
                        let col = attr.pos.col + u32::try_from(e.column).unwrap_or(0);
                        let at = xml::Pos { line: attr.pos.line, col };
                        if e.kind == ErrorKind::UndeclaredParameter && self.in_catalog {
                            self.undeclared(at, &format!("{}: {}", what(), e.message.trim_end_matches(" is not declared")));
                        } else {
                            self.push(Severity::Error, at, format!("{}: {}", what(), e.message));
                        }
                        return None;
                    }
                };
                if matches!(value.as_str(), "inf" | "-inf" | "NaN") {
                    self.push(
                        Severity::Error,
                        attr.pos,
                        format!(
                            "{}: '{}' does not evaluate to a finite number (division by zero, overflow, or a function outside its domain)",
                            what(),
                            shorten(&attr.value)
                        ),
                    );
                    return None;
                }
                self.expression_extensions(&el.name, attr);
                match self.fits(kind, &value) {
                    Ok(()) => Some(value),
                    Err(why) => {
                        self.push(Severity::Error, attr.pos, format!("{}: expression '{}' = {why}", what(), shorten(&attr.value)));
                        None
                    }
                }
            }
        }
    }

    /// A parameter that no scope declares: an error, except in a catalog read alone, whose
    /// entries may take parameters from the scenario that uses them (esmini resolves them so).
    fn undeclared(&mut self, pos: xml::Pos, what: &str) {
        if self.in_catalog {
            self.push(
                Severity::Warning,
                pos,
                format!(
                    "{what} is not declared in this catalog: it resolves only in a scenario that declares it (the standard asks a catalog to declare \
                     each parameter it uses, with a default value)"
                ),
            );
        } else {
            self.push(Severity::Error, pos, format!("{what} is not declared"));
        }
    }

    fn fits(&self, kind: &SimpleKind, value: &str) -> Result<(), String> {
        match &kind.literals {
            Some(lits) if !lits.iter().any(|l| l.value == value) => Err(format!("'{value}' is not one of the allowed values")),
            Some(_) => Ok(()),
            None => check_primitive(kind.primitive, value),
        }
    }

    fn evaluate(&self, raw: &str) -> Result<String, ResolveError> {
        params::resolve_raw(raw, &mut |name| match self.lookup(name) {
            None => Ok(None),
            Some(Declared { value: Some(v), primitive, .. }) => {
                if matches!(primitive, Primitive::DateTime) {
                    Err(ResolveError {
                        kind: ErrorKind::Expression,
                        column: 0,
                        message: format!("parameter ${name} is a dateTime; expressions take numbers and booleans only"),
                    })
                } else {
                    Ok(Some(v.clone()))
                }
            }
            Some(Declared { value: None, line, .. }) => Err(ResolveError {
                kind: ErrorKind::UndeclaredParameter,
                column: 0,
                message: format!("parameter ${name} cannot be used, its declaration at line {line} is wrong"),
            }),
        })
    }

    fn range_check(&mut self, el: &Elem, attr: &Attr, type_name: &str, value: &str) {
        let Ok(v) = value.trim().parse::<f64>() else { return };
        for rule in range_rules().iter().filter(|r| r.type_name == type_name && r.attribute == attr.name) {
            if !rule.holds(v) {
                let lenient = rules::LENIENT_RANGES.contains(&(type_name, attr.name.as_str()));
                self.push(
                    if lenient { Severity::Warning } else { Severity::Error },
                    attr.pos,
                    format!("attribute '{}' of <{}> is {value}; the standard requires {} {} {}", attr.name, el.name, attr.name, rule.op, rule.bound_text),
                );
            }
        }
    }

    fn cross_attribute_rules(&mut self, el: &Elem, type_name: &str) {
        for (ty, deprecated, replacement) in DEPRECATED_WITH_REPLACEMENT {
            if *ty != type_name {
                continue;
            }
            let Some(attr) = el.attr(deprecated) else { continue };
            let clash = match replacement {
                Replacement::Attribute(a) => el.attr(a).map(|_| format!("attribute '{a}'")),
                Replacement::Elements(names) => names.iter().find(|n| el.child(n).is_some()).map(|n| format!("element <{n}>")),
            };
            if let Some(clash) = clash {
                self.push(
                    Severity::Error,
                    attr.pos,
                    format!("<{}> has both the deprecated attribute '{deprecated}' and {clash}, which replaces it: keep only the latter", el.name),
                );
            }
        }
    }
}

/// The first schema version that marks something deprecated.
/// The first version after `minor` whose schema satisfies `has` (where a newer construct came
/// from: the fallback itself reads the newest schema that has it).
fn first_newer_with(minor: u16, has: impl Fn(&Schema) -> bool) -> Option<u16> {
    (minor + 1..=schema::NEWEST_MINOR).filter_map(schema::for_minor).find(|s| has(s)).map(|s| s.minor)
}

fn deprecated_since(is_deprecated: impl Fn(&Schema) -> bool) -> u16 {
    (0..=schema::NEWEST_MINOR).filter_map(schema::for_minor).find(|s| is_deprecated(s)).map_or(schema::NEWEST_MINOR, |s| s.minor)
}

fn deprecated_literal_since(value: &str) -> u16 {
    deprecated_since(|s| s.simple.values().any(|k| k.literals.as_ref().is_some_and(|l| l.iter().any(|l| l.value == value && l.deprecated))))
}

fn shorten(raw: &str) -> String {
    if raw.chars().count() <= 120 {
        return raw.to_string();
    }
    let head: String = raw.chars().take(120).collect();
    format!("{head}…")
}
