//! Which world box a picture shows: where the road users are (at a time with their trails, or
//! over the whole run), the whole map, a rectangle given by hand, or a window that follows one
//! road user.

use std::collections::BTreeMap;

use commonroad::{DynamicObstacle, ObstacleId, PlanningProblemSet, Scenario};

use crate::error::Error;
use crate::options::{Frame, FOLLOW_SPAN_M};
use crate::timeline::{first_step, last_step, state_at, step_of};
use crate::view::{content_bounds, shape_radius, Bounds, Fit, View};

/// A still is framed on where the road users are and their last second: longer trails may
/// run out of the picture rather than shrink the road users.
pub const FRAMED_TRAIL_S: f64 = 1.0;

/// What the picture is for: the action framing depends on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Purpose {
    /// A still at this step, with trails of `trail_steps` before it.
    Still { step: u64, trail_steps: u64 },
    /// A panel of a sheet: a still at this step whose road users are drawn large enough to
    /// see at a glance — when framing them all would draw the largest shorter than
    /// [`MIN_PANEL_USER_SHARE`] of the panel, the panel frames `ego` (else the largest road
    /// user) and the road users nearest it that fit, the others being seen in other panels.
    Panel { step: u64, trail_steps: u64, ego: Option<ObstacleId> },
    /// An animation over the whole run: one view of it all, or a camera that pans with the
    /// road users when that shows them much larger.
    Animation,
}

/// The largest road user of a sheet's panel is drawn at least this share of the panel's width
/// long (a car 12 px in a panel of 390 px).
pub const MIN_PANEL_USER_SHARE: f64 = 1.0 / 32.0;

/// Height / width of a following window.
pub const FOLLOW_ASPECT: f64 = 0.5;

/// The view of a picture: one for every frame, or one that moves with an obstacle.
#[derive(Debug, Clone, PartialEq)]
pub enum ViewPlan {
    Fixed(View),
    Follow {
        view: View,
        id: ObstacleId,
    },
    /// A camera that keeps the road users of each step in the middle, zoomed to hold them:
    /// (step, (centre x, centre y, pixels per metre)) for each step someone is on the road.
    Pan {
        view: View,
        cameras: BTreeMap<u64, (f64, f64, f64)>,
    },
}

impl ViewPlan {
    /// The view at `step`.
    pub fn at(&self, scenario: &Scenario, step: u64) -> View {
        match self {
            ViewPlan::Fixed(v) => *v,
            ViewPlan::Pan { view, cameras } => {
                let c = cameras.range(..=step).next_back().or_else(|| cameras.range(step..).next());
                match c {
                    Some((_, &(x, y, scale))) => View { scale, ..*view }.centred_on(x, y),
                    None => *view,
                }
            }
            ViewPlan::Follow { view, id } => match scenario.dynamic_obstacles.iter().find(|o| o.id == *id).and_then(|o| nearest_state(o, step)) {
                Some((x, y)) => view.centred_on(x, y),
                None => *view,
            },
        }
    }

    /// Any view of the plan (the sizes are the same at every step).
    pub fn any(&self) -> &View {
        match self {
            ViewPlan::Fixed(v) | ViewPlan::Follow { view: v, .. } | ViewPlan::Pan { view: v, .. } => v,
        }
    }
}

/// Where the obstacle is at `step`, or at its first or last state when it does not exist then.
fn nearest_state(o: &DynamicObstacle, step: u64) -> Option<(f64, f64)> {
    if let Some(s) = state_at(o, step) {
        return Some((s.x, s.y));
    }
    let all = std::iter::once(&o.initial_state).chain(&o.trajectory);
    all.min_by_key(|s| s.time_step.abs_diff(step)).map(|s| (s.x, s.y))
}

/// The boxes of the road users: those that exist at `step` over their last `trail_steps`, or
/// every state of every one (`None`).
pub fn road_users(scenario: &Scenario, still: Option<(u64, u64)>) -> Bounds {
    let mut b = Bounds::empty();
    for o in &scenario.dynamic_obstacles {
        let r = shape_radius(&o.shape);
        let states = std::iter::once(&o.initial_state).chain(&o.trajectory);
        match still {
            None => states.for_each(|s| b.add(s.x, s.y, r)),
            Some((step, trail)) => {
                if state_at(o, step).is_none() {
                    continue;
                }
                let from = step.saturating_sub(trail);
                states.filter(|s| (from..=step).contains(&s.time_step)).for_each(|s| b.add(s.x, s.y, r));
            }
        }
    }
    b
}

