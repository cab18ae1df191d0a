//! Errors, positioned in a source file; warnings are `diagnostic::Diagnostic`s (the loader
//! accepted something the user should know about: data, never printed).

use serde::Serialize;

pub use diagnostic::{Diagnostic, Location};
use std::path::{Path, PathBuf};

/// What went wrong, for callers that branch on the kind (tests, exit codes).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A file could not be read (the message names the path tried).
    Io,
    /// The file is not well-formed XML.
    Xml,
    /// A required element or attribute is missing, or an element is not the expected one.
    Structure,
    /// An attribute value does not parse as the expected type or enumeration.
    Value,
    /// A `$name` refers to a parameter that is not declared in scope.
    UndeclaredParameter,
    /// Parameter declarations refer to each other in a cycle.
    ParameterCycle,
    /// A `${...}` expression does not parse or cannot be evaluated.
    Expression,
    /// A catalog named by a CatalogReference cannot be found in any catalog directory.
    MissingCatalog,
    /// The catalog exists but has no entry of that name.
    MissingCatalogEntry,
    /// A size or depth limit guarding against hostile input was exceeded.
    Limit,
}

/// A load failure: kind, place and a message saying what was expected.
#[derive(Debug, Clone, thiserror::Error)]
#[error("{location}: {message}")]
pub struct Error {
    pub kind: ErrorKind,
    pub location: Location,
    pub message: String,
}

impl Error {
    pub fn new(kind: ErrorKind, location: Location, message: impl Into<String>) -> Self {
        Error { kind, location, message: message.into() }
    }

    pub fn io(path: &Path, err: &std::io::Error) -> Self {
        Error::new(ErrorKind::Io, Location::file_only(path), format!("cannot read file {}: {err}", path.display()))
    }
}

/// The absolute, lexically normalised form of `path` (`a/b/../c` becomes `a/c`), so that paths in
/// the model and in messages are stable and readable.
pub(crate) fn absolute(path: &Path) -> PathBuf {
    use std::path::Component;
    let joined = if path.is_absolute() { path.to_path_buf() } else { std::env::current_dir().map(|d| d.join(path)).unwrap_or_else(|_| path.to_path_buf()) };
    let mut out = PathBuf::new();
    for c in joined.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if matches!(out.components().next_back(), Some(Component::Normal(_))) {
                    out.pop();
                } else {
                    out.push(c);
                }
            }
            other => out.push(other),
        }
    }
    out
}
