//! The footer strip: a scale bar and the legend (the ego, each obstacle type shown, the goal
//! region, and the lines drawn over the map: the ego's dashed path, the trails with a dot per
//! second), wrapped onto as many lines as the width needs.

use commonroad::{ObstacleId, PlanningProblemSet, Scenario};

use super::header::strip;
use super::prim::{Prim, Rgba, Stroke};
use crate::font;
use crate::style;
use crate::view::View;

/// One legend entry: a swatch and its name.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    pub name: String,
    pub swatch: Swatch,
}

/// What a legend entry shows before its name.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// A filled square, as the obstacles and the goal region are drawn.
    Box { fill: Rgba, stroke: Rgba },
    /// A dashed line, as the ego's path is drawn.
    Dashed(Rgba),
    /// A line with dots, as a trail is drawn (a dot per second back).
    Dots(Rgba),
}

/// The entries for a scenario: the ego, the types of the other dynamic, static and
/// environment obstacles (each once, in the order of the type lists), the goal region; then
/// the ego's path (dashed over the whole run) and, with `trails`, the trails.
pub fn entries(scenario: &Scenario, problems: Option<&PlanningProblemSet>, ego: Option<ObstacleId>, trails: bool) -> Vec<Entry> {
    use commonroad::{DynamicObstacleType as D, EnvironmentObstacleType as E, StaticObstacleType as S};
    let entry = |name: &str, fill: Rgba| Entry { name: name.to_string(), swatch: Swatch::Box { fill, stroke: style::OUTLINE } };
    let mut out = Vec::new();
    if ego.is_some() {
        out.push(entry("ego", style::EGO));
    }
    for t in D::ALL {
        if scenario.dynamic_obstacles.iter().any(|o| o.obstacle_type == *t && Some(o.id) != ego) {
            out.push(entry(t.as_str(), style::dynamic_color(*t)));
        }
    }
    for t in S::ALL {
        if scenario.static_obstacles.iter().any(|o| o.obstacle_type == *t) {
            out.push(entry(t.as_str(), style::static_color(*t)));
        }
    }
    for t in E::ALL {
        if scenario.environment_obstacles.iter().any(|o| o.obstacle_type == *t) {
            out.push(entry(t.as_str(), style::environment_color(*t)));
        }
    }
    let goal = problems.iter().flat_map(|p| &p.problems).flat_map(|p| &p.goal_states).any(|g| g.position.is_some());
    if goal {
        out.push(Entry { name: "goal".into(), swatch: Swatch::Box { fill: style::GOAL_FILL, stroke: style::GOAL } });
    }
    // what obstacles::paths and trails::trails draw
    let ego_path = ego.and_then(|id| scenario.dynamic_obstacles.iter().find(|o| o.id == id)).is_some_and(|o| !o.trajectory.is_empty());
    if ego_path {
        out.push(Entry { name: "ego path".into(), swatch: Swatch::Dashed(style::EGO) });
    }
    if trails && !scenario.dynamic_obstacles.is_empty() {
        out.push(Entry { name: "trail, a dot per s".into(), swatch: Swatch::Dots(style::MUTED) });
    }
    out
}

/// Width of an entry's swatch, for a text `size` high: a square, or a line long enough to show
/// its dashes or dots.
fn swatch_width(swatch: &Swatch, size: f64) -> f64 {
    match swatch {
        Swatch::Box { .. } => size,
        Swatch::Dashed(_) | Swatch::Dots(_) => 2.5 * size,
    }
}

/// Width reserved for the scale bar and its text, in font dots.
const SCALE_DOTS: f64 = 90.0;
const PAD_DOTS: f64 = 3.0;

/// Each entry's (x, line) and the number of lines, for a footer `width` wide (after the scale
/// bar if `scale`).
fn arrange(width: u32, entries: &[Entry], scale: bool) -> (Vec<(f64, usize)>, usize) {
    let dot = style::text_dot(width);
    let size = style::text_size(width);
    let pad = PAD_DOTS * dot;
    let right = f64::from(width) - pad;
    let mut x = pad + if scale { SCALE_DOTS * dot } else { 0.0 };
    let mut line = 0;
    let mut at = Vec::new();
    for e in entries {
        let w = swatch_width(&e.swatch, size) + dot * 2.0 + font::text_box(&e.name, size).0;
        if x + w > right && x > pad {
            line += 1;
            x = pad;
        }
        at.push((x, line));
        x += w + 2.0 * pad;
    }
    (at, line + 1)
}

fn line_height(width: u32) -> f64 {
    font::text_box("m", style::text_size(width)).1 + PAD_DOTS * style::text_dot(width)
}