/// Height / width of a panning camera's view.
pub const PAN_ASPECT: f64 = 0.6;
/// An animation pans and zooms with the road users when that shows them on average at least
/// this many times larger than one view of the whole run.
pub const PAN_GAIN: f64 = 1.5;

/// The boxes of the road users at `step`.
fn users_at(scenario: &Scenario, step: u64) -> Bounds {
    let mut b = Bounds::empty();
    for o in &scenario.dynamic_obstacles {
        if let Some(s) = state_at(o, step) {
            b.add(s.x, s.y, shape_radius(&o.shape));
        }
    }
    b
}

/// How far ahead and behind a camera looks to zoom smoothly, s.
pub const ZOOM_WINDOW_S: f64 = 2.0;

/// The smallest of `v[k - w ..= k + w]` at each k.
fn min_filter(v: &[f64], w: usize) -> Vec<f64> {
    (0..v.len()).map(|k| v[k.saturating_sub(w)..=(k + w).min(v.len() - 1)].iter().copied().fold(f64::INFINITY, f64::min)).collect()
}

/// The mean of `v[k - w ..= k + w]` at each k.
fn mean_filter(v: &[f64], w: usize) -> Vec<f64> {
    (0..v.len())
        .map(|k| {
            let part = &v[k.saturating_sub(w)..=(k + w).min(v.len() - 1)];
            part.iter().sum::<f64>() / part.len() as f64
        })
        .collect()
}

/// The camera of an animation that follows the road users: at each step centred on them and
/// zoomed to hold them — the scale the smallest within [`ZOOM_WINDOW_S`] either side, then
/// averaged over the same window, so the zoom is smooth and never cuts anyone off. `None` when
/// it would not show them on average [`PAN_GAIN`] times larger than `fixed`.
fn pan(scenario: &Scenario, fixed: &View, width: u32, y0: f64) -> Result<Option<ViewPlan>, Error> {
    let fit = Fit { aspect: (PAN_ASPECT, PAN_ASPECT), ..Fit::ACTION };
    let mut steps = Vec::new();
    let mut centres = Vec::new();
    let mut scales = Vec::new();
    let mut any: Option<View> = None;
    for step in first_step(scenario)..=last_step(scenario) {
        let b = users_at(scenario, step);
        if !b.is_valid() {
            continue;
        }
        let v = View::fit(b, width, &fit, y0)?;
        steps.push(step);
        centres.push((0.5 * (b.min_x + b.max_x), 0.5 * (b.min_y + b.max_y)));
        scales.push(v.scale);
        any.get_or_insert(v);
    }
    let Some(view) = any else { return Ok(None) };
    let w = step_of(ZOOM_WINDOW_S, scenario.header.time_step_size) as usize;
    let smooth = mean_filter(&min_filter(&scales, w), w);
    let mean = smooth.iter().sum::<f64>() / smooth.len() as f64;
    if mean < PAN_GAIN * fixed.scale {
        return Ok(None);
    }
    let cameras = steps.into_iter().zip(centres).zip(smooth).map(|((k, (x, y)), scale)| (k, (x, y, scale))).collect();
    Ok(Some(ViewPlan::Pan { view, cameras }))
}

