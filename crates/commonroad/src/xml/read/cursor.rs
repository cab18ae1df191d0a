//! The reader's context (document, path, collected warnings) and the small element readers
//! every part shares: children by name, numbers, `<exact>`/interval values, points, ids.

use std::path::Path;

use roxmltree::{Document, Node};

use crate::geometry::Point;
use crate::Error;
use diagnostic::{Diagnostic, Location};

pub(crate) struct Cursor<'d, 'i> {
    doc: &'d Document<'i>,
    path: &'d Path,
    warnings: Vec<Diagnostic>,
}

impl<'d, 'i> Cursor<'d, 'i> {
    pub(super) fn new(doc: &'d Document<'i>, path: &'d Path) -> Self {
        Self { doc, path, warnings: Vec::new() }
    }

    fn pos(&self, node: Node) -> (u32, u32) {
        let p = self.doc.text_pos_at(node.range().start);
        (p.row, p.col)
    }

    /// An error at `node`.
    pub(super) fn err(&self, node: Node, message: impl Into<String>) -> Error {
        let (line, column) = self.pos(node);
        Error::Invalid { location: Location::new(self.path, line, column), message: message.into() }
    }

    /// A warning at `node`.
    pub(super) fn warn(&mut self, node: Node, message: impl Into<String>) {
        let (line, column) = self.pos(node);
        self.warnings.push(Diagnostic::new(Location::new(self.path, line, column), message));
    }

    pub(super) fn into_warnings(self) -> Vec<Diagnostic> {
        self.warnings
    }

    /// The trimmed text of `node` (empty if none).
    pub(super) fn text<'a, 'x>(&self, node: Node<'a, 'x>) -> &'a str {
        node.text().unwrap_or("").trim()
    }

    /// A required child element.
    pub(super) fn req<'a, 'x>(&self, node: Node<'a, 'x>, name: &str) -> Result<Node<'a, 'x>, Error> {
        child(node, name).ok_or_else(|| self.err(node, format!("<{}> needs a <{name}> child", node.tag_name().name())))
    }

    /// The text of `node` as a finite number (xs:decimal; an exponent is tolerated like
    /// commonroad-io does).
    pub(super) fn f64(&self, node: Node) -> Result<f64, Error> {
        let t = self.text(node);
        match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(self.err(node, format!("<{}>: expected a finite decimal number, found {t:?}", node.tag_name().name()))),
        }
    }

    /// The text of `node` as a non-negative integer.
    pub(super) fn u64(&self, node: Node) -> Result<u64, Error> {
        let t = self.text(node);
        t.parse::<u64>().map_err(|_| self.err(node, format!("<{}>: expected a non-negative integer, found {t:?}", node.tag_name().name())))
    }

    /// The number of the required child `name`.
    pub(super) fn f64_child(&self, node: Node, name: &str) -> Result<f64, Error> {
        self.f64(self.req(node, name)?)
    }

    /// `<name><exact>v</exact></name>` (a bare number is accepted too).
    pub(super) fn exact(&self, node: Node) -> Result<f64, Error> {
        match child(node, "exact") {
            Some(e) => self.f64(e),
            None if child(node, "intervalStart").is_some() => {
                Err(self.err(node, format!("<{}>: expected an exact value, found an interval", node.tag_name().name())))
            }
            None => self.f64(node),
        }
    }

    /// Like [`Cursor::exact`] for an optional child: `None` when the child is absent.
    pub(super) fn exact_child(&self, node: Node, name: &str) -> Result<Option<f64>, Error> {
        child(node, name).map(|c| self.exact(c)).transpose()
    }

    /// `<time><exact>n</exact></time>` as an integer time step.
    pub(super) fn exact_time(&self, node: Node) -> Result<u64, Error> {
        let t = self.req(node, "time")?;
        match child(t, "exact") {
            Some(e) => self.u64(e),
            None => Err(self.err(t, "<time>: expected <exact> time step")),
        }
    }

    /// `(intervalStart, intervalEnd)` numbers.
    pub(super) fn interval(&self, node: Node) -> Result<(f64, f64), Error> {
        Ok((self.f64_child(node, "intervalStart")?, self.f64_child(node, "intervalEnd")?))
    }

    /// A point element with `<x>`, `<y>` and optional `<z>`.
    pub(super) fn point(&self, node: Node) -> Result<Point, Error> {
        let x = self.f64_child(node, "x")?;
        let y = self.f64_child(node, "y")?;
        Ok(match child(node, "z") {
            Some(z) => Point::with_z(x, y, self.f64(z)?),
            None => Point::new(x, y),
        })
    }

    /// `<position><point>…</point></position>` (exact position).
    pub(super) fn position_point(&self, node: Node) -> Result<Point, Error> {
        let pos = self.req(node, "position")?;
        match child(pos, "point") {
            Some(p) => self.point(p),
            None => Err(self.err(pos, "<position>: expected an exact <point> (position sets are not supported here)")),
        }
    }

    /// A positive integer attribute (`id` or `ref`).
    pub(super) fn id_attr(&self, node: Node, attr: &str) -> Result<u64, Error> {
        let raw = node.attribute(attr).ok_or_else(|| self.err(node, format!("<{}> needs an attribute {attr}", node.tag_name().name())))?;
        match raw.trim().parse::<u64>() {
            Ok(v) if v > 0 => Ok(v),
            _ => Err(self.err(node, format!("<{}> {attr}={raw:?}: expected a positive integer", node.tag_name().name()))),
        }
    }

    /// A typed id from an attribute (`new` maps the raw number, which is known to be > 0).
    pub(super) fn typed<T>(&self, node: Node, attr: &str, new: fn(u64) -> Option<T>) -> Result<T, Error> {
        let raw = self.id_attr(node, attr)?;
        new(raw).ok_or_else(|| self.err(node, format!("{attr} must be > 0")))
    }

    /// The `ref`s of every child named `name`.
    pub(super) fn refs<T>(&self, node: Node, name: &str, new: fn(u64) -> Option<T>) -> Result<Vec<T>, Error> {
        children(node, name).map(|c| self.typed(c, "ref", new)).collect()
    }

    /// The value of an enumeration spelled as in the XSD, from the text of `node`.
    pub(super) fn enum_text<T: Copy>(&self, node: Node, all: &[T], as_str: fn(T) -> &'static str) -> Result<T, Error> {
        let t = self.text(node);
        all.iter().copied().find(|v| as_str(*v) == t).ok_or_else(|| {
            let allowed: Vec<&str> = all.iter().map(|v| as_str(*v)).collect();
            self.err(node, format!("<{}>: {t:?} is not one of {}", node.tag_name().name(), allowed.join(", ")))
        })
    }
}

/// The first child element named `name`.
pub(crate) fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children().find(|c| c.is_element() && c.tag_name().name() == name)
}

/// Every child element named `name`, in document order.
pub(crate) fn children<'a, 'i: 'a>(node: Node<'a, 'i>, name: &'a str) -> impl Iterator<Item = Node<'a, 'i>> + 'a {
    node.children().filter(move |c| c.is_element() && c.tag_name().name() == name)
}
