//! The model itself: what its constructors refuse, what `validate` finds.

mod constructors;
mod validate;
