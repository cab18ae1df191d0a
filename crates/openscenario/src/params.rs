//! Parameters: declarations, scopes, and resolution of `$name` / `${expr}` attribute values.
//!
//! esmini resolves every attribute that references a parameter while it reads the file; so do
//! we. Declarations keep their final values in the model because actions and conditions
//! (ParameterSetAction, ParameterCondition, ...) work on them at run time.

use crate::error::{Diagnostic, Error, ErrorKind, Location};
use crate::expr::{self, ExprValue};
use crate::xml::{Elem, Pos};
use serde::Serialize;
use std::path::Path;
use std::sync::Arc;

crate::xml_enum! {
    /// ParameterType of the schema (`int` is accepted for `integer`, as esmini does).
    ParameterType {
        Integer = "integer" | "int",
        UnsignedInt = "unsignedInt",
        UnsignedShort = "unsignedShort",
        Double = "double",
        Boolean = "boolean",
        String = "string",
        DateTime = "dateTime",
    }
}

/// A declared parameter (or variable) with its final value as text.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterDeclaration {
    pub name: String,
    pub parameter_type: ParameterType,
    pub value: String,
    pub origin: Location,
}

impl ParameterDeclaration {
    /// The value as a number (booleans are 1 / 0), if it is one.
    pub fn as_f64(&self) -> Option<f64> {
        value_as_expr(&self.value).map(ExprValue::as_num)
    }
}

/// Numeric/boolean reading of a parameter's text for expressions.
pub(crate) fn value_as_expr(text: &str) -> Option<ExprValue> {
    let t = text.trim();
    match t {
        "true" | "True" | "TRUE" => Some(ExprValue::Bool(true)),
        "false" | "False" | "FALSE" => Some(ExprValue::Bool(false)),
        _ => t.parse::<f64>().ok().filter(|v| !v.is_nan()).map(ExprValue::Num),
    }
}

/// Parameters visible at one level; lookups fall back to the enclosing scope.
#[derive(Debug, Default)]
pub(crate) struct Scope<'p> {
    pub params: Vec<ParameterDeclaration>,
    pub parent: Option<&'p Scope<'p>>,
}

