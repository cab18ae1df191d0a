//! An owned, positioned copy of an XML document: every element and attribute value knows its
//! line and column. Owned so that parsed catalogs can be cached and reused across references
//! without borrowing the source text.

use crate::error::{Error, ErrorKind, Location};
use std::cell::Cell;
use std::path::Path;
use std::sync::Arc;

/// Hostile-input guards.
pub(crate) const MAX_DEPTH: usize = 200;
pub(crate) const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Pos {
    pub line: u32,
    pub col: u32,
}

#[derive(Debug)]
pub(crate) struct Attr {
    pub name: String,
    pub value: String,
    /// Position of the first character of the value (inside the quotes).
    pub pos: Pos,
    /// Set when the reader asks for it: what no reader asked for is reported as ignored
    /// (`unread.rs`).
    pub read: Cell<bool>,
}

#[derive(Debug)]
pub(crate) struct Elem {
    pub name: String,
    pub attrs: Vec<Attr>,
    children: Vec<Elem>,
    pub pos: Pos,
    /// Set when the reader looks into the element (an attribute, a child, its children).
    pub read: Cell<bool>,
}

/// A parsed file.
#[derive(Debug)]
pub(crate) struct Doc {
    pub file: Arc<Path>,
    pub root: Elem,
}

impl Elem {
    pub(crate) fn attr(&self, name: &str) -> Option<&Attr> {
        self.read.set(true);
        let a = self.attrs.iter().find(|a| a.name == name)?;
        a.read.set(true);
        Some(a)
    }
    pub(crate) fn child(&self, name: &str) -> Option<&Elem> {
        self.read.set(true);
        let c = self.children.iter().find(|c| c.name == name)?;
        c.read.set(true);
        Some(c)
    }
    pub(crate) fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Elem> + 'a {
        self.read.set(true);
        self.children.iter().filter(move |c| c.name == name).inspect(|c| c.read.set(true))
    }
    /// The first child element (for XSD choices).
    pub(crate) fn first_child(&self) -> Option<&Elem> {
        self.read.set(true);
        let c = self.children.first()?;
        c.read.set(true);
        Some(c)
    }
    /// Every child element; a child counts as read only once the reader looks into it.
    pub(crate) fn children(&self) -> &[Elem] {
        self.read.set(true);
        &self.children
    }
    /// Marks the element and all it holds as read: for content the reader has already warned
    /// about as a whole (an unsupported element), so it is not reported twice.
    pub(crate) fn announce(&self) {
        self.read.set(true);
        for a in &self.attrs {
            a.read.set(true);
        }
        for c in &self.children {
            c.announce();
        }
    }
    /// The children without marking anything read (checks that only look, such as the schema
    /// pass and the report of what was not read).
    pub(crate) fn children_unmarked(&self) -> &[Elem] {
        &self.children
    }
}

/// Converts byte offsets to line/column in one forward pass (offsets arrive in document order),
/// avoiding roxmltree's per-call rescan from the start of the text.
struct LineCounter<'t> {
    text: &'t str,
    offset: usize,
    line: u32,
    col: u32,
}

impl LineCounter<'_> {
    fn pos(&mut self, target: usize) -> Pos {
        if target < self.offset {
            // Out of order (should not happen): restart from the top.
            self.offset = 0;
            self.line = 1;
            self.col = 1;
        }
        let end = target.min(self.text.len());
        if let Some(slice) = self.text.get(self.offset..end) {
            for ch in slice.chars() {
                if ch == '\n' {
                    self.line += 1;
                    self.col = 1;
                } else {
                    self.col += 1;
                }
            }
            self.offset = end;
        }
        Pos { line: self.line, col: self.col }
    }
}

pub(crate) fn read_file(path: &Path) -> Result<Doc, Error> {
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, &e))?;
    if meta.len() > MAX_FILE_BYTES {
        return Err(Error::new(ErrorKind::Limit, Location::file_only(path), format!("file is larger than {MAX_FILE_BYTES} bytes")));
    }
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, &e))?;
    // valid UTF-8 (nearly every file) is checked by the fast word-at-a-time validator; only a
    // file with a bad byte pays for the replacement characters
    let text = match std::str::from_utf8(&bytes) {
        Ok(text) => std::borrow::Cow::Borrowed(text),
        Err(_) => String::from_utf8_lossy(&bytes),
    };
    parse_str(path, &text)
}

pub(crate) fn parse_str(path: &Path, text: &str) -> Result<Doc, Error> {
    let file: Arc<Path> = Arc::from(path);
    if text.trim_start_matches('\u{feff}').trim().is_empty() {
        return Err(Error::new(ErrorKind::Xml, Location::file_only(path), "the file is empty: there is no XML document in it"));
    }
    let options = roxmltree::ParsingOptions { allow_dtd: true, ..Default::default() };
    let doc = roxmltree::Document::parse_with_options(text, options).map_err(|e| {
        let diagnostic::LineCol { line, col } = diagnostic::LineCol::of_xml_error(&e, text);
        let message = match e {
            roxmltree::Error::UnexpectedEndOfStream | roxmltree::Error::UnclosedRootNode => {
                format!("not well-formed XML: the file ends before its document does (cut off?): {e}")
            }
            _ => format!("not well-formed XML: {e}"),
        };
        Error::new(ErrorKind::Xml, Location { file: file.clone(), line, col }, message)
    })?;
    let mut counter = LineCounter { text, offset: 0, line: 1, col: 1 };
    let root = convert(doc.root_element(), &mut counter, 0, &file)?;
    Ok(Doc { file, root })
}

fn convert(node: roxmltree::Node, lc: &mut LineCounter, depth: usize, file: &Arc<Path>) -> Result<Elem, Error> {
    let pos = lc.pos(node.range().start);
    if depth > MAX_DEPTH {
        return Err(Error::new(
            ErrorKind::Limit,
            Location { file: file.clone(), line: pos.line, col: pos.col },
            format!("elements nested deeper than {MAX_DEPTH} levels"),
        ));
    }
    let attrs = node
        .attributes()
        // `xsi:noNamespaceSchemaLocation` and the like belong to XML tooling, not to the format.
        .filter(|a| a.namespace().is_none())
        .map(|a| Attr { name: a.name().to_string(), value: a.value().to_string(), pos: lc.pos(a.range_value().start), read: Cell::new(false) })
        .collect();
    let mut children = Vec::new();
    for c in node.children().filter(|c| c.is_element()) {
        children.push(convert(c, lc, depth + 1, file)?);
    }
    Ok(Elem { name: node.tag_name().name().to_string(), attrs, children, pos, read: Cell::new(false) })
}
