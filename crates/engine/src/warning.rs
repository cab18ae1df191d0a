//! Errors of a run. Its warnings — what the engine could not do as the scenario asks — are
//! `Diagnostic`s positioned in the scenario file (data, never printed).

/// A run that could not start, or was stopped.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
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
