//! The trajectory shapes' tests, one binary: each shape against closed forms, esmini's sampling,
//! degenerate and hostile input.

mod degenerate;
mod esmini_sampling;
mod shapes;
