//! Errors and warnings of the XML reader, each with file, line and column.

use std::fmt;
use std::path::PathBuf;

/// Why a file could not be read into the model.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("cannot read {path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {bytes} bytes is larger than the {} bytes the reader accepts", super::MAX_FILE_BYTES)]
    TooLarge { path: PathBuf, bytes: u64 },
    /// roxmltree's message carries the line and column.
    #[error("{path}: not well-formed XML: {source}")]
    Xml {
        path: PathBuf,
        #[source]
        source: roxmltree::Error,
    },
    /// Well-formed XML that is not what the 2020a format (or the model) allows.
    #[error("{path}:{line}:{column}: {message}")]
    Invalid { path: PathBuf, line: u32, column: u32, message: String },
}

/// Something in the file the model cannot hold and the reader skipped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ReadWarning {
    pub path: PathBuf,
    pub line: u32,
    pub column: u32,
    pub message: String,
}

impl fmt::Display for ReadWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: warning: {}", self.path.display(), self.line, self.column, self.message)
    }
}
