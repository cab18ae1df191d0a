//! `render` — pictures of a CommonRoad scenario: the lanelet network (road surface, borders,
//! line markings, stop lines), traffic signs and lights, static, environment and dynamic
//! obstacles in their shapes and type colours, the ego highlighted with its path, the planning
//! problems' goal regions, and a time stamp. Outputs: PNG stills, SVG stills, animated GIFs.
//! CPU only (tiny-skia), no display, no system fonts (a built-in 5×7 bitmap font).
//!
//! It draws the `commonroad` model and knows nothing of OpenSCENARIO or OpenDRIVE. One display
//! list ([`scene`]) feeds every output format, so a PNG and an SVG show the same picture.
//!
//! ```no_run
//! # fn f(scenario: &commonroad::Scenario, problems: &commonroad::PlanningProblemSet) -> Result<(), render::RenderError> {
//! let options = render::RenderOptions { time: 5.5, ..Default::default() };
//! let png: Vec<u8> = render::render_png(scenario, Some(problems), &options)?;
//! # Ok(()) }
//! ```

mod animation;
mod ego;
mod error;
pub mod font;
mod options;
mod palette;
mod raster;
pub mod scene;
pub mod style;
mod svg;
pub mod timeline;
pub mod view;

use commonroad::{PlanningProblemSet, Scenario};

pub use ego::{find_ego, SAME_POSITION_M};
pub use error::RenderError;
pub use options::{RenderOptions, MAX_WIDTH, MIN_WIDTH};
pub use scene::{time_label, Prepared};

/// A still at `options.time` as PNG bytes.
pub fn render_png(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    options: &RenderOptions,
) -> Result<Vec<u8>, RenderError> {
    let prepared = Prepared::new(scenario, problems, options)?;
    png_at(&prepared, options.time)
}

/// Stills at several times (seconds), sharing one view: PNG bytes in the order of `times`.
pub fn render_pngs(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    options: &RenderOptions,
    times: &[f64],
) -> Result<Vec<Vec<u8>>, RenderError> {
    let prepared = Prepared::new(scenario, problems, options)?;
    times.iter().map(|&t| png_at(&prepared, t)).collect()
}

/// A still at `options.time` as RGBA pixels (straight alpha, row-major), with its size.
pub fn render_rgba(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    options: &RenderOptions,
) -> Result<(u32, u32, Vec<u8>), RenderError> {
    let prepared = Prepared::new(scenario, problems, options)?;
    let pm = pixmap_at(&prepared, options.time)?;
    Ok((pm.width(), pm.height(), pm.data().to_vec()))
}

/// A still at `options.time` as an SVG document.
pub fn render_svg(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    options: &RenderOptions,
) -> Result<String, RenderError> {
    let prepared = Prepared::new(scenario, problems, options)?;
    let step = checked_step(&prepared, options.time)?;
    Ok(svg::to_svg(&prepared.scene(step)))
}

/// An animated GIF over the whole scenario (`options.time` is not used).
pub fn render_gif(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    options: &RenderOptions,
) -> Result<Vec<u8>, RenderError> {
    let prepared = Prepared::new(scenario, problems, options)?;
    animation::animate(&prepared, options.gif_max_frames, options.gif_max_bytes)
}

/// Decodes PNG bytes into (width, height, straight RGBA pixels): for callers that check or
/// post-process a picture without a PNG crate of their own.
pub fn decode_png(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>), RenderError> {
    let pm = tiny_skia::Pixmap::decode_png(bytes).map_err(|e| RenderError::Encode {
        format: "PNG",
        message: e.to_string(),
    })?;
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

fn checked_step(prepared: &Prepared, time: f64) -> Result<u64, RenderError> {
    if !(time.is_finite() && time >= 0.0) {
        return Err(RenderError::Option(format!(
            "--time must be a finite number of seconds >= 0, got {time}"
        )));
    }
    Ok(timeline::step_of(time, prepared.scenario.header.time_step_size))
}

fn pixmap_at(prepared: &Prepared, time: f64) -> Result<tiny_skia::Pixmap, RenderError> {
    let step = checked_step(prepared, time)?;
    let mut pm = raster::canvas(prepared.view.width, prepared.view.height, style::BACKGROUND)?;
    raster::paint_prims(&mut pm, prepared.still());
    raster::paint_prims(&mut pm, &prepared.moving(step));
    Ok(pm)
}

fn png_at(prepared: &Prepared, time: f64) -> Result<Vec<u8>, RenderError> {
    pixmap_at(prepared, time)?
        .encode_png()
        .map_err(|e| RenderError::Encode {
            format: "PNG",
            message: e.to_string(),
        })
}
