//! Errors of the XML writer.

use std::path::PathBuf;

/// Why a scenario could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// NaN or infinity: `xs:decimal` has no spelling for it.
    #[error("cannot write {context}: {value} is not a finite number")]
    NonFinite { context: String, value: f64 },
    /// A `positiveDecimal` that is <= 0 or rounds to 0 at the written precision.
    #[error("cannot write {context}: {value} is not > 0 at {} decimals", super::number::DECIMALS)]
    NotPositive { context: String, value: f64 },
    /// A character XML 1.0 cannot represent (e.g. a C0 control character).
    #[error("cannot write {context}: character U+{:04X} is not allowed in XML 1.0", *ch as u32)]
    InvalidChar { context: String, ch: char },
    /// A scenario file needs at least one planning problem (use the map mode otherwise).
    #[error("a CommonRoad scenario file needs at least one planning problem (write a map instead)")]
    NoPlanningProblem,
    /// Creating, writing or renaming the output file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}