/// The view plan of `frame` for `purpose`, the map area `width` pixels wide from row `top_px`;
/// `aspect` (height / width) fixes the map area's shape when given (panels of a sheet).
pub fn plan(
    scenario: &Scenario,
    problems: Option<&PlanningProblemSet>,
    frame: &Frame,
    purpose: Purpose,
    width: u32,
    top_px: f64,
    aspect: Option<f64>,
) -> Result<ViewPlan, Error> {
    let with_aspect = |fit: Fit| match aspect {
        Some(a) => Fit { aspect: (a, a), ..fit },
        None => fit,
    };
    let whole = || View::fit(content_bounds(scenario, problems), width, &with_aspect(Fit::WHOLE), top_px);
    match frame {
        Frame::WholeMap => whole().map(ViewPlan::Fixed),
        Frame::Region([x0, y0, x1, y1]) => {
            let b = Bounds { min_x: *x0, min_y: *y0, max_x: *x1, max_y: *y1 };
            View::fit(b, width, &with_aspect(Fit::EXACT), top_px).map(ViewPlan::Fixed)
        }
        Frame::Action => {
            let framed_trail = step_of(FRAMED_TRAIL_S, scenario.header.time_step_size);
            let still = match purpose {
                Purpose::Still { step, trail_steps } | Purpose::Panel { step, trail_steps, .. } => Some((step, trail_steps.min(framed_trail))),
                Purpose::Animation => None,
            };
            let mut b = road_users(scenario, still);
            if !b.is_valid() && still.is_some() {
                // nobody on the road at that time: where they are over the run
                b = road_users(scenario, None);
            }
            if !b.is_valid() {
                return whole().map(ViewPlan::Fixed);
            }
            let mut fixed = View::fit(b, width, &with_aspect(Fit::ACTION), top_px)?;
            if let (Purpose::Panel { ego, .. }, Some((step, trail))) = (purpose, still) {
                if let Some(near) = near_ego(scenario, step, trail, ego, width, &with_aspect(Fit::ACTION), top_px, &fixed)? {
                    fixed = near;
                }
            }
            if purpose == Purpose::Animation && aspect.is_none() {
                if let Some(p) = pan(scenario, &fixed, width, top_px)? {
                    return Ok(p);
                }
            }
            Ok(ViewPlan::Fixed(fixed))
        }
        Frame::Follow(id) => {
            let Some(o) = scenario.dynamic_obstacles.iter().find(|o| o.id.get() == *id) else {
                return Err(Error::Option(format!("--follow: the scenario has no dynamic obstacle with id {id}")));
            };
            let a = aspect.unwrap_or(FOLLOW_ASPECT);
            let half = 0.5 * FOLLOW_SPAN_M;
            let b = Bounds { min_x: -half, max_x: half, min_y: -half * a, max_y: half * a };
            let view = View::fit(b, width, &Fit { aspect: (a, a), ..Fit::EXACT }, top_px)?;
            Ok(ViewPlan::Follow { view, id: o.id })
        }
    }
}

/// The view of a panel at `step` (trails of `trail` steps) on `ego` (else the largest road user)
/// and the road users nearest it, as many as keep the largest road user
/// [`MIN_PANEL_USER_SHARE`] of the width long; `None` when `all` (every road user) does so.
#[allow(clippy::too_many_arguments)]
fn near_ego(
    scenario: &Scenario,
    step: u64,
    trail: u64,
    ego: Option<ObstacleId>,
    width: u32,
    fit: &Fit,
    top_px: f64,
    all: &View,
) -> Result<Option<View>, Error> {
    // each road user there at `step`: where it is, its box over the framed trail, its size
    let mut users: Vec<(ObstacleId, (f64, f64), Bounds, f64)> = Vec::new();
    for o in &scenario.dynamic_obstacles {
        let Some(now) = state_at(o, step) else { continue };
        let r = shape_radius(&o.shape);
        let mut b = Bounds::empty();
        let from = step.saturating_sub(trail);
        std::iter::once(&o.initial_state).chain(&o.trajectory).filter(|s| (from..=step).contains(&s.time_step)).for_each(|s| b.add(s.x, s.y, r));
        users.push((o.id, (now.x, now.y), b, 2.0 * r));
    }
    let largest = users.iter().map(|u| u.3).fold(0.0, f64::max);
    let min_scale = MIN_PANEL_USER_SHARE * f64::from(width) / largest.max(f64::MIN_POSITIVE);
    if all.scale >= min_scale {
        return Ok(None);
    }
    let anchor = users.iter().find(|u| Some(u.0) == ego).or_else(|| users.iter().max_by(|a, b| a.3.total_cmp(&b.3).then(b.0.cmp(&a.0))));
    let Some(&(_, (ax, ay), anchor_box, _)) = anchor else { return Ok(None) };
    users.sort_by(|a, b| (a.1 .0 - ax).hypot(a.1 .1 - ay).total_cmp(&(b.1 .0 - ax).hypot(b.1 .1 - ay)).then(a.0.cmp(&b.0)));
    let mut framed = anchor_box;
    let mut view = View::fit(framed, width, fit, top_px)?;
    for (_, _, b, _) in &users {
        let mut wider = framed;
        wider.add(b.min_x, b.min_y, 0.0);
        wider.add(b.max_x, b.max_y, 0.0);
        let v = View::fit(wider, width, fit, top_px)?;
        if v.scale < min_scale {
            break;
        }
        (framed, view) = (wider, v);
    }
    Ok(Some(view))
}
