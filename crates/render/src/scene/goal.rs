//! Planning problems: goal regions outlined (shapes or lanelets) and, when no obstacle is the
//! ego, the initial state as an arrow.

use commonroad::{AbsoluteShape, GoalPosition, LaneletNetwork, PlanningProblemSet};

use super::geometry::{local_to_world, place_absolute, to_px, Placed};
use super::prim::{Prim, Stroke};
use crate::style;
use crate::view::View;

fn goal_prim(view: &View, shape: Placed) -> Prim {
    let stroke = Some(Stroke::dashed(style::GOAL, 2.0, 8.0, 4.0));
    match shape {
        Placed::Polygon(p) => Prim::Path { points: to_px(view, &p), closed: true, fill: Some(style::GOAL_FILL), stroke },
        Placed::Circle((x, y), r) => Prim::Circle { center: view.px(x, y), radius: r * view.scale, fill: Some(style::GOAL_FILL), stroke },
    }
}

/// Every goal position of every planning problem.
pub(super) fn goals(problems: &PlanningProblemSet, net: &LaneletNetwork, view: &View, out: &mut Vec<Prim>) {
    for g in problems.problems.iter().flat_map(|p| &p.goal_states) {
        let shapes: Vec<Placed> = match &g.position {
            Some(GoalPosition::Rectangles(rs)) => rs.iter().map(|r| place_absolute(&AbsoluteShape::Rectangle(*r))).collect(),
            Some(GoalPosition::Circles(cs)) => cs.iter().map(|c| place_absolute(&AbsoluteShape::Circle(*c))).collect(),
            Some(GoalPosition::Polygons(ps)) => ps.iter().map(|p| place_absolute(&AbsoluteShape::Polygon(p.clone()))).collect(),
            Some(GoalPosition::Lanelets(ids)) => ids
                .iter()
                .filter_map(|id| net.lanelets.iter().find(|l| l.id == *id))
                .map(|l| {
                    let mut outline: Vec<(f64, f64)> = l.bounds.left().iter().map(|p| (p.x, p.y)).collect();
                    outline.extend(l.bounds.right().iter().rev().map(|p| (p.x, p.y)));
                    Placed::Polygon(outline)
                })
                .collect(),
            None => Vec::new(),
        };
        out.extend(shapes.into_iter().map(|s| goal_prim(view, s)));
    }
}

/// An arrow (4 m long, at least 12 px) at each planning problem's initial state.
pub(super) fn initial_states(problems: &PlanningProblemSet, view: &View, out: &mut Vec<Prim>) {
    let len = (4.0_f64).max(12.0 / view.scale);
    for p in &problems.problems {
        let s = &p.initial_state;
        let tri = [
            local_to_world(s.x, s.y, s.orientation, 0.5 * len, 0.0),
            local_to_world(s.x, s.y, s.orientation, -0.5 * len, 0.3 * len),
            local_to_world(s.x, s.y, s.orientation, -0.5 * len, -0.3 * len),
        ];
        out.push(Prim::Path { points: to_px(view, &tri), closed: true, fill: Some(style::EGO.with_alpha(120)), stroke: Some(Stroke::solid(style::EGO, 2.0)) });
    }
}
