//! Parameter and variable declarations as the schema pass checks them: their values against
//! their declared types, their ConstraintGroups, `--param` overrides, and the uses of variables.
//!
//! A value may be a `$parameter` or an expression over the parameters declared before it, in
//! this block or an enclosing one (VariableDeclarations see the global parameters); a
//! constraint's bound likewise, evaluated by the reader's evaluator. A value that does not fit
//! its declared type is an error (as the ASAM OpenSCENARIO API has it), and the parameter then
//! cannot be used.

use super::{values, Declared, Severity, Walker};
use crate::xml::{self, Elem};
use schema::Primitive;

impl Walker {
    /// Applies `--param` overrides to the global scope: a value must be of the declared type, and
    /// only a declared global parameter can be overridden.
    pub(super) fn inject(&mut self, block_pos: xml::Pos) {
        for (name, value) in std::mem::take(&mut self.injected) {
            let global = if self.scopes.len() == 1 { self.scopes.first_mut() } else { None };
            let Some(d) = global.and_then(|s| s.iter_mut().rev().find(|d| d.name == name)) else {
                self.push(
                    Severity::Warning,
                    block_pos,
                    format!("--param {name}={value}: there is no global parameter '{name}' to override; the value is ignored"),
                );
                continue;
            };
            match values::fits_declared_type(d.primitive, &value) {
                Ok(()) => d.value = Some(value),
                Err(why) => {
                    let (line, ty) = (d.line, values::parameter_type_name(d.primitive));
                    self.push(
                        Severity::Error,
                        xml::Pos { line, col: 1 },
                        format!("--param {name}={value}: parameter '{name}' is declared {ty} here, and {why}; the declared value is kept"),
                    );
                }
            }
        }
    }

    /// Reads a ParameterDeclarations block into the innermost scope, checking each declaration;
    /// the constraints are checked once the whole block is declared (a bound may name a
    /// parameter declared after the one it constrains).
    pub(super) fn declare_parameters(&mut self, block: &Elem) {
        let decls: Vec<&Elem> = block.children_named("ParameterDeclaration").collect();
        for d in &decls {
            if let Some(declared) = self.declaration(d, "parameterType", "parameter") {
                if let Some(scope) = self.scopes.last_mut() {
                    scope.push(declared);
                }
            }
        }
        for d in decls {
            self.constraints_of(d);
        }
    }

    /// VariableDeclarations, in the global parameters' scope (their values may use them).
    pub(super) fn declare_variables(&mut self, block: &Elem) {
        self.scopes.push(Vec::new());
        for d in block.children_named("VariableDeclaration") {
            if let Some(v) = self.declaration(d, "variableType", "variable") {
                if let Some(scope) = self.scopes.last_mut() {
                    scope.push(v.clone());
                }
                self.variables.push(v);
            }
        }
        self.scopes.pop();
    }

    fn declaration(&mut self, d: &Elem, type_attr: &str, noun: &str) -> Option<Declared> {
        let name = d.attr("name")?.value.trim().trim_start_matches('$').to_string();
        let primitive = values::primitive_of_parameter_type(d.attr(type_attr)?.value.trim())?;
        let raw = d.attr("value")?;
        let value = if raw.value.starts_with('$') {
            match self.evaluate(&raw.value) {
                Ok(v) => Some(v),
                Err(e) => {
                    self.push(Severity::Error, raw.pos, format!("{noun} '{name}': {}", e.message));
                    None
                }
            }
        } else {
            Some(raw.value.clone())
        };
        if self.in_catalog && raw.value.is_empty() {
            self.push(
                Severity::Warning,
                raw.pos,
                format!("{noun} '{name}' has no default value: the standard asks a catalog to give each of its parameters one"),
            );
        }
        let mut value = value;
        if let Some(v) = &value {
            if let Err(why) = values::fits_declared_type(primitive, v) {
                let message = format!("{noun} '{name}' is declared {}, but its value {why}", values::parameter_type_name(primitive));
                if self.in_catalog {
                    // only a default: each scenario that uses the entry may assign a value that fits
                    // (esmini's own followGhost controller declares a double `time`, passed on as text)
                    self.push(Severity::Warning, raw.pos, format!("{message} (a default; a scenario that uses the entry may assign one that fits)"));
                } else {
                    self.push(Severity::Error, raw.pos, message);
                    value = None;
                }
            }
        }
        Some(Declared { name, primitive, value, line: d.pos.line })
    }

