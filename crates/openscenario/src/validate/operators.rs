//! Expressions that use more than the standard's grammar. The standard's `${…}` expressions
//! compute numbers and booleans with `-`, `+`, `*`, `/`, `%`, `round`, `floor`, `ceil`, `sqrt`,
//! `pow`, `not`, `and` and `or`; esmini (and osc2cr) also evaluate comparisons, more functions,
//! `pi`, and join text with `+` (`${$name + _suffix}`). Such an expression runs as esmini runs
//! it and is a warning: another tool may refuse it.

use super::{Severity, Walker};
use crate::expr;
use crate::params::value_as_expr;
use crate::xml::{self, Attr};

impl Walker {
    /// Warnings for what the expression `attr` (a `${…}` value) uses beyond the standard.
    pub(super) fn expression_extensions(&mut self, element: &str, attr: &Attr) {
        let Some(body) = attr.value.strip_prefix("${").and_then(|b| b.strip_suffix('}')) else { return };
        let what = format!("attribute '{}' of <{element}>", attr.name);
        for (col, part) in expr::beyond_the_standard(body) {
            // the body starts two characters into the value
            let at = xml::Pos { line: attr.pos.line, col: attr.pos.col + u32::try_from(col + 1).unwrap_or(0) };
            self.push(Severity::Warning, at, format!("{what}: {part} is not in the standard's expression grammar (esmini evaluates it, other tools may not)"));
        }
        let numeric = expr::evaluate(body, &mut |name| match self.lookup(name).and_then(|d| d.value.as_deref()) {
            Some(v) => value_as_expr(v).ok_or_else(|| "text".to_string()),
            None => Err("undeclared".to_string()),
        });
        if numeric.is_err() {
            self.push(
                Severity::Warning,
                attr.pos,
                format!("{what}: '{}' joins text with '+', esmini's extension (the standard's expressions compute numbers and booleans)", attr.value),
            );
        }
    }
}
