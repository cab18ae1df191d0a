//! The storyboard as a state machine: the element tree flattened into nodes, element states
//! and transitions, and the rules that move elements between them (start, end, stop, triggers).

pub mod machine;
pub mod select_triggering;
pub mod tree;

pub use tree::{Kind, Node, State, Transition};
