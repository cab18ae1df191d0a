//! Trails: each road user's centre over the last seconds before the picture's time, fading
//! with age, with a dot at each whole second back.

use commonroad::{ObstacleId, Scenario};

use super::prim::{Prim, Stroke};
use crate::style;
use crate::timeline::state_at;
use crate::view::View;

/// The trails at `step`, `steps` long, of the road users that exist then.
pub(super) fn trails(scenario: &Scenario, ego: Option<ObstacleId>, step: u64, steps: u64, view: &View, out: &mut Vec<Prim>) {
    if steps == 0 {
        return;
    }
    let dt = scenario.header.time_step_size;
    let per_second = (1.0 / dt).round().max(1.0) as u64;
    let width = (0.5 * view.scale).clamp(2.0, 6.0);
    for o in &scenario.dynamic_obstacles {
        if state_at(o, step).is_none() {
            continue;
        }
        let color = if Some(o.id) == ego { style::EGO } else { style::dynamic_color(o.obstacle_type) };
        let from = step.saturating_sub(steps);
        let pts: Vec<(u64, (f64, f64))> = (from..=step).filter_map(|k| state_at(o, k).map(|s| (k, view.px(s.x, s.y)))).collect();
        for pair in pts.windows(2) {
            let [(k0, a), (_, b)] = [pair[0], pair[1]];
            let age = (step - k0) as f64 / steps as f64;
            let alpha = (200.0 * (1.0 - age)).clamp(30.0, 200.0) as u8;
            out.push(Prim::Path { points: vec![a, b], closed: false, fill: None, stroke: Some(Stroke::solid(color.with_alpha(alpha), width)) });
        }
        for &(k, p) in &pts {
            if k != step && (step - k).is_multiple_of(per_second) {
                out.push(Prim::Circle { center: p, radius: 0.8 * width, fill: Some(color), stroke: Some(Stroke::solid(style::STRIP, 1.0)) });
            }
        }
    }
}