impl<'p> Scope<'p> {
    pub(crate) fn child(&'p self, params: Vec<ParameterDeclaration>) -> Scope<'p> {
        Scope { params, parent: Some(self) }
    }
    pub(crate) fn get(&self, name: &str) -> Option<&ParameterDeclaration> {
        match self.params.iter().rev().find(|p| p.name == name) {
            Some(p) => Some(p),
            None => self.parent.and_then(|s| s.get(name)),
        }
    }
}

/// Why an attribute value could not be resolved; `column` is 0-based inside the raw value.
pub(crate) struct ResolveError {
    pub kind: ErrorKind,
    pub column: usize,
    pub message: String,
}

/// Resolves a raw attribute value. `lookup` answers parameter names.
pub(crate) fn resolve_raw(raw: &str, lookup: &mut dyn FnMut(&str) -> Result<Option<String>, ResolveError>) -> Result<String, ResolveError> {
    let Some(rest) = raw.strip_prefix('$') else { return Ok(raw.to_string()) };
    if let Some(inner) = rest.strip_prefix('{') {
        let Some(body) = inner.strip_suffix('}') else {
            return Err(ResolveError {
                kind: ErrorKind::Expression,
                column: raw.chars().count(),
                message: format!("expression '{raw}' is not closed with '}}'"),
            });
        };
        let mut failure: Option<ResolveError> = None;
        let mut lk = |name: &str| -> Result<ExprValue, String> {
            match lookup(name) {
                Ok(Some(text)) => value_as_expr(&text).ok_or_else(|| format!("parameter ${name} has value '{text}', which is not a number or boolean")),
                Ok(None) => Err(format!("parameter ${name} is not declared")),
                Err(e) => {
                    let msg = e.message.clone();
                    failure = Some(e);
                    Err(msg)
                }
            }
        };
        let result = expr::evaluate(body, &mut lk);
        if let Some(f) = failure {
            return Err(f);
        }
        return match result {
            Ok(v) => Ok(v.to_text()),
            Err(e) if e.message.starts_with("expected a number, a $parameter") || e.message.contains("which is not a number") => {
                let mut text_lookup = |name: &str| lookup(name).ok().flatten();
                match expr::concatenate(body, &mut text_lookup) {
                    Some(s) => Ok(s),
                    None => Err(ResolveError {
                        kind: ErrorKind::Expression,
                        column: e.column + 1,
                        message: format!("in expression '{}' at column {}: {}", shorten(raw), e.column + 2, e.message),
                    }),
                }
            }
            Err(e) => {
                let kind = if e.message.contains("is not declared") { ErrorKind::UndeclaredParameter } else { ErrorKind::Expression };
                Err(ResolveError { kind, column: e.column + 1, message: format!("in expression '{}' at column {}: {}", shorten(raw), e.column + 2, e.message) })
            }
        };
    }
    let name = rest.trim();
    match lookup(name)? {
        Some(v) => Ok(v),
        None => Err(ResolveError { kind: ErrorKind::UndeclaredParameter, column: 0, message: format!("parameter ${name} is not declared") }),
    }
}

pub(crate) fn location(file: &Arc<Path>, pos: Pos) -> Location {
    Location { file: file.clone(), line: pos.line, col: pos.col }
}

/// Resolves a raw value against a scope.
pub(crate) fn resolve_in_scope(raw: &str, scope: &Scope) -> Result<String, ResolveError> {
    resolve_raw(raw, &mut |name| Ok(scope.get(name).map(|p| p.value.clone())))
}

/// Turns a ResolveError at an attribute value into a positioned Error.
pub(crate) fn positioned(file: &Arc<Path>, pos: Pos, e: ResolveError) -> Error {
    let col = pos.col + u32::try_from(e.column).unwrap_or(0);
    Error::new(e.kind, Location { file: file.clone(), line: pos.line, col }, e.message)
}

/// One raw declaration before resolution.
struct RawDecl<'e> {
    name: String,
    ty: ParameterType,
    value: String,
    /// Position of the value (for errors) and of the element (for the origin).
    value_pos: Pos,
    pos: Pos,
    elem: &'e Elem,
}

