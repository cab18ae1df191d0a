//! Builds the display list of a scenario: the still layer (the map) once per view, the moving
//! layer (road users, their trails and labels, the header and footer strips) per step.

pub mod footer;
pub mod geometry;
mod goal;
pub mod header;
mod labels;
mod network;
mod obstacles;
pub mod prim;
mod timebar;
mod trails;

use std::borrow::Cow;
use std::collections::BTreeMap;

use commonroad::{ObstacleId, PlanningProblemSet, Scenario};

use crate::ego::find_ego;
use crate::error::Error;
use crate::frame::{plan, Purpose, ViewPlan};
use crate::layout::{DrawnObstacle, Label, Layout, PxRect};
use crate::options::{Mark, RenderOptions};
use crate::style;
use crate::timeline::{first_step, last_step, step_of};
use crate::view::View;
use prim::{Prim, Scene};

/// A scenario prepared for drawing at any time step.
pub struct Prepared<'a> {
    pub scenario: &'a Scenario,
    problems: Option<&'a PlanningProblemSet>,
    pub plan: ViewPlan,
    pub ego: Option<ObstacleId>,
    /// Picture size, pixels.
    pub width: u32,
    pub height: u32,
    /// Whether the picture has a header (time, events): not for a bare map.
    timed: bool,
    /// Whether a time bar runs under the map (a timed picture with marks).
    time_bar: bool,
    legend: Vec<footer::Entry>,
    /// The map layer of a fixed view.
    still: Option<Vec<Prim>>,
    names: BTreeMap<u64, String>,
    marks: Vec<Mark>,
    trail_steps: u64,
}

impl<'a> Prepared<'a> {
    /// Prepared for `purpose`; `aspect` fixes the map area's height / width (sheet panels);
    /// `legend`: whether the footer lists the obstacle types (its scale bar is always drawn).
    pub fn new(
        scenario: &'a Scenario,
        problems: Option<&'a PlanningProblemSet>,
        options: &RenderOptions,
        purpose: Purpose,
        aspect: Option<f64>,
        legend: bool,
    ) -> Result<Self, Error> {
        options.check()?;
        let ego = find_ego(scenario, problems, options.ego)?;
        let timed = !(scenario.dynamic_obstacles.is_empty() && scenario.network.traffic_lights.is_empty());
        let header_h = if timed { header::height(options.width) } else { 0.0 };
        let plan = plan(scenario, problems, &options.frame, purpose, options.width, header_h, aspect)?;
        let trail_steps = step_of(options.trail, scenario.header.time_step_size);
        let legend = if legend { footer::entries(scenario, problems, ego, timed && trail_steps > 0) } else { Vec::new() };
        let view = plan.any();
        let time_bar = timed && !options.marks.is_empty();
        let bar_h = if time_bar { timebar::height(options.width) } else { 0.0 };
        let footer_h = footer::height(options.width, &legend, true);
        let height = (header_h + f64::from(view.height) + bar_h + footer_h).round() as u32;
        let mut p = Self {
            scenario,
            problems,
            plan,
            ego,
            width: options.width,
            height,
            timed,
            time_bar,
            legend,
            still: None,
            names: options.names.clone(),
            marks: options.marks.clone(),
            trail_steps,
        };
        if let ViewPlan::Fixed(v) = &p.plan {
            p.still = Some(p.still_layer(v));
        }
        Ok(p)
    }

    /// A still at `step` (framed at that time, with its trails).
    pub fn still_at(scenario: &'a Scenario, problems: Option<&'a PlanningProblemSet>, options: &RenderOptions, step: u64) -> Result<Self, Error> {
        let trail_steps = step_of(options.trail, scenario.header.time_step_size);
        Self::new(scenario, problems, options, Purpose::Still { step, trail_steps }, None, true)
    }

