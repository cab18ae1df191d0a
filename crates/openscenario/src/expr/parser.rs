//! Recursive-descent evaluation of a token stream.
//!
//! Grammar (lowest precedence first):
//! ```text
//! or   := and ('or' and)*
//! and  := not ('and' not)*
//! not  := 'not' not | cmp
//! cmp  := add (('=='|'!='|'<'|'<='|'>'|'>=') add)?
//! add  := mul (('+'|'-') mul)*
//! mul  := unary (('*'|'/'|'%') unary)*
//! unary:= '-' unary | primary
//! primary := number | true | false | $name | name '(' args ')' | '(' or ')'
//! ```

use super::error::ExprError;
use super::functions;
use super::lexer::{tokenize, Spanned, Tok};
use super::value::ExprValue;

/// Deepest nesting of parentheses / unary operators accepted.
const MAX_DEPTH: usize = 100;

/// Evaluates `src` (the text between `${` and `}`). `lookup` gives a parameter's value or a
/// message saying why it has none.
pub fn evaluate(src: &str, lookup: &mut dyn FnMut(&str) -> Result<ExprValue, String>) -> Result<ExprValue, ExprError> {
    let tokens = tokenize(src)?;
    let mut p = Parser { tokens, at: 0, lookup, depth: 0 };
    let v = p.or()?;
    match p.peek() {
        Tok::End => Ok(v),
        t => Err(p.err(format!("expected an operator or the end of the expression, found {}", t.describe()))),
    }
}

struct Parser<'l> {
    tokens: Vec<Spanned>,
    at: usize,
    lookup: &'l mut dyn FnMut(&str) -> Result<ExprValue, String>,
    depth: usize,
}