/// Reads a `ParameterDeclarations` (or `VariableDeclarations`) element and resolves every value.
/// `assignments` (already resolved, by name) replace declared values — catalog
/// ParameterAssignments or command-line overrides. Values may refer to each other in any order
/// inside the block (cycles are errors) and to the enclosing scope.
pub(crate) fn read_declarations(
    el: Option<&Elem>,
    parent: &Scope,
    assignments: &[(String, String)],
    file: &Arc<Path>,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Vec<ParameterDeclaration>, Error> {
    let mut raws: Vec<RawDecl> = Vec::new();
    if let Some(el) = el {
        for d in el.children() {
            let (name_attr, type_attr) = match d.name.as_str() {
                "ParameterDeclaration" => ("name", "parameterType"),
                "VariableDeclaration" => ("name", "variableType"),
                _ => continue,
            };
            let loc = location(file, d.pos);
            let name = d
                .attr(name_attr)
                .map(|a| a.value.trim().trim_start_matches('$').to_string())
                .ok_or_else(|| Error::new(ErrorKind::Structure, loc.clone(), format!("{} needs a '{name_attr}' attribute", d.name)))?;
            let ty_attr = d
                .attr(type_attr)
                .ok_or_else(|| Error::new(ErrorKind::Structure, loc.clone(), format!("{} '{name}' needs a '{type_attr}' attribute", d.name)))?;
            let ty = crate::attr::parse_enum::<ParameterType>(&ty_attr.value)
                .ok_or_else(|| positioned_value_error::<ParameterType>(file, ty_attr.pos, &ty_attr.value, type_attr))?;
            let val = d.attr("value").ok_or_else(|| Error::new(ErrorKind::Structure, loc.clone(), format!("{} '{name}' needs a 'value' attribute", d.name)))?;
            if let Some(prev) = raws.iter().position(|r| r.name == name) {
                warnings.push(Diagnostic {
                    location: loc.clone(),
                    message: format!("parameter '{name}' is declared twice (first at line {}); the later declaration wins", raws[prev].pos.line),
                });
                raws.remove(prev);
            }
            raws.push(RawDecl { name, ty, value: val.value.clone(), value_pos: val.pos, pos: d.pos, elem: d });
        }
    }
    for (name, value) in assignments {
        if let Some(r) = raws.iter_mut().find(|r| &r.name == name) {
            // An assigned value is final text already: make sure it is not re-resolved.
            r.value = value.clone();
            r.value_pos = Pos::default();
        }
    }
    let assigned: Vec<bool> = raws.iter().map(|r| assignments.iter().any(|(n, _)| n == &r.name)).collect();
    let mut state: Vec<Option<String>> = vec![None; raws.len()];
    let mut resolver = BlockResolver { raws: &raws, assigned: &assigned, state: &mut state, stack: Vec::new(), parent, file };
    for i in 0..raws.len() {
        resolver.resolve(i)?;
    }
    let values: Vec<String> = state.into_iter().map(Option::unwrap_or_default).collect();
    // a constraint's bound may be a parameter or an expression over the block and the scopes
    // around it, evaluated as any attribute is
    let mut bound_lookup = |name: &str| -> Result<Option<String>, ResolveError> {
        Ok(match raws.iter().rposition(|r| r.name == name) {
            Some(j) => values.get(j).cloned(),
            None => parent.get(name).map(|p| p.value.clone()),
        })
    };
    let mut out = Vec::with_capacity(raws.len());
    for (r, value) in raws.iter().zip(values.iter().cloned()) {
        if let Some(msg) = violated_constraints(r.elem, &value, &mut bound_lookup) {
            warnings
                .push(Diagnostic { location: location(file, r.pos), message: format!("parameter '{}' = '{value}' violates its constraints ({msg})", r.name) });
        }
        // esmini does not check declared types; a mismatch is worth a warning, not a failure.
        if let Err(msg) = check_type(r.ty, &value) {
            warnings.push(Diagnostic {
                location: location(file, if r.value_pos.line > 0 { r.value_pos } else { r.pos }),
                message: format!("parameter '{}' is declared {}: {msg}", r.name, r.ty),
            });
        }
        out.push(ParameterDeclaration { name: r.name.clone(), parameter_type: r.ty, value, origin: location(file, r.pos) });
    }
    Ok(out)
}

pub(crate) fn positioned_value_error<T: crate::attr::XmlEnum>(file: &Arc<Path>, pos: Pos, value: &str, attr: &str) -> Error {
    Error::new(ErrorKind::Value, location(file, pos), format!("attribute '{attr}': expected one of {}, found '{value}'", T::NAMES.join(", ")))
}

struct BlockResolver<'a, 'e> {
    raws: &'a [RawDecl<'e>],
    assigned: &'a [bool],
    state: &'a mut Vec<Option<String>>,
    stack: Vec<usize>,
    parent: &'a Scope<'a>,
    file: &'a Arc<Path>,
}

