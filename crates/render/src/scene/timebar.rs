//! The time bar under the map: the run from its first to its last step, a tick at each
//! storyboard event, the part already run darker and a knob at the picture's time — when the
//! events happen, at a glance.

use super::prim::{Prim, Stroke};
use crate::options::Mark;
use crate::style;
use crate::timeline::step_of;

/// Height of the bar's strip in a picture `width` wide.
pub(super) fn height(width: u32) -> f64 {
    7.0 * style::text_dot(width)
}

/// The bar with its strip's top at row `y`, for the picture at `step` of a run from `first`
/// to `last`.
#[allow(clippy::too_many_arguments)]
pub(super) fn bar(width: u32, y: f64, first: u64, last: u64, step: u64, dt: f64, marks: &[Mark], out: &mut Vec<Prim>) {
    let dot = style::text_dot(width);
    let h = height(width);
    let w = f64::from(width);
    super::header::strip(y, width, h, out);
    let (x0, x1) = (3.0 * dot, w - 3.0 * dot);
    let ym = y + 0.5 * h;
    let span = last.saturating_sub(first).max(1) as f64;
    let x_of = |k: u64| x0 + (x1 - x0) * (k.clamp(first, last) - first) as f64 / span;
    let line =
        |a: f64, b: f64, color, width| Prim::Path { points: vec![(a, ym), (b, ym)], closed: false, fill: None, stroke: Some(Stroke::solid(color, width)) };
    out.push(line(x0, x1, style::STRIP_LINE, dot));
    out.push(line(x0, x_of(step), style::MUTED, dot));
    for m in marks {
        let x = x_of(step_of(m.time, dt));
        out.push(Prim::Path {
            points: vec![(x - dot, ym - 2.5 * dot), (x + dot, ym - 2.5 * dot), (x + dot, ym + 2.5 * dot), (x - dot, ym + 2.5 * dot)],
            closed: true,
            fill: Some(style::MARK_NEW),
            stroke: Some(Stroke::solid(style::MUTED, 1.0)),
        });
    }
    out.push(Prim::Circle { center: (x_of(step), ym), radius: 2.0 * dot, fill: Some(style::TEXT), stroke: Some(Stroke::solid(style::STRIP, 1.0)) });
}
