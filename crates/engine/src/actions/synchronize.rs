//! SynchronizeAction: the actor adapts its speed so that it reaches its target position when the
//! master entity reaches the master's target position, optionally arriving at a final speed
//! (absolute or relative to the master) that it keeps over a steady-state distance or time
//! before the target.
//!
//! The speed profile is esmini's: with a final speed, constant-acceleration phases — straight to
//! the final speed when that fits (linear), else accelerate-then-decelerate or the reverse
//! (non-linear, convex or concave, switching to linear at the apex), or stop and wait when even
//! that would need a negative speed; without a final speed, the constant acceleration that
//! covers the distance in the master's time. Distances are measured along the trajectory an
//! entity follows (to the path's point nearest the target), else along the roads (a target
//! given in the world attached to the road where it lies), else in a straight line. The action ends when the actor or the
//! master is within its tolerance, when either distance starts to grow (a target was passed),
//! or when the master arrives within the next step; then the actor takes the final speed. While
//! the master stands still the actor stands too.

pub(crate) mod state;

use state::{Final, Mode, Submode, SynchronizeRt};

use super::state::{ActionRt, Kept};
use crate::angles::angle_difference;
use crate::positions::{resolve, Placement};
use crate::roads::road_path::path_ends;
use crate::sim::Sim;
use opendrive::ContactPoint;
use openscenario::{FinalSpeed, Position, SpeedTargetValueType, SteadyState};
use std::f64::consts::FRAC_PI_2;

/// esmini's SMALL_NUMBER, every tolerance of SynchronizeAction::Step.
const SMALL: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;
const LARGE: f64 = 1e10;
/// The deceleration esmini uses to stop at once, m/s².
const STOP_DECELERATION: f64 = -8.0;

/// The action's parameters as the model gives them.
#[derive(Clone, Copy)]
pub(crate) struct SynchronizeSpec<'s> {
    pub master: &'s str,
    pub target_master: &'s Position,
    pub target: &'s Position,
    pub final_speed: Option<&'s FinalSpeed>,
    /// (targetToleranceMaster, targetTolerance).
    pub tolerances: (Option<f64>, Option<f64>),
}

impl<'a> Sim<'a> {
    pub(super) fn start_synchronize(&mut self, slot: usize, e: usize, spec: &SynchronizeSpec) -> ActionRt {
        let SynchronizeSpec { master, target_master, target, final_speed, tolerances } = *spec;
        let Some(master) = self.entity_index(master) else {
            self.warn_action(slot, format!("SynchronizeAction: unknown master entity `{master}`"));
            return ActionRt::Done;
        };
        let (tm, t) = match (resolve(target_master, self.net, &self.entities), resolve(target, self.net, &self.entities)) {
            (Ok(a), Ok(b)) => (self.on_road(a), self.on_road(b)),
            (Err(e), _) | (_, Err(e)) => {
                self.warn_action(slot, format!("SynchronizeAction: target position: {e}; the action completes at once"));
                return ActionRt::Done;
            }
        };
        let (fin, steady) = match final_speed {
            None => (None, None),
            Some(FinalSpeed::Absolute { value, steady_state }) => (Some(Final::Absolute(*value)), *steady_state),
            Some(FinalSpeed::RelativeToMaster { value, value_type, steady_state }) => {
                (Some(Final::Relative { value: *value, factor: *value_type == SpeedTargetValueType::Factor }), *steady_state)
            }
        };
        let (steady_dist, steady_time) = match steady {
            Some(SteadyState::Distance(d)) => (Some(d), None),
            Some(SteadyState::Time(t)) => (None, Some(t)),
            None => (None, None),
        };
        let mut rt = SynchronizeRt {
            master,
            target_master: tm,
            target: t,
            final_speed: fin,
            steady_dist,
            steady_time,
            // Without targetTolerance(Master) esmini 3.6 aims at the positions themselves (its
            // distance tolerance default is 0; the synchronised corpus scenarios show it).
            tolerance: tolerances.1.unwrap_or(0.0),
            tolerance_master: tolerances.0.unwrap_or(0.0),
            mode: Mode::None,
            submode: Submode::None,
            last_dist: LARGE,
            last_master_dist: LARGE,
        };
        if let Some(Kept::Synchronize(k)) = self.actions.get(slot).and_then(|s| s.kept_for(e)) {
            // The object's state from the last execution (SynchronizeKept).
            rt.mode = k.mode;
            rt.submode = k.submode;
            rt.last_dist = k.last_dist;
            rt.last_master_dist = k.last_master_dist;
            rt.steady_dist = k.steady_dist;
            rt.steady_time = None;
        }
        // A steady-state time becomes a distance at the final speed the action starts with.
        if let Some(st) = rt.steady_time.take() {
            rt.steady_dist = Some(st * self.final_speed_value(&rt));
        }
        ActionRt::Synchronize(Box::new(rt))
    }

