//! Attribute reading with positioned errors and warnings; the context of one parse.

use super::line_index::LineIndex;
use crate::error::Error;
use diagnostic::{Diagnostic, LineCol, Location};
use roxmltree::{Document, Node};
use std::path::Path;

/// Parse state: the file name for messages, the document's line index for positions,
/// warnings so far.
pub(super) struct Ctx<'a, 'input> {
    pub file: &'a Path,
    pub lines: LineIndex<'input>,
    pub warnings: Vec<Diagnostic>,
}

impl<'a, 'input> Ctx<'a, 'input> {
    pub(super) fn new(file: &'a Path, doc: &Document<'input>) -> Self {
        Ctx { file, lines: LineIndex::new(doc.input_text()), warnings: Vec::new() }
    }
    pub(super) fn pos_of(&self, byte: usize) -> LineCol {
        self.lines.pos(byte)
    }
    pub(super) fn pos(&self, node: Node) -> LineCol {
        self.pos_of(node.range().start)
    }
    pub(super) fn error_at(&self, byte: usize, message: impl Into<String>) -> Error {
        let p = self.pos_of(byte);
        Error::Invalid { file: self.file.to_path_buf(), line: p.line, col: p.col, message: message.into() }
    }
    pub(super) fn error(&self, node: Node, message: impl Into<String>) -> Error {
        self.error_at(node.range().start, message)
    }
    pub(super) fn warn(&mut self, node: Node, message: impl Into<String>) {
        let p = self.pos(node);
        self.warnings.push(Diagnostic::new(Location::new(self.file, p.line, p.col), message));
    }

    /// A required attribute as text.
    pub(super) fn req_str<'n>(&self, node: Node<'n, 'input>, name: &str) -> Result<&'n str, Error> {
        node.attribute(name).ok_or_else(|| self.error(node, format!("<{}> is missing the required attribute `{name}`", node.tag_name().name())))
    }
    /// An optional attribute as an owned string.
    pub(super) fn opt_string(&self, node: Node, name: &str) -> Option<String> {
        node.attribute(name).map(str::to_string)
    }

    fn number(&self, node: Node, name: &str, raw: &str) -> Result<f64, Error> {
        let at = node.attribute_node(name).map_or(node.range().start, |a| a.range_value().start);
        let value: f64 = raw
            .trim()
            .parse()
            .map_err(|_| self.error_at(at, format!("attribute `{name}` of <{}>: expected a number, found `{raw}`", node.tag_name().name())))?;
        if !value.is_finite() {
            return Err(self.error_at(at, format!("attribute `{name}` of <{}>: expected a finite number, found `{raw}`", node.tag_name().name())));
        }
        Ok(value)
    }
    /// A required finite number.
    pub(super) fn req_f64(&self, node: Node, name: &str) -> Result<f64, Error> {
        self.required(node, name, Self::number)
    }
    /// An optional finite number (empty text counts as absent).
    pub(super) fn opt_f64(&self, node: Node, name: &str) -> Result<Option<f64>, Error> {
        self.optional(node, name, Self::number)
    }
    /// A finite number with a default when absent.
    pub(super) fn f64_or(&self, node: Node, name: &str, default: f64) -> Result<f64, Error> {
        Ok(self.opt_f64(node, name)?.unwrap_or(default))
    }

    fn integer(&self, node: Node, name: &str, raw: &str) -> Result<i32, Error> {
        let at = node.attribute_node(name).map_or(node.range().start, |a| a.range_value().start);
        let t = raw.trim();
        // Some tools write lane ids as "1.0"; accept integral decimals.
        t.parse::<i32>()
            .ok()
            .or_else(|| t.parse::<f64>().ok().filter(|v| v.fract() == 0.0 && v.abs() < 1e9).map(|v| v as i32))
            .ok_or_else(|| self.error_at(at, format!("attribute `{name}` of <{}>: expected an integer, found `{raw}`", node.tag_name().name())))
    }
    /// A required integer.
    pub(super) fn req_i32(&self, node: Node, name: &str) -> Result<i32, Error> {
        self.required(node, name, Self::integer)
    }
    /// An optional integer (empty text counts as absent).
    pub(super) fn opt_i32(&self, node: Node, name: &str) -> Result<Option<i32>, Error> {
        self.optional(node, name, Self::integer)
    }

    /// A required attribute read by `parse` (`number`, `integer`).
    fn required<T>(&self, node: Node, name: &str, parse: fn(&Self, Node, &str, &str) -> Result<T, Error>) -> Result<T, Error> {
        let raw = self.req_str(node, name)?;
        parse(self, node, name, raw)
    }
    /// An optional attribute read by `parse`; empty text counts as absent.
    fn optional<T>(&self, node: Node, name: &str, parse: fn(&Self, Node, &str, &str) -> Result<T, Error>) -> Result<Option<T>, Error> {
        match node.attribute(name) {
            Some(raw) if !raw.trim().is_empty() => parse(self, node, name, raw).map(Some),
            _ => Ok(None),
        }
    }
    /// An optional boolean (`true`/`false`/`1`/`0`); anything else warns and counts as absent.
    pub(super) fn opt_bool(&mut self, node: Node, name: &str) -> Option<bool> {
        let raw = node.attribute(name)?;
        match raw.trim().to_ascii_lowercase().as_str() {
            "true" | "1" | "yes" => Some(true),
            "false" | "0" | "no" => Some(false),
            _ => {
                self.warn(node, format!("attribute `{name}`: expected true/false, found `{raw}`; ignored"));
                None
            }
        }
    }

    /// Check a count against a hostile-input cap.
    pub(super) fn cap(&self, node: Node, what: &str, count: usize, max: usize) -> Result<(), Error> {
        if count > max {
            Err(self.error(node, format!("too many {what}: more than {max}")))
        } else {
            Ok(())
        }
    }
}

/// Element children of `node` (text and comments skipped).
pub(super) fn elements<'a, 'input>(node: Node<'a, 'input>) -> impl Iterator<Item = Node<'a, 'input>> {
    node.children().filter(|n| n.is_element())
}

/// Element children named `name`.
pub(super) fn children_named<'a, 'input: 'a>(node: Node<'a, 'input>, name: &'a str) -> impl Iterator<Item = Node<'a, 'input>> + 'a {
    node.children().filter(move |n| n.is_element() && n.tag_name().name() == name)
}

/// Elements we skip without a word: they carry nothing a converter or the engine uses.
pub(super) fn irrelevant(name: &str) -> bool {
    matches!(name, "userData" | "include" | "dataQuality" | "surface" | "access" | "material" | "visibility")
}
