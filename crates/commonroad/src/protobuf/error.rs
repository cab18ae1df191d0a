//! Why a model could not be written in the 2024 format.

/// A value the 2024 messages cannot hold, or a scenario the format cannot describe.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WriteError {
    /// NaN or infinity in a state, a shape or the location.
    #[error("cannot write {context}: {value} is not a finite number")]
    NonFinite { context: String, value: f64 },
    /// An id, time step or duration larger than its field (`uint32`, `int32`).
    #[error("cannot write {context}: {value} does not fit the 2024 field (at most {max})")]
    OutOfRange { context: String, value: u64, max: u64 },
    /// Ids from [`super::FIRST_MAP_PART_ID`] on are the map's bounds, stop lines and crossings.
    #[error(
        "cannot write {context}: id {id} is in the range the 2024 map numbers its bounds and stop \
         lines from ({} on)",
        super::FIRST_MAP_PART_ID
    )]
    IdInMapPartRange { context: String, id: u64 },
    /// A goal names a lanelet the network does not have.
    #[error("cannot write {context}: goal lanelet {id} is not in the lanelet network")]
    UnknownLanelet { context: String, id: u64 },
    /// A scenario file needs at least one planning problem.
    #[error("a CommonRoad scenario file needs at least one planning problem")]
    NoPlanningProblem,
    /// A name of the model the generated enums do not have (a bug: every variant is mapped).
    #[error("{what} {name:?} has no 2024 enumeration value")]
    NoEnumValue { what: &'static str, name: String },
}

pub(super) fn finite(context: impl FnOnce() -> String, value: f64) -> Result<f64, WriteError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(WriteError::NonFinite { context: context(), value })
    }
}

pub(super) fn fits_u32(context: impl FnOnce() -> String, value: u64) -> Result<u32, WriteError> {
    u32::try_from(value).map_err(|_| WriteError::OutOfRange { context: context(), value, max: u32::MAX as u64 })
}

pub(super) fn fits_i32(context: impl FnOnce() -> String, value: u64) -> Result<i32, WriteError> {
    i32::try_from(value).map_err(|_| WriteError::OutOfRange { context: context(), value, max: i32::MAX as u64 })
}
