//! A minimal indenting XML emitter that knows the schema's lexical rules: decimals through
//! [`format_decimal`], escaped text, and a context stack ("lanelet 3 / leftBound") so an error
//! names the element that could not be written.

use super::error::WriteError;
use super::escape::escape;
use super::number::{format_decimal, is_written_positive};

pub(crate) struct Emitter {
    out: String,
    depth: usize,
    context: Vec<String>,
}

impl Emitter {
    pub(crate) fn new() -> Self {
        Self {
            out: String::from("<?xml version='1.0' encoding='utf-8'?>\n"),
            depth: 0,
            context: Vec::new(),
        }
    }

    pub(crate) fn finish(self) -> Vec<u8> {
        self.out.into_bytes()
    }

    fn where_(&self, name: &str) -> String {
        let mut parts = self.context.clone();
        parts.push(name.to_string());
        parts.join(" / ")
    }

    /// Starts a context for error messages (e.g. "dynamicObstacle 21").
    pub(crate) fn push_context(&mut self, label: String) {
        self.context.push(label);
    }

    pub(crate) fn pop_context(&mut self) {
        self.context.pop();
    }

    fn indent(&mut self) {
        for _ in 0..self.depth {
            self.out.push_str("  ");
        }
    }

    pub(crate) fn escaped(&self, name: &str, s: &str) -> Result<String, WriteError> {
        escape(s).map_err(|ch| WriteError::InvalidChar {
            context: self.where_(name),
            ch,
        })
    }

    pub(crate) fn decimal(&self, name: &str, v: f64) -> Result<String, WriteError> {
        format_decimal(v).ok_or_else(|| WriteError::NonFinite {
            context: self.where_(name),
            value: v,
        })
    }

    /// A `positiveDecimal`: must still be > 0 after rounding.
    pub(crate) fn positive(&self, name: &str, v: f64) -> Result<String, WriteError> {
        let s = self.decimal(name, v)?;
        if !is_written_positive(v) {
            return Err(WriteError::NotPositive {
                context: self.where_(name),
                value: v,
            });
        }
        Ok(s)
    }

    fn attributes(&self, name: &str, attrs: &[(&str, String)]) -> Result<String, WriteError> {
        let mut s = String::new();
        for (k, v) in attrs {
            s.push(' ');
            s.push_str(k);
            s.push_str("=\"");
            s.push_str(&self.escaped(&format!("{name}@{k}"), v)?);
            s.push('"');
        }
        Ok(s)
    }

    /// `<name attrs>` on its own line; nesting deepens.
    pub(crate) fn open(&mut self, name: &str, attrs: &[(&str, String)]) -> Result<(), WriteError> {
        let a = self.attributes(name, attrs)?;
        self.indent();
        self.out.push('<');
        self.out.push_str(name);
        self.out.push_str(&a);
        self.out.push_str(">\n");
        self.depth += 1;
        Ok(())
    }

    pub(crate) fn close(&mut self, name: &str) {
        self.depth = self.depth.saturating_sub(1);
        self.indent();
        self.out.push_str("</");
        self.out.push_str(name);
        self.out.push_str(">\n");
    }

    /// `<name attrs/>`.
    pub(crate) fn empty(&mut self, name: &str, attrs: &[(&str, String)]) -> Result<(), WriteError> {
        let a = self.attributes(name, attrs)?;
        self.indent();
        self.out.push('<');
        self.out.push_str(name);
        self.out.push_str(&a);
        self.out.push_str("/>\n");
        Ok(())
    }

    /// A line of already escaped/formatted markup (e.g. a whole `<point>`).
    pub(crate) fn raw_line(&mut self, markup: &str) {
        self.indent();
        self.out.push_str(markup);
        self.out.push('\n');
    }

    /// `<name>text</name>` with `text` escaped.
    pub(crate) fn text(&mut self, name: &str, text: &str) -> Result<(), WriteError> {
        let t = self.escaped(name, text)?;
        self.raw_line(&format!("<{name}>{t}</{name}>"));
        Ok(())
    }

    /// `<name>decimal</name>`.
    pub(crate) fn num(&mut self, name: &str, v: f64) -> Result<(), WriteError> {
        let t = self.decimal(name, v)?;
        self.raw_line(&format!("<{name}>{t}</{name}>"));
        Ok(())
    }

    /// `<name>positive decimal</name>`.
    pub(crate) fn positive_num(&mut self, name: &str, v: f64) -> Result<(), WriteError> {
        let t = self.positive(name, v)?;
        self.raw_line(&format!("<{name}>{t}</{name}>"));
        Ok(())
    }

    /// `<name>integer</name>`.
    pub(crate) fn int(&mut self, name: &str, v: impl std::fmt::Display) {
        self.raw_line(&format!("<{name}>{v}</{name}>"));
    }
}
