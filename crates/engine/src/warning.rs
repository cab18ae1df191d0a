//! Warnings (data, never printed) and errors of a run.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// Something the engine could not do as the scenario asks, positioned in the scenario file.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    pub file: Arc<Path>,
    /// 1-based; 0 when the warning concerns the file as a whole.
    pub line: u32,
    pub col: u32,
    pub message: String,
}

impl Warning {
    pub(crate) fn at(origin: &openscenario::Origin, message: impl Into<String>) -> Self {
        Warning { file: origin.file.clone(), line: origin.line, col: origin.col, message: message.into() }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file.display(), self.message)
        } else {
            write!(f, "{}:{}:{}: {}", self.file.display(), self.line, self.col, self.message)
        }
    }
}

/// A run that could not start, or was stopped.
#[derive(Debug, Clone, thiserror::Error)]
pub enum Error {
    #[error("invalid settings: {0}")]
    Settings(String),
    /// What the caller asked of a closed-loop run is wrong (an unknown entity, an input for an
    /// entity that is not external, a value that is not finite, …).
    #[error("{0}")]
    Input(String),
    /// The run's wall-clock deadline passed; the simulated time it had reached.
    #[error("stopped at {0:.2} s of simulated time: the time limit for the run passed")]
    Deadline(f64),
}
