//! The lanelet network: road surface, borders and markings, stop lines, signs and lights.

use std::collections::BTreeMap;

use commonroad::{LaneletNetwork, LineMarking, Point};

use super::geometry::{offset_polyline, to_px};
use super::prim::{Prim, Rgba, Stroke};
use crate::style;
use crate::timeline::light_color;
use crate::view::{Bounds, View};

fn pts(points: &[Point]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.x, p.y)).collect()
}

/// Whether any of the lanelet lies in the view (with 10 m to spare): the map is clipped to
/// the view, so a picture of a few cars on a large map does not carry the whole map.
fn visible(l: &commonroad::Lanelet, view: &View) -> bool {
    let mut b = Bounds::empty();
    l.bounds.left().iter().chain(l.bounds.right()).for_each(|p| b.add(p.x, p.y, 0.0));
    let mut w = view.world();
    w.min_x -= 10.0;
    w.min_y -= 10.0;
    w.max_x += 10.0;
    w.max_y += 10.0;
    b.is_valid() && b.intersects(&w)
}

fn path(points: Vec<(f64, f64)>, stroke: Stroke) -> Prim {
    Prim::Path { points, closed: false, fill: None, stroke: Some(stroke) }
}

/// Road surface of every lanelet. The fill is also stroked in the road colour so that
/// anti-aliased seams between neighbouring lanelets do not show the background.
pub(super) fn surfaces(net: &LaneletNetwork, view: &View, out: &mut Vec<Prim>) {
    for l in net.lanelets.iter().filter(|l| visible(l, view)) {
        let mut outline = pts(l.bounds.left());
        outline.extend(pts(l.bounds.right()).into_iter().rev());
        out.push(Prim::Path { points: to_px(view, &outline), closed: true, fill: Some(style::ROAD), stroke: Some(Stroke::solid(style::ROAD, 1.0)) });
    }
}

fn dash(view: &View) -> (f64, f64) {
    ((style::DASH_M.0 * view.scale).max(style::MIN_DASH_PX), (style::DASH_M.1 * view.scale).max(style::MIN_DASH_PX))
}

/// The lines one bound's marking draws (two for double markings).
fn marking_lines(line: &[(f64, f64)], m: LineMarking, view: &View, out: &mut Vec<Prim>) {
    let (on, off) = dash(view);
    let w = style::MARKING_WIDTH;
    let solid = |w| Stroke::solid(style::MARKING, w);
    let dashed = |w| Stroke::dashed(style::MARKING, w, on, off);
    let single = |s: Stroke, out: &mut Vec<Prim>| out.push(path(line.to_vec(), s));
    let double = |a: Stroke, b: Stroke, out: &mut Vec<Prim>| {
        let gap = 0.5 * w + 0.75;
        out.push(path(offset_polyline(line, gap), a));
        out.push(path(offset_polyline(line, -gap), b));
    };
    match m {
        LineMarking::Solid => single(solid(w), out),
        LineMarking::BroadSolid => single(solid(2.0 * w), out),
        LineMarking::Dashed => single(dashed(w), out),
        LineMarking::BroadDashed => single(dashed(2.0 * w), out),
        LineMarking::SolidSolid => double(solid(w), solid(w), out),
        LineMarking::DashedDashed => double(dashed(w), dashed(w), out),
        LineMarking::SolidDashed => double(solid(w), dashed(w), out),
        LineMarking::DashedSolid => double(dashed(w), solid(w), out),
        LineMarking::Curb => single(Stroke::solid(style::CURB, 2.0), out),
        LineMarking::LoweredCurb => single(Stroke::dashed(style::CURB, 2.0, on, off), out),
        LineMarking::Unknown | LineMarking::NoMarking => {}
    }
}

/// Thin borders of every lanelet first, then the markings on top (neighbours share bounds).
pub(super) fn borders_and_markings(net: &LaneletNetwork, view: &View, out: &mut Vec<Prim>) {
    let border = Stroke::solid(style::BORDER, style::BORDER_WIDTH);
    let shown: Vec<&commonroad::Lanelet> = net.lanelets.iter().filter(|l| visible(l, view)).collect();
    for l in &shown {
        out.push(path(to_px(view, &pts(l.bounds.left())), border));
        out.push(path(to_px(view, &pts(l.bounds.right())), border));
    }
    for l in &shown {
        for (points, marking) in [(l.bounds.left(), l.left_marking), (l.bounds.right(), l.right_marking)] {
            if let Some(m) = marking {
                marking_lines(&to_px(view, &pts(points)), m, view, out);
            }
        }
        if let Some(stop) = &l.stop_line {
            let ends = match &stop.points {
                Some([a, b]) => Some((*a, *b)),
                None => l.bounds.left().last().zip(l.bounds.right().last()).map(|(a, b)| (*a, *b)),
            };
            if let Some((a, b)) = ends {
                let w = (0.4 * view.scale).max(2.0);
                out.push(path(to_px(view, &[(a.x, a.y), (b.x, b.y)]), Stroke::solid(style::STOP_LINE, w)));
            }
        }
    }
}

/// Where signs and lights without a position stand: the readers put a sign at the start of
/// its first lanelet's right bound; a light is drawn at the end (where its stop line is).
fn positions(net: &LaneletNetwork) -> (BTreeMap<u64, Point>, BTreeMap<u64, Point>) {
    let mut signs = BTreeMap::new();
    let mut lights = BTreeMap::new();
    for l in &net.lanelets {
        for s in &l.traffic_sign_refs {
            if let Some(p) = l.bounds.right().first() {
                signs.entry(s.get()).or_insert(*p);
            }
        }
        for t in &l.traffic_light_refs {
            if let Some(p) = l.bounds.right().last() {
                lights.entry(t.get()).or_insert(*p);
            }
        }
    }
    (signs, lights)
}

/// Traffic signs as small red-rimmed discs.
pub(super) fn signs(net: &LaneletNetwork, view: &View, out: &mut Vec<Prim>) {
    let (fallback, _) = positions(net);
    for s in &net.traffic_signs {
        if let Some(p) = s.position.or_else(|| fallback.get(&s.id.get()).copied()) {
            out.push(Prim::Circle {
                center: view.px(p.x, p.y),
                radius: 4.5,
                fill: Some(Rgba::rgb(255, 255, 255)),
                stroke: Some(Stroke::solid(style::SIGN, 2.0)),
            });
        }
    }
}

/// Traffic lights as discs in the colour they show at `step`.
pub(super) fn lights(net: &LaneletNetwork, view: &View, step: u64, out: &mut Vec<Prim>) {
    let (_, fallback) = positions(net);
    for t in &net.traffic_lights {
        if let Some(p) = t.position.or_else(|| fallback.get(&t.id.get()).copied()) {
            out.push(Prim::Circle {
                center: view.px(p.x, p.y),
                radius: 5.0,
                fill: Some(style::light_color(light_color(t, step))),
                stroke: Some(Stroke::solid(style::OUTLINE, 1.5)),
            });
        }
    }
}