    /// A target given in the world (a WorldPosition, relative world or object positions) in
    /// road coordinates too: esmini's target is a roadmanager::Position, which
    /// Position::SetInertiaPos attaches to the nearest lane (XYZ2TrackPos), so
    /// SynchronizeAction::Step measures to it along the road (Position::Delta), not in a
    /// straight line.
    fn on_road(&self, mut p: Placement) -> Placement {
        if let (None, Some(net)) = (p.lane, self.net) {
            p.lane = crate::roads::locate::world_to_lane(net, p.x, p.y, None).map(|lp| crate::roads::LanePos {
                road: lp.road,
                lane_id: lp.lane_id,
                s: lp.s,
                offset: lp.offset,
                dir: 1.0,
            });
        }
        p
    }

    fn final_speed_value(&self, s: &SynchronizeRt) -> f64 {
        let ms = self.entities.get(s.master).map_or(0.0, |m| m.speed);
        match s.final_speed {
            Some(Final::Absolute(v)) => v,
            Some(Final::Relative { value, factor: true }) => ms * value,
            Some(Final::Relative { value, factor: false }) => ms + value,
            None => 0.0,
        }
    }

    /// Distance of entity `e` to a placement, as SynchronizeAction::Step measures it: along the
    /// trajectory the entity follows, else along esmini's road path (Position::Delta:
    /// RoadPath::Calculate follows the entity's lane, `path_ends`), else in a straight line.
    fn distance_to(&self, e: usize, p: &Placement) -> f64 {
        let Some(en) = self.entities.get(e) else { return 0.0 };
        if let Some(d) = self.along_trajectory(e, p) {
            return d.abs();
        }
        if let (Some(net), Some(a), Some(b)) = (self.net, en.lane, p.lane) {
            if a.road == b.road {
                return (b.s - a.s).abs();
            }
            if let Some(path) = path_ends(net, a.road, a.s, a.lane_id, b.road) {
                return path.length_to(b.s, net.roads.get(b.road).map_or(0.0, |r| r.length));
            }
        }
        (en.x - p.x).hypot(en.y - p.y)
    }

    /// Distance of the master `m` to its target and whether the target lies ahead of it (+1) or
    /// behind (-1), as SynchronizeAction::Step reads them from Position::Delta: on one road
    /// the sign of the s difference seen in the direction the master faces (RoadPath::Calculate's
    /// same-road case); across roads, whether the shortest chain leaves the master's road ahead
    /// of it, turned round when the master faces against its lane's driving direction, turned
    /// to the left of it (the end of RoadPath::Calculate); off the network, whether the straight line to the target points
    /// forward of the master's heading. A master driving away from its target makes the actor
    /// wait (stand) as a master standing still does.
    fn master_distance(&self, m: usize, p: &Placement) -> (f64, f64) {
        let Some(en) = self.entities.get(m) else { return (0.0, 1.0) };
        let sign = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
        if let Some(d) = self.along_trajectory(m, p) {
            // On a trajectory the direction is the distance's sign, turned round when the
            // master faces against the path (IsAngleForward of GetAngleDifference(GetHTrue, H)).
            let Some(f) = self.running_trajectory(m) else { return (d.abs(), sign(d)) };
            let facing = angle_difference(f.path.true_heading_at(f.s), en.h).abs() <= FRAC_PI_2;
            return (d.abs(), sign(d) * if facing { 1.0 } else { -1.0 });
        }
        if let (Some(net), Some(a), Some(b)) = (self.net, en.lane, p.lane) {
            let facing_along = (a.dir >= 0.0) == (en.yaw_offset.cos() >= 0.0);
            let ahead = if facing_along { 1.0 } else { -1.0 };
            if a.road == b.road {
                let ds = (b.s - a.s) * ahead;
                return (ds.abs(), sign(ds));
            }
            if let Some(path) = path_ends(net, a.road, a.s, a.lane_id, b.road) {
                let d = path.length_to(b.s, net.roads.get(b.road).map_or(0.0, |r| r.length));
                let leaves_ahead = (path.first_exit == ContactPoint::End) == facing_along;
                let mut dir = if leaves_ahead { 1.0 } else { -1.0 };
                // RoadPath::Calculate turns the sign for a master facing against its lane's
                // driving direction by GetHRelativeDrivingDirection in (pi/2, 3pi/2): an
                // angle difference in [-pi, pi], so only one turned to the left of it. For a
                // master facing exactly against it the difference is ±pi by rounding;
                // Position::GetDrivingDirection's own arithmetic decides (the road heading,
                // turned by pi into [0, 2pi) for a left lane and again for left-hand
                // traffic), against the heading esmini's position holds (EvaluateHPR's
                // guarded matrices: along ±y it is a micro-radian off the road's, which
                // turns an exact tie to one side).
                if let (Some(r), Some(pose)) = (net.roads.get(a.road), a.pose(net)) {
                    if crate::roads::driving_direction::faces_against(r.rule, a.lane_id, pose.road_heading, crate::entities::position_heading(Some(net), en)) {
                        dir = -dir;
                    }
                }
                return (d, if d == 0.0 { 1.0 } else { dir });
            }
        }
        let (vx, vy) = (p.x - en.x, p.y - en.y);
        let forward = (vy.atan2(vx) - en.h).cos() >= 0.0;
        (vx.hypot(vy), if forward { 1.0 } else { -1.0 })
    }

