//! The crate's one error: a value the model cannot represent (its checked constructors), a
//! model a writer cannot write (2020a XML, the 2024 protobuf files), or a file the reader cannot
//! read. Messages name what and where.

use std::path::PathBuf;
use std::sync::Arc;

use diagnostic::Location;

/// Why a model value could not be built, a scenario written, or a file read.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// Left and right bound of a lanelet must have the same number of points: the reader
    /// computes the centre line as `0.5 * (left + right)` point by point.
    #[error("lanelet bounds must have the same number of points: left has {left}, right has {right}")]
    BoundPointCountMismatch { left: usize, right: usize },
    /// A bound needs at least two points (XSD `minOccurs="2"`).
    #[error("lanelet bounds need at least 2 points, got {got}")]
    TooFewBoundPoints { got: usize },
    /// A polygon needs at least three points (XSD `minOccurs="3"`).
    #[error("a polygon needs at least 3 points, got {got}")]
    TooFewPolygonPoints { got: usize },
    /// NaN or infinity where the schema wants an `xs:decimal`.
    #[error("{what} must be a finite number, got {value}")]
    NonFinite { what: &'static str, value: f64 },
    /// Length, width or radius that is not strictly positive (`positiveDecimal`).
    #[error("{what} must be > 0, got {value}")]
    NotPositive { what: &'static str, value: f64 },
    /// An interval whose start is after its end.
    #[error("interval start {start} is after its end {end}")]
    ReversedInterval { start: f64, end: f64 },
    /// A goal time interval must end at time step >= 1 (`positiveInteger`).
    #[error("a goal time interval must end at time step >= 1, got [{start}, {end}]")]
    BadTimeInterval { start: u64, end: u64 },
    /// A date that does not exist.
    #[error("invalid date {year:04}-{month:02}-{day:02}")]
    InvalidDate { year: u16, month: u8, day: u8 },
    /// A benchmark id the CommonRoad readers would not parse.
    #[error("benchmark id {id:?} does not match COUNTRY_MapName-MapId[_ConfigId[_T-PredId]]: {why}")]
    InvalidBenchmarkId { id: String, why: &'static str },

    /// Writing: NaN or infinity, which neither `xs:decimal` nor the 2024 messages can hold.
    #[error("cannot write {context}: {value} is not a finite number")]
    WriteNonFinite { context: String, value: f64 },
    /// Writing XML: a `positiveDecimal` that is <= 0 or rounds to 0 at the written precision
    /// (`decimals`, [`crate::xml::DECIMALS`]).
    #[error("cannot write {context}: {value} is not > 0 at {decimals} decimals")]
    WriteNotPositive { context: String, value: f64, decimals: usize },
    /// Writing XML: a character XML 1.0 cannot represent (e.g. a C0 control character).
    #[error("cannot write {context}: character U+{:04X} is not allowed in XML 1.0", *ch as u32)]
    InvalidChar { context: String, ch: char },
    /// A scenario file needs at least one planning problem (`hint`: what to do instead).
    #[error("a CommonRoad scenario file needs at least one planning problem{hint}")]
    NoPlanningProblem { hint: &'static str },
    /// Writing 2024: an id, time step or duration larger than its field (`uint32`, `int32`).
    #[error("cannot write {context}: {value} does not fit the 2024 field (at most {max})")]
    OutOfRange { context: String, value: u64, max: u64 },
    /// Writing 2024: ids from `first` ([`crate::protobuf::FIRST_MAP_PART_ID`]) on are the map's
    /// bounds, stop lines and crossings.
    #[error("cannot write {context}: id {id} is in the range the 2024 map numbers its bounds and stop lines from ({first} on)")]
    IdInMapPartRange { context: String, id: u64, first: u64 },
    /// Writing 2024: a goal names a lanelet the network does not have.
    #[error("cannot write {context}: goal lanelet {id} is not in the lanelet network")]
    UnknownLanelet { context: String, id: u64 },
    /// Writing 2024: a name of the model the generated enums do not have (a bug: every variant
    /// is mapped).
    #[error("{what} {name:?} has no 2024 enumeration value")]
    NoEnumValue { what: &'static str, name: String },
    /// Creating, writing or renaming an output file failed.
    #[error("cannot write {path}: {source}")]
    WriteFile {
        path: PathBuf,
        #[source]
        source: Arc<std::io::Error>,
    },

    /// Reading: the file could not be read.
    #[error("cannot read {path}: {source}")]
    ReadFile {
        path: PathBuf,
        #[source]
        source: Arc<std::io::Error>,
    },
    /// Reading: a file larger than the reader accepts (`max`, [`crate::xml::MAX_FILE_BYTES`]).
    #[error("{path}: {bytes} bytes is larger than the {max} bytes the reader accepts")]
    TooLarge { path: PathBuf, bytes: u64, max: u64 },
    /// Reading: not well-formed XML (roxmltree's message carries the line and column).
    #[error("{path}: not well-formed XML: {source}")]
    Xml {
        path: PathBuf,
        #[source]
        source: roxmltree::Error,
    },
    /// Reading: well-formed XML that is not what the 2020a format (or the model) allows.
    #[error("{location}: {message}")]
    Invalid { location: Location, message: String },
}

pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite { what, value })
    }
}

pub(crate) fn positive(what: &'static str, value: f64) -> Result<f64, Error> {
    finite(what, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { what, value })
    }
}