    /// The declaration `d`'s ConstraintGroups: the value must satisfy every ValueConstraint of
    /// at least one group.
    fn constraints_of(&mut self, d: &Elem) {
        let groups: Vec<&Elem> = d.children_named("ConstraintGroup").collect();
        let Some(name) = d.attr("name").map(|a| a.value.trim().trim_start_matches('$').to_string()) else { return };
        if groups.is_empty() {
            return;
        }
        let Some(declared) = self.scopes.last().and_then(|s| s.iter().rev().find(|x| x.name == name)).cloned() else { return };
        let Some(value) = &declared.value else { return };
        let primitive = declared.primitive;
        let Some(v) = values::ordered(primitive, value) else { return };
        let mut any_group_holds = false;
        for g in &groups {
            let mut all = true;
            for c in g.children_named("ValueConstraint") {
                let (Some(rule), Some(bound)) = (c.attr("rule"), c.attr("value")) else { continue };
                let text = if bound.value.starts_with('$') {
                    match self.evaluate(&bound.value) {
                        Ok(t) => t,
                        Err(e) => {
                            let col = bound.pos.col + u32::try_from(e.column).unwrap_or(0);
                            self.push(Severity::Error, xml::Pos { line: bound.pos.line, col }, format!("parameter '{name}', constraint value: {}", e.message));
                            all = false;
                            continue;
                        }
                    }
                } else {
                    bound.value.clone()
                };
                let Some(b) = values::ordered(primitive, &text) else {
                    let shown = if text == bound.value { format!("'{text}'") } else { format!("'{}' = '{text}'", bound.value) };
                    self.push(
                        Severity::Error,
                        bound.pos,
                        format!("parameter '{name}': the constraint value {shown} is not a {}", values::parameter_type_name(primitive)),
                    );
                    all = false;
                    continue;
                };
                if values::holds(&rule.value, &v, &b) != Some(true) {
                    all = false;
                }
            }
            any_group_holds |= all;
        }
        if !any_group_holds {
            self.push(Severity::Error, d.pos, format!("parameter '{name}' = '{value}' satisfies none of its constraint groups"));
        }
    }

    pub(super) fn variable_use(&mut self, el: &Elem) {
        let Some(r) = el.attr("variableRef") else { return };
        let name = r.value.trim();
        if name.starts_with('$') {
            return;
        }
        let Some(var) = self.variables.iter().find(|v| v.name == name).cloned() else {
            self.push(Severity::Error, r.pos, format!("<{}>: variable '{name}' is not declared", el.name));
            return;
        };
        if el.name == "VariableCondition" {
            if let Some(v) = el.attr("value") {
                if let Err(why) = values::fits_declared_type(var.primitive, &v.value) {
                    self.push(Severity::Error, v.pos, format!("variable '{name}' is {}: {why}", values::parameter_type_name(var.primitive)));
                }
            }
            return;
        }
        if let Some(set) = el.child("SetAction") {
            if let Some(v) = set.attr("value") {
                if !v.value.starts_with('$') {
                    if let Err(why) = values::fits_declared_type(var.primitive, &v.value) {
                        self.push(Severity::Error, v.pos, format!("variable '{name}' is {}: {why}", values::parameter_type_name(var.primitive)));
                    }
                }
            }
        }
        let modify = el.child("ModifyAction");
        if let Some(modify) = modify.filter(|_| matches!(var.primitive, Primitive::Boolean | Primitive::String | Primitive::DateTime)) {
            self.push(
                Severity::Error,
                modify.pos,
                format!("variable '{name}' is {}; a ModifyAction (add or multiply) needs a numeric variable", values::parameter_type_name(var.primitive)),
            );
        }
    }
}
