//! The sheet: one picture with a panel per storyboard event time — the start, each time a
//! mark happens, the end — each panel a still framed at its time, the legend once below.

use commonroad::{PlanningProblemSet, Scenario};
use tiny_skia::{Pixmap, PixmapPaint, Transform};

use crate::error::Error;
use crate::frame::Purpose;
use crate::options::RenderOptions;
use crate::raster::{canvas, paint_prims};
use crate::scene::prim::Prim;
use crate::scene::{footer, Prepared};
use crate::style;
use crate::timeline::{first_step, last_step, step_of};

/// Most panels of a sheet (the start, the end and the first marks' times between).
pub const MAX_PANELS: usize = 12;
/// Height / width of each panel's map area.
const PANEL_ASPECT: f64 = 0.6;
/// Space between panels, pixels.
const GAP: u32 = 6;

/// The distinct steps of the marks strictly between the first and the last step.
fn mark_steps(scenario: &Scenario, marks: &[crate::options::Mark]) -> Vec<u64> {
    let dt = scenario.header.time_step_size;
    let (first, last) = (first_step(scenario), last_step(scenario));
    let mut steps: Vec<u64> = marks.iter().map(|m| step_of(m.time, dt)).filter(|s| (first..=last).contains(s)).collect();
    steps.sort_unstable();
    steps.dedup();
    steps.retain(|&s| s != first && s != last);
    steps
}

/// The time steps of the panels: the first step, each step a mark happens at (in time order,
/// within the scenario), the last step; at most [`MAX_PANELS`].
pub fn sheet_times(scenario: &Scenario, marks: &[crate::options::Mark]) -> Vec<u64> {
    let (first, last) = (first_step(scenario), last_step(scenario));
    let mut steps = mark_steps(scenario, marks);
    steps.truncate(MAX_PANELS - 2);
    let mut out = vec![first];
    out.extend(steps);
    if last != first {
        out.push(last);
    }
    out
}

/// The sheet as PNG bytes, `options.width` wide: panels in up to 3 columns.
pub fn render_sheet_png(scenario: &Scenario, problems: Option<&PlanningProblemSet>, options: &RenderOptions) -> Result<Vec<u8>, Error> {
    options.check()?;
    let steps = sheet_times(scenario, &options.marks);
    let n = steps.len() as u32;
    let cols = match n {
        0 | 1 => 1,
        2 | 4 => 2,
        _ => 3,
    };
    let rows = n.div_ceil(cols);
    let panel_w = (options.width.saturating_sub((cols + 1) * GAP) / cols).max(crate::MIN_WIDTH);
    let panel_options = RenderOptions { width: panel_w, ..options.clone() };
    let trail_steps = step_of(options.trail, scenario.header.time_step_size);
    let ego = crate::find_ego(scenario, problems, options.ego)?;
    let mut panels: Vec<Pixmap> = Vec::new();
    for &step in &steps {
        let p = Prepared::new(scenario, problems, &panel_options, Purpose::Panel { step, trail_steps, ego }, Some(PANEL_ASPECT), false)?;
        let mut pm = canvas(p.width, p.height, style::BACKGROUND)?;
        paint_prims(&mut pm, &p.base(step));
        paint_prims(&mut pm, &p.moving(step));
        panels.push(pm);
    }
    let panel_h = panels.iter().map(Pixmap::height).max().unwrap_or(1);
    let width = cols * panel_w + (cols + 1) * GAP;
    let legend = footer::entries(scenario, problems, ego, trail_steps > 0);
    let legend_h = footer::height(width, &legend, false).round() as u32;
    let height = rows * panel_h + (rows + 1) * GAP + legend_h;
    let mut sheet = canvas(width, height, style::STRIP_LINE)?;
    for (i, pm) in panels.iter().enumerate() {
        let (c, r) = (i as u32 % cols, i as u32 / cols);
        let x = GAP + c * (panel_w + GAP);
        let y = GAP + r * (panel_h + GAP);
        sheet.draw_pixmap(x as i32, y as i32, pm.as_ref(), &PixmapPaint::default(), Transform::identity(), None);
    }
    let mut legend_prims = Vec::new();
    footer::footer(None, width, f64::from(height - legend_h), &legend, &mut legend_prims);
    let left_out = mark_steps(scenario, &options.marks).len().saturating_sub(MAX_PANELS - 2);
    if left_out > 0 {
        // say so at the right end of the legend strip
        let size = style::text_size(width);
        let text = format!("+{left_out} later event times not shown");
        let (w, _) = crate::font::text_box(&text, size);
        let pad = 3.0 * style::text_dot(width);
        legend_prims.push(Prim::Text {
            x: f64::from(width) - w - pad,
            y: f64::from(height - legend_h) + pad,
            size,
            color: style::MUTED,
            background: None,
            text,
        });
    }
    paint_prims(&mut sheet, &legend_prims);
    sheet.encode_png().map_err(|e| Error::Encode { format: "PNG", message: e.to_string() })
}
