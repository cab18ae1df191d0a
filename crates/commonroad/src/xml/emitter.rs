//! A minimal indenting XML emitter that knows the schema's lexical rules: decimals through
//! [`format_decimal`](super::number::format_decimal), escaped text, and a context stack
//! ("lanelet 3 / leftBound") so an error names the element that could not be written.
//!
//! Everything is appended to one pre-sized buffer: a scenario file holds tens of thousands
//! of numbers, and a temporary `String` per number (or per line) used to be a large part of
//! the writing time. Error contexts are built only when an error happens. If writing fails
//! the buffer is dropped, so a half-written line never escapes.

use super::escape::escape_into;
use super::number::{is_written_positive, push_decimal, DECIMALS};
use crate::Error;
use std::fmt::Display;
use std::fmt::Write;

pub(crate) struct Emitter {
    out: String,
    depth: usize,
    context: Vec<String>,
}

const PROLOG: &str = "<?xml version='1.0' encoding='utf-8'?>\n";

impl Emitter {
    /// An emitter whose buffer starts with room for `capacity` bytes.
    pub(crate) fn with_capacity(capacity: usize) -> Self {
        let mut out = String::with_capacity(capacity.max(PROLOG.len()));
        out.push_str(PROLOG);
        Self { out, depth: 0, context: Vec::new() }
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

    /// Indentation of a new line.
    pub(crate) fn begin_line(&mut self) {
        for _ in 0..self.depth {
            self.out.push_str("  ");
        }
    }

    pub(crate) fn end_line(&mut self) {
        self.out.push('\n');
    }

    /// Already escaped markup.
    pub(crate) fn push(&mut self, markup: &str) {
        self.out.push_str(markup);
    }

    /// An integer (or any text that needs no escaping).
    pub(crate) fn push_display(&mut self, v: impl Display) {
        // Writing into a String cannot fail.
        let _ = write!(self.out, "{v}");
    }

    /// A decimal; `name` (built only on error) says what it was, e.g. "point/x".
    pub(crate) fn push_decimal(&mut self, v: f64, name: impl FnOnce() -> String) -> Result<(), Error> {
        if push_decimal(&mut self.out, v) {
            Ok(())
        } else {
            Err(Error::WriteNonFinite { context: self.where_(&name()), value: v })
        }
    }

    /// A decimal as a `String` (for attribute values).
    pub(crate) fn decimal(&self, name: &str, v: f64) -> Result<String, Error> {
        let mut s = String::new();
        if push_decimal(&mut s, v) {
            Ok(s)
        } else {
            Err(Error::WriteNonFinite { context: self.where_(name), value: v })
        }
    }

    /// A `positiveDecimal`: must still be > 0 after rounding.
    pub(crate) fn push_positive(&mut self, v: f64, name: &str) -> Result<(), Error> {
        if v.is_finite() && !is_written_positive(v) {
            return Err(Error::WriteNotPositive { context: self.where_(name), value: v, decimals: DECIMALS });
        }
        self.push_decimal(v, || name.to_string())
    }

    /// Escaped text; `name` (built only on error) says where it goes.
    pub(crate) fn push_escaped(&mut self, s: &str, name: impl FnOnce() -> String) -> Result<(), Error> {
        escape_into(&mut self.out, s).map_err(|ch| Error::InvalidChar { context: self.where_(&name()), ch })
    }

    /// ` k="v"` for each attribute, values escaped.
    fn attributes(&mut self, name: &str, attrs: &[(&str, &dyn Display)]) -> Result<(), Error> {
        let mut value = String::new();
        for (k, v) in attrs {
            self.out.push(' ');
            self.out.push_str(k);
            self.out.push_str("=\"");
            value.clear();
            let _ = write!(value, "{v}");
            self.push_escaped(&value, || format!("{name}@{k}"))?;
            self.out.push('"');
        }
        Ok(())
    }

    /// `<name attrs>` on its own line; nesting deepens.
    pub(crate) fn open(&mut self, name: &str, attrs: &[(&str, &dyn Display)]) -> Result<(), Error> {
        self.tag_line(name, attrs, ">\n")?;
        self.depth += 1;
        Ok(())
    }

    pub(crate) fn close(&mut self, name: &str) {
        self.depth = self.depth.saturating_sub(1);
        self.begin_line();
        self.out.push_str("</");
        self.out.push_str(name);
        self.out.push_str(">\n");
    }

    /// `<name attrs/>`.
    pub(crate) fn empty(&mut self, name: &str, attrs: &[(&str, &dyn Display)]) -> Result<(), Error> {
        self.tag_line(name, attrs, "/>\n")
    }

    /// An indented `<name attrs` closed by `end` (`>` or `/>` and the line break).
    fn tag_line(&mut self, name: &str, attrs: &[(&str, &dyn Display)], end: &str) -> Result<(), Error> {
        self.begin_line();
        self.out.push('<');
        self.out.push_str(name);
        self.attributes(name, attrs)?;
        self.out.push_str(end);
        Ok(())
    }

    /// A line of already escaped/formatted markup.
    pub(crate) fn raw_line(&mut self, markup: &str) {
        self.begin_line();
        self.out.push_str(markup);
        self.out.push('\n');
    }

    fn open_tag(&mut self, name: &str) {
        self.begin_line();
        self.out.push('<');
        self.out.push_str(name);
        self.out.push('>');
    }

    fn close_tag(&mut self, name: &str) {
        self.out.push_str("</");
        self.out.push_str(name);
        self.out.push_str(">\n");
    }

    /// `<name>text</name>` with `text` escaped.
    pub(crate) fn text(&mut self, name: &str, text: &str) -> Result<(), Error> {
        self.open_tag(name);
        self.push_escaped(text, || name.to_string())?;
        self.close_tag(name);
        Ok(())
    }

    /// `<name>decimal</name>`.
    pub(crate) fn num(&mut self, name: &str, v: f64) -> Result<(), Error> {
        self.open_tag(name);
        self.push_decimal(v, || name.to_string())?;
        self.close_tag(name);
        Ok(())
    }

    /// `<name>positive decimal</name>`.
    pub(crate) fn positive_num(&mut self, name: &str, v: f64) -> Result<(), Error> {
        self.open_tag(name);
        self.push_positive(v, name)?;
        self.close_tag(name);
        Ok(())
    }

    /// `<name>integer</name>`.
    pub(crate) fn int(&mut self, name: &str, v: impl Display) {
        self.open_tag(name);
        self.push_display(v);
        self.close_tag(name);
    }
}