/// Height of the footer of a picture `width` wide with these entries (and a scale bar if
/// `scale`).
pub fn height(width: u32, entries: &[Entry], scale: bool) -> f64 {
    let (_, lines) = arrange(width, entries, scale);
    lines as f64 * line_height(width) + PAD_DOTS * style::text_dot(width)
}

/// The longest of 1, 2, 5 × 10^k m that is at most `max_px` long at `scale` px/m.
pub fn scale_length(scale: f64, max_px: f64) -> f64 {
    let mut best = 0.001;
    let mut k = -3;
    while k <= 6 {
        for m in [1.0, 2.0, 5.0] {
            let l = m * 10f64.powi(k);
            if l * scale <= max_px {
                best = l;
            }
        }
        k += 1;
    }
    best
}

fn metres(l: f64) -> String {
    if l >= 1000.0 {
        format!("{} km", l / 1000.0)
    } else if l >= 1.0 {
        format!("{l:.0} m")
    } else {
        format!("{} m", l)
    }
}

/// The footer `width` wide with its top at row `y`: the scale bar of `view` (if given), then
/// the legend.
pub fn footer(view: Option<&View>, width: u32, y: f64, entries: &[Entry], out: &mut Vec<Prim>) {
    let h = height(width, entries, view.is_some());
    strip(y, width, h, out);
    out.push(Prim::Path {
        points: vec![(0.0, y + 0.5), (f64::from(width), y + 0.5)],
        closed: false,
        fill: None,
        stroke: Some(Stroke::solid(style::STRIP_LINE, 1.0)),
    });
    let dot = style::text_dot(width);
    let size = style::text_size(width);
    let pad = PAD_DOTS * dot;
    let text_h = font::text_box("m", size).1;
    let lh = line_height(width);

    if let Some(view) = view {
        scale_bar(view.scale, width, pad + dot, y + pad, out);
    }
    let (at, _) = arrange(width, entries, view.is_some());
    for (e, (x, line)) in entries.iter().zip(at) {
        let top = y + pad + line as f64 * lh;
        let s = size;
        let sy = top + 0.5 * (text_h - s);
        let sw = swatch_width(&e.swatch, s);
        swatch(&e.swatch, x, sy, sw, s, out);
        out.push(Prim::Text { x: x + sw + 0.5 * dot, y: top, size, color: style::TEXT, background: None, text: e.name.clone() });
    }
}

/// A swatch `w` × `s` pixels with its top-left at (x, y).
fn swatch(kind: &Swatch, x: f64, y: f64, w: f64, s: f64, out: &mut Vec<Prim>) {
    let ym = y + 0.5 * s;
    match *kind {
        Swatch::Box { fill, stroke } => out.push(Prim::Path {
            points: vec![(x, y), (x + w, y), (x + w, y + s), (x, y + s)],
            closed: true,
            fill: Some(fill),
            stroke: Some(Stroke::solid(stroke, 1.0)),
        }),
        Swatch::Dashed(color) => {
            let (on, off) = style::EGO_PATH_DASH;
            let stroke = Stroke::dashed(color.with_alpha(style::EGO_PATH_ALPHA), style::EGO_PATH_WIDTH, on, off);
            out.push(Prim::Path { points: vec![(x, ym), (x + w, ym)], closed: false, fill: None, stroke: Some(stroke) });
        }
        Swatch::Dots(color) => {
            let width = 0.3 * s;
            out.push(Prim::Path { points: vec![(x, ym), (x + w, ym)], closed: false, fill: None, stroke: Some(Stroke::solid(color.with_alpha(120), width)) });
            for cx in [x + 0.25 * w, x + 0.75 * w] {
                out.push(Prim::Circle { center: (cx, ym), radius: 0.8 * width, fill: Some(color), stroke: Some(Stroke::solid(style::STRIP, 1.0)) });
            }
        }
    }
}

/// A bar with end ticks and its length after it, the text's top-left at (x0, y) in a
/// picture `width` wide — the bar is 1, 2 or 5 × 10^k m at `scale` px/m, at most 50 font dots.
fn scale_bar(scale: f64, width: u32, x0: f64, y: f64, out: &mut Vec<Prim>) {
    let dot = style::text_dot(width);
    let size = style::text_size(width);
    let text_h = font::text_box("m", size).1;
    let l = scale_length(scale, 50.0 * dot);
    let bar = l * scale;
    let ym = y + 0.5 * text_h;
    let tick = 0.35 * text_h;
    out.push(Prim::Path {
        points: vec![(x0, ym - tick), (x0, ym + tick), (x0, ym), (x0 + bar, ym), (x0 + bar, ym - tick), (x0 + bar, ym + tick)],
        closed: false,
        fill: None,
        stroke: Some(Stroke::solid(style::TEXT, dot)),
    });
    out.push(Prim::Text { x: x0 + bar + 2.0 * dot, y, size, color: style::TEXT, background: None, text: metres(l) });
}
