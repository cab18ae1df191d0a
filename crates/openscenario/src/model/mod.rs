//! The resolved scenario model: every number is concrete, every catalog reference replaced by
//! its entry. Elements the engine may warn about carry their `origin` (file, line, column).

mod action;
mod condition;
mod entity;
mod environment;
mod position;
mod scenario;
mod storyboard;
mod trajectory;

pub use action::*;
pub use condition::*;
pub use entity::*;
pub use environment::*;
pub use position::*;
pub use scenario::*;
pub use storyboard::*;
pub use trajectory::*;

/// Where an element came from.
pub type Origin = crate::error::Location;
