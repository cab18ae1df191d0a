//! The renderer's tests, one binary: stills (PNG, SVG), what a picture frames, animations.

mod common;

mod animation;
mod framing;
mod stills;