impl Parser<'_> {
    fn peek(&self) -> &Tok {
        self.tokens.get(self.at).map(|t| &t.0).unwrap_or(&Tok::End)
    }
    fn col(&self) -> usize {
        self.tokens.get(self.at).or(self.tokens.last()).map(|t| t.1).unwrap_or(1)
    }
    fn bump(&mut self) -> (Tok, usize) {
        let t = self.tokens.get(self.at).cloned().unwrap_or((Tok::End, self.col()));
        if self.at < self.tokens.len() {
            self.at += 1;
        }
        t
    }
    fn err(&self, message: String) -> ExprError {
        ExprError { column: self.col(), message }
    }
    fn is_word(&self, w: &str) -> bool {
        matches!(self.peek(), Tok::Ident(s) if s == w)
    }
    fn enter(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.err(format!("expression nested deeper than {MAX_DEPTH} levels")));
        }
        Ok(())
    }

    fn or(&mut self) -> Result<ExprValue, ExprError> {
        let mut v = self.and()?;
        while self.is_word("or") {
            self.bump();
            let r = self.and()?;
            v = ExprValue::Bool(v.as_bool() || r.as_bool());
        }
        Ok(v)
    }

    fn and(&mut self) -> Result<ExprValue, ExprError> {
        let mut v = self.not()?;
        while self.is_word("and") {
            self.bump();
            let r = self.not()?;
            v = ExprValue::Bool(v.as_bool() && r.as_bool());
        }
        Ok(v)
    }

    fn not(&mut self) -> Result<ExprValue, ExprError> {
        if self.is_word("not") {
            self.bump();
            self.enter()?;
            let v = self.not()?;
            self.depth -= 1;
            return Ok(ExprValue::Bool(!v.as_bool()));
        }
        self.cmp()
    }

    fn cmp(&mut self) -> Result<ExprValue, ExprError> {
        let l = self.add()?;
        let op = self.peek().clone();
        if !matches!(op, Tok::Eq | Tok::Ne | Tok::Lt | Tok::Le | Tok::Gt | Tok::Ge) {
            return Ok(l);
        }
        self.bump();
        let r = self.add()?;
        let (a, b) = (l.as_num(), r.as_num());
        Ok(ExprValue::Bool(match op {
            Tok::Eq => a == b,
            Tok::Ne => a != b,
            Tok::Lt => a < b,
            Tok::Le => a <= b,
            Tok::Gt => a > b,
            _ => a >= b,
        }))
    }

    fn add(&mut self) -> Result<ExprValue, ExprError> {
        let mut v = self.mul()?.as_num();
        loop {
            let op = self.peek().clone();
            if !matches!(op, Tok::Plus | Tok::Minus) {
                return Ok(ExprValue::Num(v));
            }
            self.bump();
            let r = self.mul()?.as_num();
            v = if op == Tok::Plus { v + r } else { v - r };
        }
    }

    fn mul(&mut self) -> Result<ExprValue, ExprError> {
        let first = self.unary()?;
        if !matches!(self.peek(), Tok::Star | Tok::Slash | Tok::Percent) {
            return Ok(first);
        }
        let mut v = first.as_num();
        loop {
            let (op, col) = match self.peek() {
                Tok::Star | Tok::Slash | Tok::Percent => self.bump(),
                _ => return Ok(ExprValue::Num(v)),
            };
            let r = self.unary()?.as_num();
            v = match op {
                Tok::Star => v * r,
                _ if r == 0.0 => return Err(ExprError { column: col, message: "division by zero".into() }),
                Tok::Slash => v / r,
                _ => v % r,
            };
        }
    }

    fn unary(&mut self) -> Result<ExprValue, ExprError> {
        if *self.peek() == Tok::Minus {
            self.bump();
            self.enter()?;
            let v = self.unary()?;
            self.depth -= 1;
            return Ok(ExprValue::Num(-v.as_num()));
        }
        self.primary()
    }

    fn primary(&mut self) -> Result<ExprValue, ExprError> {
        let (tok, col) = self.bump();
        match tok {
            Tok::Num(v) => Ok(ExprValue::Num(v)),
            Tok::Param(name) => (self.lookup)(&name).map_err(|message| ExprError { column: col, message }),
            Tok::LParen => {
                self.enter()?;
                let v = self.or()?;
                self.depth -= 1;
                self.expect_rparen(col)?;
                Ok(v)
            }
            Tok::Ident(name) if name == "true" => Ok(ExprValue::Bool(true)),
            Tok::Ident(name) if name == "false" => Ok(ExprValue::Bool(false)),
            // esmini accepts the constant `pi`.
            Tok::Ident(name) if name == "pi" && *self.peek() != Tok::LParen => Ok(ExprValue::Num(std::f64::consts::PI)),
            Tok::Ident(name) => {
                if *self.peek() != Tok::LParen {
                    return Err(ExprError { column: col, message: format!("expected a number, a $parameter, '(' or a function call, found '{name}'") });
                }
                let open = self.bump().1;
                self.enter()?;
                let mut args = Vec::new();
                if *self.peek() != Tok::RParen {
                    loop {
                        args.push(self.or()?.as_num());
                        if *self.peek() == Tok::Comma {
                            self.bump();
                        } else {
                            break;
                        }
                    }
                }
                self.depth -= 1;
                self.expect_rparen(open)?;
                functions::call(&name, &args).map(ExprValue::Num).map_err(|message| ExprError { column: col, message })
            }
            Tok::End => Err(ExprError { column: col, message: "unexpected end of expression, expected a value".into() }),
            other => Err(ExprError { column: col, message: format!("expected a value, found {}", other.describe()) }),
        }
    }

    fn expect_rparen(&mut self, open: usize) -> Result<(), ExprError> {
        if *self.peek() == Tok::RParen {
            self.bump();
            Ok(())
        } else {
            Err(self.err(format!("expected ')' to close '(' at column {open}, found {}", self.peek().describe())))
        }
    }
}

/// esmini's tolerance for non-numeric expressions such as `${$name + suffix}`: when every
/// top-level `+` term is a `$parameter` or plain words, the result is the terms' texts joined.
/// None when the expression is not of that form.
pub fn concatenate(src: &str, lookup: &mut dyn FnMut(&str) -> Option<String>) -> Option<String> {
    let mut out = String::new();
    for term in src.split('+') {
        let t = term.trim();
        if t.is_empty() {
            return None;
        }
        if let Some(name) = t.strip_prefix('$') {
            if !name.chars().all(|c| c.is_alphanumeric() || c == '_') {
                return None;
            }
            out.push_str(&lookup(name)?);
        } else if t.chars().all(|c| c.is_alphanumeric() || c == '_' || c == ' ' || c == '.') {
            out.push_str(t);
        } else {
            return None;
        }
    }
    Some(out)
}
