//! Errors of loading an OpenDRIVE file, with file, line and column. Its warnings are
//! `diagnostic::Diagnostic`s, positioned the same way.

use std::path::PathBuf;

use diagnostic::LineCol;

/// Why a file could not be loaded.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The file could not be read; `path` is the path tried.
    #[error("{}: cannot read OpenDRIVE file: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// The text is not well-formed XML.
    #[error("{}:{line}:{col}: malformed XML: {message}", file.display())]
    Xml { file: PathBuf, line: u32, col: u32, message: String },
    /// Well-formed XML, but not the OpenDRIVE we expect (missing attribute, bad number, ...).
    #[error("{}:{line}:{col}: {message}", file.display())]
    Invalid { file: PathBuf, line: u32, col: u32, message: String },
}

impl Error {
    /// Line and column of the error, if it has one (I/O errors have none).
    pub fn position(&self) -> Option<LineCol> {
        match self {
            Error::Io { .. } => None,
            Error::Xml { line, col, .. } | Error::Invalid { line, col, .. } => Some(LineCol { line: *line, col: *col }),
        }
    }
}
