//! The storyboard as a state machine: the element tree flattened into nodes, element states
//! and transitions, and the rules that move elements between them (start, end, stop, triggers).

pub(crate) mod machine;
pub(crate) mod select_triggering;
pub(crate) mod tree;

pub(crate) use tree::{Kind, Node, State, Transition};
