//! The checks that turn a value the 2024 messages cannot hold into a [`crate::Error`].

use crate::Error;

pub(super) fn finite(context: impl FnOnce() -> String, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::WriteNonFinite { context: context(), value })
    }
}

pub(super) fn fits_u32(context: impl FnOnce() -> String, value: u64) -> Result<u32, Error> {
    u32::try_from(value).map_err(|_| Error::OutOfRange { context: context(), value, max: u32::MAX as u64 })
}

pub(super) fn fits_i32(context: impl FnOnce() -> String, value: u64) -> Result<i32, Error> {
    i32::try_from(value).map_err(|_| Error::OutOfRange { context: context(), value, max: i32::MAX as u64 })
}
