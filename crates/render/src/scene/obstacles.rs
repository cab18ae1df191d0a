//! Obstacles: static and environment obstacles (still), dynamic obstacles at a time step,
//! their paths, and the ego.

use commonroad::{DynamicObstacle, ObstacleId, Scenario, Shape};

use crate::layout::PxRect;

use super::geometry::{local_to_world, place, place_absolute, to_px, Placed};
use super::prim::{Prim, Rgba, Stroke};
use crate::style;
use crate::timeline::state_at;
use crate::view::View;

/// Obstacles smaller than this on the picture also get a marker disc of this radius, so a
/// pedestrian on a large map is still visible.
pub(super) const MIN_MARKER_PX: f64 = 3.0;

fn placed_prim(view: &View, shape: &Placed, fill: Rgba, stroke: Stroke) -> Prim {
    match shape {
        Placed::Polygon(p) => Prim::Path { points: to_px(view, p), closed: true, fill: Some(fill), stroke: Some(stroke) },
        Placed::Circle((x, y), r) => Prim::Circle { center: view.px(*x, *y), radius: r * view.scale, fill: Some(fill), stroke: Some(stroke) },
    }
}

fn marker_if_tiny(view: &View, shape: &Shape, x: f64, y: f64, fill: Rgba, out: &mut Vec<Prim>) {
    let extent = match shape {
        Shape::Rectangle(r) => r.length().max(r.width()),
        Shape::Circle(c) => 2.0 * c.radius(),
        Shape::Polygon(p) => p.points().iter().map(|q| 2.0 * q.x.hypot(q.y)).fold(0.0, f64::max),
    };
    if extent * view.scale < 2.0 * MIN_MARKER_PX {
        out.push(Prim::Circle { center: view.px(x, y), radius: MIN_MARKER_PX, fill: Some(fill), stroke: Some(Stroke::solid(style::OUTLINE, 0.75)) });
    }
}

/// Environment obstacles, then static obstacles.
pub(super) fn still_obstacles(scenario: &Scenario, view: &View, out: &mut Vec<Prim>) {
    let outline = Stroke::solid(style::OUTLINE, style::OUTLINE_WIDTH);
    for o in &scenario.environment_obstacles {
        let c = style::environment_color(o.obstacle_type);
        out.push(placed_prim(view, &place_absolute(&o.shape), c, outline));
    }
    for o in &scenario.static_obstacles {
        let c = style::static_color(o.obstacle_type);
        out.push(placed_prim(view, &place(&o.shape, o.x, o.y, o.orientation), c, outline));
        marker_if_tiny(view, &o.shape, o.x, o.y, c, out);
    }
}

/// Each dynamic obstacle's path over the whole scenario, faint (the ego's stronger), so a still
/// shows where everyone goes.
pub(super) fn paths(scenario: &Scenario, ego: Option<ObstacleId>, view: &View, out: &mut Vec<Prim>) {
    for o in &scenario.dynamic_obstacles {
        let line: Vec<(f64, f64)> = std::iter::once(&o.initial_state).chain(&o.trajectory).map(|s| view.px(s.x, s.y)).collect();
        if line.len() < 2 {
            continue;
        }
        let stroke = if Some(o.id) == ego {
            Stroke::dashed(style::EGO.with_alpha(style::EGO_PATH_ALPHA), style::EGO_PATH_WIDTH, style::EGO_PATH_DASH.0, style::EGO_PATH_DASH.1)
        } else {
            Stroke::solid(style::dynamic_color(o.obstacle_type).with_alpha(90), 1.0)
        };
        out.push(Prim::Path { points: line, closed: false, fill: None, stroke: Some(stroke) });
    }
}

/// The smaller side of an obstacle shape, m.
fn minor_extent(shape: &Shape) -> f64 {
    match shape {
        Shape::Rectangle(r) => r.length().min(r.width()),
        Shape::Circle(c) => 2.0 * c.radius(),
        Shape::Polygon(p) => p.points().iter().map(|q| 2.0 * q.x.hypot(q.y)).fold(0.0, f64::max),
    }
}

/// A light wedge in the front half of a box, pointing along the heading.
fn heading_wedge(o: &DynamicObstacle, x: f64, y: f64, h: f64, view: &View) -> Option<Prim> {
    let Shape::Rectangle(r) = &o.shape else {
        return None;
    };
    let (l, w) = (r.length(), r.width());
    let tri = [local_to_world(x, y, h, 0.45 * l, 0.0), local_to_world(x, y, h, 0.2 * l, 0.3 * w), local_to_world(x, y, h, 0.2 * l, -0.3 * w)];
    Some(Prim::Path { points: to_px(view, &tri), closed: true, fill: Some(Rgba::rgb(255, 255, 255).with_alpha(170)), stroke: None })
}

/// A road user as drawn (before its label is placed).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Shown {
    pub id: ObstacleId,
    pub ego: bool,
    pub obstacle_type: &'static str,
    pub length_px: f64,
    pub bbox: PxRect,
    pub center: (f64, f64),
}

/// The length of an obstacle shape (a box's length, a circle's diameter), m.
fn length(shape: &Shape) -> f64 {
    match shape {
        Shape::Rectangle(r) => r.length(),
        Shape::Circle(c) => 2.0 * c.radius(),
        Shape::Polygon(p) => p.points().iter().map(|q| 2.0 * q.x.hypot(q.y)).fold(0.0, f64::max),
    }
}

/// Dynamic obstacles at `step` (those that exist then); the ego last, on top, with a thick
/// outline. Returns where each was drawn.
pub(super) fn dynamic_at(scenario: &Scenario, ego: Option<ObstacleId>, step: u64, view: &View, out: &mut Vec<Prim>) -> Vec<Shown> {
    let mut shown = Vec::new();
    let others = scenario.dynamic_obstacles.iter().filter(|o| Some(o.id) != ego);
    let ego_obstacle = scenario.dynamic_obstacles.iter().filter(|o| Some(o.id) == ego);
    for o in others.chain(ego_obstacle) {
        let Some(s) = state_at(o, step) else { continue };
        let is_ego = Some(o.id) == ego;
        let (fill, width) = if is_ego { (style::EGO, style::EGO_OUTLINE_WIDTH) } else { (style::dynamic_color(o.obstacle_type), style::OUTLINE_WIDTH) };
        // a small obstacle would be all outline: keep most of it its fill colour
        let stroke = Stroke::solid(style::OUTLINE, width.min(0.15 * minor_extent(&o.shape) * view.scale));
        let placed = place(&o.shape, s.x, s.y, s.orientation);
        let bbox = match &placed {
            Placed::Polygon(p) => PxRect::around(&to_px(view, p)),
            Placed::Circle((x, y), r) => {
                let (cx, cy) = view.px(*x, *y);
                let rp = r * view.scale;
                PxRect { x0: cx - rp, y0: cy - rp, x1: cx + rp, y1: cy + rp }
            }
        };
        out.push(placed_prim(view, &placed, fill, stroke));
        out.extend(heading_wedge(o, s.x, s.y, s.orientation, view));
        marker_if_tiny(view, &o.shape, s.x, s.y, fill, out);
        shown.push(Shown {
            id: o.id,
            ego: is_ego,
            obstacle_type: o.obstacle_type.as_str(),
            length_px: length(&o.shape) * view.scale,
            bbox,
            center: view.px(s.x, s.y),
        });
    }
    shown
}
