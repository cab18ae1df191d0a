//! `render` — pictures of a CommonRoad scenario: the lanelet network (road surface, borders,
//! line markings, stop lines), traffic signs and lights, static, environment and dynamic
//! obstacles in their shapes and type colours, the ego highlighted with its path, the planning
//! problems' goal regions; each road user labelled (`name (id)`) with a trail of its last
//! seconds; a header with the time and the storyboard events so far, a footer with a scale
//! bar and a legend. By default a picture shows where the road users are ([`Frame`]).
//! Outputs: PNG stills, SVG stills, animated GIFs, a sheet of stills at the events' times.
//! CPU only (tiny-skia), no display, no system fonts (a built-in 5×7 bitmap font).
//!
//! Names and events are plain data ([`RenderOptions::names`], [`RenderOptions::marks`]): the
//! crate knows nothing of where they come from.
//!
//! It draws the `commonroad` model and knows nothing of OpenSCENARIO or OpenDRIVE. One display
//! list ([`scene`]) feeds every output format, so a PNG and an SVG show the same picture.
//!
//! ```no_run
//! # fn f(scenario: &commonroad::Scenario, problems: &commonroad::PlanningProblemSet) -> Result<(), render::Error> {
//! let options = render::RenderOptions { time: 5.5, ..Default::default() };
//! let png: Vec<u8> = render::render_png(scenario, Some(problems), &options)?;
//! # Ok(()) }
//! ```

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod animation;
mod ego;
mod error;
pub mod font;
pub mod frame;
pub mod layout;
mod options;
mod palette;
mod raster;
pub mod scene;
mod sheet;
pub mod style;
mod svg;
pub mod timeline;
pub mod view;

use commonroad::{PlanningProblemSet, Scenario};

pub use ego::{find_ego, SAME_POSITION_M};
pub use error::Error;
pub use layout::{DrawnObstacle, Label, Layout, PxRect};
pub use options::{Frame, Mark, RenderOptions, FOLLOW_SPAN_M, MAX_WIDTH, MIN_WIDTH};
pub use scene::{time_label, Prepared};
pub use sheet::{render_sheet_png, sheet_times, MAX_PANELS};

/// A still at `options.time` as PNG bytes.
pub fn render_png(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<Vec<u8>, Error> {
    let step = checked_step(scenario, options.time)?;
    let prepared = Prepared::still_at(scenario, problems, options, step)?;
    encode_png(&pixmap_at(&prepared, step)?)
}

/// Stills at several times (seconds), each framed as [`render_png`] frames it: PNG bytes in
/// the order of `times`.
pub fn render_pngs(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions, times: &[f64]) -> Result<Vec<Vec<u8>>, Error> {
    times.iter().map(|&time| render_png(scenario, problems, &RenderOptions { time, ..options.clone() })).collect()
}

/// A still at `options.time` as RGBA pixels (straight alpha, row-major), with its size.
pub fn render_rgba(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<(u32, u32, Vec<u8>), Error> {
    let step = checked_step(scenario, options.time)?;
    let prepared = Prepared::still_at(scenario, problems, options, step)?;
    let pm = pixmap_at(&prepared, step)?;
    Ok((pm.width(), pm.height(), pm.data().to_vec()))
}

/// Where the road users and their labels are on the still [`render_png`] draws at
/// `options.time`, in pixels.
pub fn render_layout(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<Layout, Error> {
    let step = checked_step(scenario, options.time)?;
    Ok(Prepared::still_at(scenario, problems, options, step)?.layout(step))
}

/// A still at `options.time` as an SVG document.
pub fn render_svg(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<String, Error> {
    let step = checked_step(scenario, options.time)?;
    let prepared = Prepared::still_at(scenario, problems, options, step)?;
    Ok(svg::to_svg(&prepared.scene(step)))
}

/// An animated GIF over the whole scenario (`options.time` is not used), framed over the
/// whole run (or following `Frame::Follow`'s obstacle).
pub fn render_gif(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<Vec<u8>, Error> {
    let prepared = Prepared::new(scenario, problems, options, frame::Purpose::Animation, None, true)?;
    animation::animate(&prepared, options.gif_max_frames, options.gif_max_bytes)
}

/// Decodes PNG bytes into (width, height, straight RGBA pixels): for callers that check or
/// post-process a picture without a PNG crate of their own.
pub fn decode_png(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>), Error> {
    let pm = tiny_skia::Pixmap::decode_png(bytes).map_err(|e| Error::Encode { format: "PNG", message: e.to_string() })?;
    let rgba = pm
        .pixels()
        .iter()
        .flat_map(|p| {
            let c = p.demultiply();
            [c.red(), c.green(), c.blue(), c.alpha()]
        })
        .collect();
    Ok((pm.width(), pm.height(), rgba))
}

fn checked_step(scenario: &Scenario, time: f64) -> Result<u64, Error> {
    if !(time.is_finite() && time >= 0.0) {
        return Err(Error::Option(format!("--time must be a finite number of seconds >= 0, got {time}")));
    }
    Ok(timeline::step_of(time, scenario.header.time_step_size))
}

fn pixmap_at(prepared: &Prepared, step: u64) -> Result<tiny_skia::Pixmap, Error> {
    let mut pm = raster::canvas(prepared.width, prepared.height, style::BACKGROUND)?;
    raster::paint_prims(&mut pm, &prepared.base(step));
    raster::paint_prims(&mut pm, &prepared.moving(step));
    Ok(pm)
}

fn encode_png(pm: &tiny_skia::Pixmap) -> Result<Vec<u8>, Error> {
    pm.encode_png().map_err(|e| Error::Encode { format: "PNG", message: e.to_string() })
}

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
