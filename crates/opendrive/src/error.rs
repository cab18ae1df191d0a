//! Errors and warnings of loading an OpenDRIVE file. Both carry file, line and column.

use std::path::PathBuf;

/// A position in the source file (1-based line and column).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Default)]
pub struct SourcePos {
    pub line: u32,
    pub col: u32,
}

/// Something in the file that was not modelled or looked suspicious; loading went on.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Warning {
    pub file: PathBuf,
    pub line: u32,
    pub col: u32,
    pub message: String,
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}:{}: warning: {}", self.file.display(), self.line, self.col, self.message)
    }
}

/// Why a file could not be loaded.
#[derive(Debug, thiserror::Error)]
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
    pub fn position(&self) -> Option<SourcePos> {
        match self {
            Error::Io { .. } => None,
            Error::Xml { line, col, .. } | Error::Invalid { line, col, .. } => Some(SourcePos { line: *line, col: *col }),
        }
    }
}
