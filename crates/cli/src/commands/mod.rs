//! One file per command, named after it (`osc2cr convert` is `convert.rs`): its arguments and
//! its `run`. The options several commands share are defined once, in `shared_options.rs`.

pub(crate) mod check;
pub(crate) mod convert;
pub(crate) mod export;
pub(crate) mod inspect;
pub(crate) mod map;
pub(crate) mod render;
pub(crate) mod serve;
pub(crate) mod simulate;
