//! What an expression uses beyond the OpenSCENARIO 1.2 expression grammar, whose operators are
//! unary and binary `-`, `+`, `*`, `/`, `%`, `round`, `floor`, `ceil`, `sqrt`, `pow`, `not`,
//! `and` and `or`. esmini evaluates more — comparisons, trigonometric and other functions, the
//! constant `pi` — and so does osc2cr, with a warning: other tools may not.

use super::lexer::{tokenize, Tok};

/// Functions of the standard's grammar, and its word operators (`not (…)` looks like a call).
const STANDARD_FUNCTIONS: &[&str] = &["round", "floor", "ceil", "sqrt", "pow", "not", "and", "or"];

/// The parts of expression `src` outside the standard's grammar, each with its 1-based column in
/// `src` and what it is (`"comparison '<='"`, `"function 'sin'"`, `"constant 'pi'"`). An
/// expression that does not tokenize yields nothing here (its error is reported elsewhere).
pub fn beyond_the_standard(src: &str) -> Vec<(usize, String)> {
    let Ok(tokens) = tokenize(src) else { return Vec::new() };
    let mut out = Vec::new();
    for (i, (tok, col)) in tokens.iter().enumerate() {
        let next_is_call = matches!(tokens.get(i + 1), Some((Tok::LParen, _)));
        match tok {
            Tok::Eq | Tok::Ne | Tok::Lt | Tok::Le | Tok::Gt | Tok::Ge => out.push((*col, format!("comparison {}", tok.describe()))),
            Tok::Ident(name) if next_is_call && !STANDARD_FUNCTIONS.contains(&name.as_str()) => out.push((*col, format!("function '{name}'"))),
            Tok::Ident(name) if name == "pi" && !next_is_call => out.push((*col, "constant 'pi'".to_string())),
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::beyond_the_standard;

    #[test]
    fn the_standard_grammar_passes_and_esmini_s_extensions_are_named() {
        assert!(beyond_the_standard("-$a + round($b / 3.6) * pow(2, 3) % 4 - sqrt(floor(ceil(1)))").is_empty());
        assert!(beyond_the_standard("not ($a and $b) or true").is_empty());
        let found = beyond_the_standard("sin($a) + pi >= 2");
        let what: Vec<&str> = found.iter().map(|(_, w)| w.as_str()).collect();
        assert_eq!(what, ["function 'sin'", "constant 'pi'", "comparison '>='"]);
        assert_eq!(found[0].0, 1);
    }
}
