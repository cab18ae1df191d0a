//! Errors of the model's checked constructors (the things the types refuse to represent).

/// A value the CommonRoad 2020a model cannot represent.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
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
}

pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64, ModelError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ModelError::NonFinite { what, value })
    }
}

pub(crate) fn positive(what: &'static str, value: f64) -> Result<f64, ModelError> {
    finite(what, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(ModelError::NotPositive { what, value })
    }
}