impl BlockResolver<'_, '_> {
    fn resolve(&mut self, i: usize) -> Result<String, Error> {
        if let Some(Some(v)) = self.state.get(i) {
            return Ok(v.clone());
        }
        let raws = self.raws;
        let Some(raw) = raws.get(i) else { return Ok(String::new()) };
        if self.assigned.get(i).copied().unwrap_or(false) {
            self.state[i] = Some(raw.value.clone());
            return Ok(raw.value.clone());
        }
        if let Some(at) = self.stack.iter().position(|&j| j == i) {
            let mut names: Vec<&str> = self.stack[at..].iter().filter_map(|&j| self.raws.get(j)).map(|r| r.name.as_str()).collect();
            names.push(&raw.name);
            return Err(Error::new(ErrorKind::ParameterCycle, location(self.file, raw.value_pos), format!("parameter cycle: {}", names.join(" -> "))));
        }
        if self.stack.len() > 200 {
            return Err(Error::new(ErrorKind::Limit, location(self.file, raw.pos), "parameter references nested too deeply"));
        }
        self.stack.push(i);
        let mut inner_err: Option<Error> = None;
        let value = {
            let mut lookup = |name: &str| -> Result<Option<String>, ResolveError> {
                // A declaration may refer to itself only through the enclosing scope.
                if let Some(j) = raws.iter().position(|r| r.name == name) {
                    match self.resolve(j) {
                        Ok(v) => return Ok(Some(v)),
                        Err(e) => {
                            let msg = e.message.clone();
                            let kind = e.kind;
                            inner_err = Some(e);
                            return Err(ResolveError { kind, column: 0, message: msg });
                        }
                    }
                }
                Ok(self.parent.get(name).map(|p| p.value.clone()))
            };
            resolve_raw(&raw.value, &mut lookup)
        };
        self.stack.pop();
        if let Some(e) = inner_err {
            return Err(e);
        }
        let value = value.map_err(|e| positioned(self.file, raw.value_pos, e))?;
        self.state[i] = Some(value.clone());
        Ok(value)
    }
}

/// Checks a final value against its declared type (leniently, as esmini: an integer written
/// `3.0` is an integer).
fn check_type(ty: ParameterType, value: &str) -> Result<(), String> {
    let v = value.trim();
    let integral = || v.parse::<i64>().is_ok() || v.parse::<f64>().is_ok_and(|f| f.fract() == 0.0);
    match ty {
        ParameterType::Integer if !integral() => Err(format!("expected an integer, found '{value}'")),
        ParameterType::UnsignedInt | ParameterType::UnsignedShort if !integral() || v.parse::<f64>().is_ok_and(|f| f < 0.0) => {
            Err(format!("expected an unsigned integer, found '{value}'"))
        }
        ParameterType::Double if v.parse::<f64>().map_or(true, f64::is_nan) => Err(format!("expected a number, found '{value}'")),
        ParameterType::Boolean if !matches!(v.to_ascii_lowercase().as_str(), "true" | "false" | "1" | "0") => {
            Err(format!("expected true or false, found '{value}'"))
        }
        _ => Ok(()),
    }
}

/// Checks the ConstraintGroups (1.1+) of a declaration: satisfied when every ValueConstraint of
/// at least one group holds. Returns a description of the failed groups, or None.
fn violated_constraints(decl: &Elem, value: &str, lookup: &mut dyn FnMut(&str) -> Result<Option<String>, ResolveError>) -> Option<String> {
    let groups: Vec<&Elem> = decl.children_named("ConstraintGroup").collect();
    if groups.is_empty() {
        return None;
    }
    let mut failed = Vec::new();
    for g in &groups {
        let mut all = true;
        for c in g.children_named("ValueConstraint") {
            let rule = c.attr("rule").map(|a| a.value.as_str()).unwrap_or("");
            let raw = c.attr("value").map(|a| a.value.as_str()).unwrap_or("");
            // a bound that cannot be evaluated is the schema pass's to report; it holds here
            let Ok(bound) = resolve_raw(raw, lookup) else { continue };
            let bound = bound.as_str();
            let holds = match (value.trim().parse::<f64>(), bound.trim().parse::<f64>()) {
                (Ok(a), Ok(b)) => crate::attr::parse_enum::<crate::model::Rule>(rule).is_none_or(|r| r.compare(a, b)),
                _ => match rule {
                    "equalTo" => value == bound,
                    "notEqualTo" => value != bound,
                    _ => true,
                },
            };
            if !holds {
                all = false;
                failed.push(format!("{rule} {bound}"));
            }
        }
        if all {
            return None;
        }
    }
    Some(failed.join(", "))
}

/// An expression quoted in a message: at most 120 characters (a hostile file may hold a
/// megabyte in one attribute; the column says where the problem is).
fn shorten(raw: &str) -> String {
    const MAX: usize = 120;
    if raw.chars().count() <= MAX {
        return raw.to_string();
    }
    let head: String = raw.chars().take(MAX).collect();
    format!("{head}… ({} characters)", raw.chars().count())
}
