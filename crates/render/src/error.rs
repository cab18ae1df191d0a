//! Why a picture could not be drawn.

/// A rendering failure; the message says which option or which part of the scenario.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An option out of range (the message names it).
    #[error("{0}")]
    Option(String),
    /// `--ego ID` names no dynamic obstacle of the scenario.
    #[error("--ego {0}: the scenario has no dynamic obstacle with this id")]
    UnknownEgo(u64),
    /// Nothing to draw, or coordinates no picture can hold.
    #[error("cannot fit a view: {0}")]
    View(String),
    /// The encoder failed (PNG or GIF).
    #[error("cannot encode the {format} picture: {message}")]
    Encode { format: &'static str, message: String },
}
