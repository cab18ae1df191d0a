//! `diagnostic`: a place in a source file (`Location`: file, 1-based line and column) and a
//! message about it (`Diagnostic`), the one positioned form in which osc2cr's readers
//! (OpenSCENARIO, OpenDRIVE), its lanelet converter and its engine report what they noticed.
//! Warnings are data: a library returns them, a front end decides how to show them.
//!
//! It owns nothing but these two types, how they are written (`file:line:col: message`, or
//! `file: message` for the file as a whole) and where in a text the readers' XML parser (roxmltree)
//! found an error (`LineCol::of_xml_error`), so that every crate says "where" the same way.
//!
//! ```
//! use diagnostic::{Diagnostic, Location};
//!
//! let at = Location::new("cut_in.xosc", 12, 5);
//! let d = Diagnostic::new(at, "attribute 'x' of <Y> is not read by osc2cr and has no effect");
//! assert_eq!(d.to_string(), "cut_in.xosc:12:5: attribute 'x' of <Y> is not read by osc2cr and has no effect");
//! assert_eq!(d.labelled("warning").to_string(), "cut_in.xosc:12:5: warning: attribute 'x' of <Y> is not read by osc2cr and has no effect");
//! assert_eq!(Location::file_only("cut_in.xosc".as_ref()).to_string(), "cut_in.xosc");
//! ```

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use serde::Serialize;

/// A line and a column in a source file, both 1-based (0 where there is none).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default, Serialize)]
pub struct LineCol {
    pub line: u32,
    pub col: u32,
}

impl LineCol {
    /// Where an XML parse error is. roxmltree puts "the file ended too early" errors at 1:1;
    /// the place a reader needs is the end of the file, where the document was cut off.
    pub fn of_xml_error(e: &roxmltree::Error, text: &str) -> LineCol {
        match e {
            roxmltree::Error::UnexpectedEndOfStream | roxmltree::Error::UnclosedRootNode => LineCol::end_of(text),
            _ => LineCol { line: e.pos().row, col: e.pos().col },
        }
    }

    /// Just after the last character of `text` (columns counted in characters): where a
    /// reader points when a document ends too early.
    ///
    /// ```
    /// use diagnostic::LineCol;
    /// assert_eq!(LineCol::end_of("<a>\n  <b>"), LineCol { line: 2, col: 6 });
    /// assert_eq!(LineCol::end_of(""), LineCol { line: 1, col: 1 });
    /// ```
    pub fn end_of(text: &str) -> LineCol {
        let (before, last_line) = match text.rfind('\n') {
            Some(i) => (&text[..=i], &text[i + 1..]),
            None => ("", text),
        };
        let line = before.matches('\n').count() + 1;
        let col = last_line.chars().count() + 1;
        LineCol { line: u32::try_from(line).unwrap_or(u32::MAX), col: u32::try_from(col).unwrap_or(u32::MAX) }
    }
}

/// A place in a source file: 1-based line and column (line 0 means "the file as a whole").
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct Location {
    pub file: Arc<Path>,
    pub line: u32,
    pub col: u32,
}

impl Location {
    pub fn new(file: impl AsRef<Path>, line: u32, col: u32) -> Self {
        Location { file: Arc::from(file.as_ref()), line, col }
    }

    /// The file as a whole (line and column 0).
    pub fn file_only(file: &Path) -> Self {
        Location::new(file, 0, 0)
    }

    /// `pos` in `file`.
    pub fn at(file: &Arc<Path>, pos: LineCol) -> Self {
        Location { file: file.clone(), line: pos.line, col: pos.col }
    }

    /// Line and column.
    pub fn line_col(&self) -> LineCol {
        LineCol { line: self.line, col: self.col }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}", self.file.display())
        } else {
            write!(f, "{}:{}:{}", self.file.display(), self.line, self.col)
        }
    }
}

/// Something said about a place in a file: a warning a reader or the engine returns, a
/// problem a strict reading stops at.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct Diagnostic {
    pub location: Location,
    pub message: String,
}

impl Diagnostic {
    pub fn new(location: Location, message: impl Into<String>) -> Self {
        Diagnostic { location, message: message.into() }
    }

    /// A message about `location`.
    pub fn at(location: &Location, message: impl Into<String>) -> Self {
        Diagnostic::new(location.clone(), message)
    }

    /// Written with a label after the place: `file:line:col: <label>: message`.
    pub fn labelled<'a>(&'a self, label: &'a str) -> impl fmt::Display + 'a {
        Labelled { diagnostic: self, label }
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.location, self.message)
    }
}

struct Labelled<'a> {
    diagnostic: &'a Diagnostic,
    label: &'a str,
}

impl fmt::Display for Labelled<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.diagnostic.location, self.label, self.diagnostic.message)
    }
}

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