    /// The distance along the trajectory entity `e` follows, if it follows one, to the path's
    /// point nearest the target: SynchronizeAction::Step asks an entity on a trajectory first
    /// for Position::Distance in the trajectory's frame (longitudinal: the s of
    /// FindClosestPoint less the entity's trajectory s), and only without one for
    /// Position::Delta along the roads.
    fn along_trajectory(&self, e: usize, p: &Placement) -> Option<f64> {
        let f = self.running_trajectory(e)?;
        Some(f.path.closest_s(p.x, p.y) - f.s)
    }

    /// The velocity projected on the road's s axis, with the sign of the speed (esmini's
    /// `SIGN(GetSpeed()) * |Position::GetVelS()|`). The velocity is the one derived from the
    /// last step's motion, so a master that just got a speed counts as moving one step later.
    fn speed_along_road(&self, e: usize) -> f64 {
        self.entities.get(e).map_or(0.0, |en| {
            let road_h = en.h - en.yaw_offset;
            en.speed.signum() * (en.vel.0 * road_h.cos() + en.vel.1 * road_h.sin()).abs()
        })
    }

    /// One step; true when the action is done.
    pub(super) fn step_synchronize(&mut self, e: usize, s: &mut SynchronizeRt) -> bool {
        let dt = self.dt;
        let (master_dist_raw, master_direction) = self.master_distance(s.master, &s.target_master);
        let dist_raw = self.distance_to(e, &s.target);
        let mut done =
            dist_raw < s.tolerance + SMALL || master_dist_raw < s.tolerance_master + SMALL || dist_raw > s.last_dist || master_dist_raw > s.last_master_dist;
        s.last_dist = dist_raw;
        s.last_master_dist = master_dist_raw;
        let mut dist = (dist_raw - s.tolerance).max(SMALL);
        let master_dist = (master_dist_raw - s.tolerance_master).max(SMALL);
        let master_speed = master_direction * self.speed_along_road(s.master);
        let mut t_master = LARGE;
        if master_speed > SMALL {
            t_master = master_dist / master_speed;
            if t_master < dt {
                done = true;
            }
        } else if s.mode != Mode::Waiting {
            // SynchronizeAction::Step: a master standing still ("Waiting for master to move")
            // stops the actor at once, whether a final speed is given or not; with one it
            // waits until the master moves again.
            s.mode = Mode::Waiting;
            self.set_speed(e, 0.0);
        }
        let speed = self.entities.get(e).map_or(0.0, |x| x.speed);
        if done {
            if s.final_speed.is_some() {
                let v = self.final_speed_value(s);
                self.set_speed(e, v);
            }
            return true;
        }
        if s.final_speed.is_none() {
            let average = dist / t_master;
            let final_speed = 2.0 * average - speed;
            let acc = (final_speed - speed) / t_master;
            self.set_speed(e, speed + acc * dt);
            return false;
        }
        let v1 = self.final_speed_value(s);
        if let Some(ss) = s.steady_dist {
            if s.mode != Mode::SteadyState {
                let time_to_ss = ss / v1;
                if dist - ss < SMALL || t_master - time_to_ss < SMALL {
                    s.mode = Mode::SteadyState;
                    s.submode = Submode::None;
                } else {
                    dist -= ss;
                    t_master -= time_to_ss;
                }
            }
        }
        match s.mode {
            Mode::SteadyState => {
                self.set_speed(e, v1);
                return false;
            }
            Mode::Waiting => {
                if t_master >= LARGE {
                    return false;
                }
                s.mode = Mode::None;
            }
            Mode::StopImmediately => {
                let v = speed + STOP_DECELERATION * dt;
                if v < 0.0 {
                    self.set_speed(e, 0.0);
                    s.mode = Mode::Waiting;
                } else {
                    self.set_speed(e, v);
                }
                return false;
            }
            Mode::Stopped => {
                if t_master < 2.0 * dist / v1 {
                    s.mode = Mode::Linear;
                } else {
                    self.set_speed(e, 0.0);
                    return false;
                }
            }
            _ => {}
        }
        if s.mode == Mode::Linear {
            let v = if t_master > LARGE - 1.0 { 0.0 } else { linear_start_speed(v1.max(0.0), t_master, dist).max(0.0) };
            self.set_speed(e, v);
            return false;
        }
        if s.mode == Mode::NonLinear && t_master < LARGE {
            let v0_on_line = 2.0 * dist / t_master - v1;
            if (speed - v0_on_line).abs() < 0.1 {
                // Passed the apex: constant acceleration from here; keep the speed this step.
                s.mode = Mode::Linear;
                return false;
            }
        }
        if s.mode == Mode::None {
            s.mode = Mode::NonLinear;
            s.submode = if (v1 + speed) / 2.0 < dist / t_master { Submode::Convex } else { Submode::Concave };
        }
        let (st, t) = (dist, t_master);
        let v0 = self.speed_along_road(e);
        let root = 2f64.sqrt() * (2.0 * st * st - 2.0 * (v1 + v0) * t * st + (v1 * v1 + v0 * v0) * t * t).max(0.0).sqrt();
        let (mut vx, mut acc) = (0.0, 0.0);
        if (v1 - v0).abs() < SMALL {
            vx = (st - (t / 2.0) * v0) / (t / 2.0);
            acc = (vx - v0) / (t / 2.0);
        } else {
            let x1 = -(root + 2.0 * st - 2.0 * v1 * t) / (2.0 * (v1 - v0));
            let x2 = -(-root + 2.0 * st - 2.0 * v1 * t) / (2.0 * (v1 - v0));
            let vx1 = (2.0 * st - root) / (2.0 * t);
            let vx2 = (2.0 * st + root) / (2.0 * t);
            if x1 > 0.0 && x1 < t {
                vx = vx1;
                acc = (vx1 - v0) / x1;
            } else if x2 > 0.0 && x2 < t {
                vx = vx2;
                acc = (vx2 - v0) / x2;
            }
        }
        if s.mode == Mode::NonLinear && ((s.submode == Submode::Concave && acc > 0.0) || (s.submode == Submode::Convex && acc < 0.0)) {
            // The apex of the profile: linear from the next step, keep the speed now.
            s.mode = Mode::Linear;
            acc = 0.0;
        }
        if s.mode == Mode::NonLinear && vx < 0.0 {
            // Even the slowest two-phase profile needs to stop: decelerate to a stop and wait.
            let t1 = 2.0 * v0 * st / (v0 * v0 + v1 * v1);
            acc = if t1.abs() > SMALL { -v0 / t1 } else { 0.0 };
            if t1 * v0 / 2.0 > st / 2.0 {
                acc = STOP_DECELERATION;
                s.mode = Mode::StopImmediately;
            }
            if v0 + acc * dt < 0.0 {
                self.set_speed(e, 0.0);
                s.mode = Mode::Stopped;
                return false;
            }
        }
        self.set_speed(e, speed + acc * dt);
        false
    }

    fn set_speed(&mut self, e: usize, v: f64) {
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = v;
        }
    }
}

/// Start speed of a constant-acceleration profile that covers `dist` in `time` ending at `v_final`.
fn linear_start_speed(v_final: f64, time: f64, dist: f64) -> f64 {
    if time < 0.001 || dist < 0.001 {
        return 0.0;
    }
    2.0 * dist / time - v_final
}
