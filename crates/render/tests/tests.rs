//! The renderer's tests, one binary: stills (PNG, SVG), what a picture frames, what its legend,
//! time bar and header say, animations.

mod common;

mod animation;
mod framing;
mod legend_and_time;
mod stills;