    fn still_layer(&self, view: &View) -> Vec<Prim> {
        let net = &self.scenario.network;
        let mut still = Vec::new();
        network::surfaces(net, view, &mut still);
        if let Some(p) = self.problems {
            goal::goals(p, net, view, &mut still);
        }
        network::borders_and_markings(net, view, &mut still);
        obstacles::still_obstacles(self.scenario, view, &mut still);
        network::signs(net, view, &mut still);
        obstacles::paths(self.scenario, self.ego, view, &mut still);
        if let (Some(p), None) = (self.problems, self.ego) {
            goal::initial_states(p, view, &mut still);
        }
        still
    }

    /// Whether every step has the same map layer (the view does not move).
    pub fn is_fixed(&self) -> bool {
        self.still.is_some()
    }

    /// The map layer at `step`.
    pub fn base(&self, step: u64) -> Cow<'_, [Prim]> {
        match &self.still {
            Some(s) => Cow::Borrowed(s.as_slice()),
            None => Cow::Owned(self.still_layer(&self.plan.at(self.scenario, step))),
        }
    }

    /// What moves, at `step`: lights, trails, road users and their labels, the strips.
    pub fn moving(&self, step: u64) -> Vec<Prim> {
        self.frame(step).0
    }

    /// Where things are at `step`.
    pub fn layout(&self, step: u64) -> Layout {
        let view = self.plan.at(self.scenario, step);
        let (x0, y0, x1, y1) = view.area();
        Layout { width: self.width, height: self.height, map: PxRect { x0, y0, x1, y1 }, world: view.world(), scale: view.scale, obstacles: self.frame(step).1 }
    }

    fn frame(&self, step: u64) -> (Vec<Prim>, Vec<DrawnObstacle>) {
        let view = self.plan.at(self.scenario, step);
        let mut out = Vec::new();
        network::lights(&self.scenario.network, &view, step, &mut out);
        trails::trails(self.scenario, self.ego, step, self.trail_steps, &view, &mut out);
        let shown = obstacles::dynamic_at(self.scenario, self.ego, step, &view, &mut out);
        let size = style::text_size(self.width);
        let names: Vec<Option<&str>> = shown.iter().map(|s| self.names.get(&s.id.get()).map(String::as_str)).collect();
        let texts: Vec<String> = shown.iter().zip(&names).map(|(s, n)| labels::text(s.id.get(), *n, s.ego)).collect();
        let boxes: Vec<PxRect> = shown.iter().map(|s| s.bbox).collect();
        let (ax0, ay0, ax1, ay1) = view.area();
        let area = PxRect { x0: ax0, y0: ay0, x1: ax1, y1: ay1 };
        let rects = labels::place(&boxes, &texts, size, &area);
        let mut drawn = Vec::new();
        let mut label_prims = Vec::new();
        for (((s, n), t), r) in shown.iter().zip(names).zip(texts).zip(rects) {
            let label = Label { text: t, rect: r };
            label_prims.push((label.clone(), s.ego, s.bbox));
            drawn.push(DrawnObstacle {
                id: s.id.get(),
                name: n.map(str::to_string),
                ego: s.ego,
                obstacle_type: s.obstacle_type,
                length_px: s.length_px,
                bbox: s.bbox,
                center: s.center,
                label: Some(label),
            });
        }
        labels::prims(&label_prims, size, &mut out);
        if self.timed {
            header::header(self.width, step, self.scenario.header.time_step_size, &self.marks, &mut out);
        }
        let mut y = view.y0 + f64::from(view.height);
        if self.time_bar {
            let (first, last) = (first_step(self.scenario), last_step(self.scenario));
            let dt = self.scenario.header.time_step_size;
            timebar::bar(self.width, y, first, last, step, dt, &self.marks, &mut out);
            y += timebar::height(self.width);
        }
        footer::footer(Some(&view), self.width, y, &self.legend, &mut out);
        (out, drawn)
    }

    /// The whole picture at `step`.
    pub fn scene(&self, step: u64) -> Scene {
        Scene { width: self.width, height: self.height, background: style::BACKGROUND, still: self.base(step).into_owned(), moving: self.moving(step) }
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
