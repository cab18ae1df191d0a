//! Builds the display list of a scenario: the still layer once, the moving layer per step.

pub mod geometry;
mod goal;
mod network;
mod obstacles;
pub mod prim;

use commonroad::{ObstacleId, PlanningProblemSet, Scenario};

use crate::ego::find_ego;
use crate::error::RenderError;
use crate::options::RenderOptions;
use crate::style;
use crate::view::{content_bounds, View};
use prim::{Prim, Scene};

/// A scenario prepared for drawing at any time step.
pub struct Prepared<'a> {
    pub scenario: &'a Scenario,
    pub view: View,
    pub ego: Option<ObstacleId>,
    still: Vec<Prim>,
}

impl<'a> Prepared<'a> {
    /// Fits the view, finds the ego and draws everything that does not move.
    pub fn new(
        scenario: &'a Scenario,
        problems: Option<&PlanningProblemSet>,
        options: &RenderOptions,
    ) -> Result<Self, RenderError> {
        options.check()?;
        let view = View::fit(content_bounds(scenario, problems), options.width)?;
        let ego = find_ego(scenario, problems, options.ego)?;
        let net = &scenario.network;
        let mut still = Vec::new();
        network::surfaces(net, &view, &mut still);
        if let Some(p) = problems {
            goal::goals(p, net, &view, &mut still);
        }
        network::borders_and_markings(net, &view, &mut still);
        obstacles::still_obstacles(scenario, &view, &mut still);
        network::signs(net, &view, &mut still);
        obstacles::paths(scenario, ego, &view, &mut still);
        if let (Some(p), None) = (problems, ego) {
            goal::initial_states(p, &view, &mut still);
        }
        Ok(Self {
            scenario,
            view,
            ego,
            still,
        })
    }

    /// What moves, at `step`: lights, dynamic obstacles, the time stamp (none for a bare map).
    pub fn moving(&self, step: u64) -> Vec<Prim> {
        let mut out = Vec::new();
        network::lights(&self.scenario.network, &self.view, step, &mut out);
        obstacles::dynamic_at(self.scenario, self.ego, step, &self.view, &mut out);
        // a map has no time: no stamp
        if self.scenario.dynamic_obstacles.is_empty() && self.scenario.network.traffic_lights.is_empty() {
            return out;
        }
        let size = (f64::from(self.view.width) / 60.0).clamp(10.0, 40.0);
        out.push(Prim::Text {
            x: 0.5 * size,
            y: 0.5 * size,
            size,
            color: style::TEXT,
            background: Some(style::TEXT_BACKGROUND),
            text: time_label(step, self.scenario.header.time_step_size),
        });
        out
    }

    /// The still layer.
    pub fn still(&self) -> &[Prim] {
        &self.still
    }

    /// The whole picture at `step`.
    pub fn scene(&self, step: u64) -> Scene {
        Scene {
            width: self.view.width,
            height: self.view.height,
            background: style::BACKGROUND,
            still: self.still.clone(),
            moving: self.moving(step),
        }
    }
}

/// Decimals that show every multiple of `dt` exactly (at most 3).
pub fn time_decimals(dt: f64) -> usize {
    (1..=3)
        .find(|&d| {
            let v = dt * 10f64.powi(d as i32);
            (v - v.round()).abs() < 1e-6
        })
        .unwrap_or(3)
}

/// `t = 5.5 s`.
pub fn time_label(step: u64, dt: f64) -> String {
    format!("t = {:.*} s", time_decimals(dt), step as f64 * dt)
}
