//! FollowTrajectoryAction, as esmini 3.6 runs it: the trajectory's positions are resolved when
//! the action starts (relative ones from the entities' poses then), the entity is put on the
//! path at the initial distance offset, and each step moves it along the path — by speed · dt
//! without a time reference, to the point of the current trajectory time with one (the speed
//! then follows from the distance covered). It ends at the path's end (open paths without
//! timing) or at the last time stamp, moving on along the final heading by whatever distance
//! the step had left.

pub(crate) mod state;

use state::FollowTrajectoryRt;

use super::state::ActionRt;
use crate::dynamics::SMALL;
use crate::positions::resolve;
use crate::sim::Sim;
use openscenario::{FollowingMode, ReferenceContext, TimeReference, Trajectory};
use trajectory::{Path, Pose, TimeDomain, TimeMapping};

impl FollowTrajectoryRt {
    fn s_at_time(&self, t: f64) -> Option<f64> {
        let Some(segs) = &self.accel else { return self.path.s_at_time(t) };
        let first = segs.first()?;
        if t <= first.1 {
            return Some(first.0);
        }
        let i = segs.partition_point(|q| q.1 <= t).saturating_sub(1);
        let (s0, t0, v0, a) = segs[i];
        let tau = t - t0;
        Some(s0 + v0 * tau + 0.5 * a * tau * tau)
    }
}

/// The constant-acceleration segments of a timed path (see [`FollowTrajectoryRt::accel`]).
fn accel_segments(path: &Path) -> Option<Vec<(f64, f64, f64, f64)>> {
    let pts = path.time_table()?.points();
    let mut out = Vec::with_capacity(pts.len());
    let mut v = match pts {
        [a, b, ..] if b.1 - a.1 > SMALL => (b.0 - a.0) / (b.1 - a.1),
        _ => 0.0,
    };
    for w in pts.windows(2) {
        if let [a, b] = w {
            let (d, dt) = (b.0 - a.0, b.1 - a.1);
            let acc = if dt > SMALL { 2.0 * (d - v * dt) / (dt * dt) } else { 0.0 };
            out.push((a.0, a.1, v, acc));
            v += acc * dt;
        }
    }
    if let Some(last) = pts.last() {
        // After the last stamp the entity stays at the end.
        out.push((last.0, last.1, 0.0, 0.0));
    }
    Some(out)
}

/// The world pose of a position resolved for a trajectory vertex.
pub(crate) fn vertex_pose(pos: &openscenario::Position, net: Option<&opendrive::RoadNetwork>, entities: &[crate::entities::Entity]) -> Option<Pose> {
    let p = resolve(pos, net, entities).ok()?;
    Some(Pose::new(p.x, p.y, p.z.unwrap_or(0.0), p.h))
}

/// Build a trajectory's path from the current state of the run.
pub(crate) fn build_path(sim: &Sim, traj: &Trajectory, current: Pose) -> Result<Path, String> {
    let net = sim.net;
    let entities = &sim.entities;
    let resolver = |p: &openscenario::Position| vertex_pose(p, net, entities);
    Path::from_trajectory(traj, current, &resolver).map_err(|e| e.to_string())
}

impl<'a> Sim<'a> {
    pub(super) fn start_follow_trajectory(
        &mut self,
        slot: usize,
        e: usize,
        traj: &Trajectory,
        time_ref: &TimeReference,
        mode: FollowingMode,
        initial_offset: Option<f64>,
    ) -> ActionRt {
        let Some(en) = self.entities.get(e) else { return ActionRt::Done };
        let current = Pose::new(en.x, en.y, en.z, en.h);
        let entity_speed = en.speed;
        let path = match build_path(self, traj, current) {
            Ok(p) => p,
            Err(msg) => {
                self.warn_action(slot, format!("FollowTrajectoryAction: trajectory `{}` cannot be followed: {msg}", traj.name));
                return ActionRt::Done;
            }
        };
        for w in &path.warnings {
            let msg = format!("trajectory `{}`: {w}", traj.name);
            self.warn_action(slot, msg);
        }
        let timing = match time_ref {
            TimeReference::Timing { domain, scale, offset } if path.is_timed() => Some(TimeMapping {
                domain: if *domain == ReferenceContext::Absolute { TimeDomain::Absolute } else { TimeDomain::Relative },
                scale: *scale,
                offset: *offset,
            }),
            TimeReference::Timing { .. } => {
                self.warn_action(slot, format!("FollowTrajectoryAction: trajectory `{}` has no time stamps; timing ignored", traj.name));
                None
            }
            TimeReference::None => None,
        };
        let s = path.normalize_s(initial_offset.unwrap_or(0.0));
        let time = path.time_at(s).unwrap_or(0.0);
        // esmini's FollowTrajectoryAction::Start: without time stamps the speed's sign picks the
        // way the entity faces (against the path when reversing), and that sign is kept for
        // the whole action.
        let speed_sign = if timing.is_none() && entity_speed < 0.0 { -1.0 } else { 1.0 };
        if speed_sign < 0.0 && explicit_headings(traj) {
            // esmini then faces the entity as the vertices say and moves it by sign(speed)
            // against that (IsHSetExplicitly): along a path whose headings point forward it
            // backs off the start and the action ends at once.
            self.warn_action(
                slot,
                format!("FollowTrajectoryAction: trajectory `{}` is started reversing and its vertices give headings; esmini's motion along explicit vertex headings is not modelled (the entity faces against the path and advances along it)", traj.name),
            );
        }
        let p = path.pose_at(s);
        let heading = p.heading + if speed_sign < 0.0 { std::f64::consts::PI } else { 0.0 };
        let start_speed = timing.map(|_| start_speed(&path, s));
        let net = self.net;
        let en = &mut self.entities[e];
        en.set_world(net, p.x, p.y, None, heading);
        if let Some(v) = start_speed {
            en.speed = speed_sign * v;
        }
        let accel = if timing.is_some() && mode == FollowingMode::Follow { accel_segments(&path) } else { None };
        ActionRt::FollowTrajectory(Box::new(FollowTrajectoryRt { path, s, timing, time, accel, heading_sign: speed_sign, elevated: elevated(traj) }))
    }

    pub(super) fn step_follow_trajectory(&mut self, e: usize, f: &mut FollowTrajectoryRt) -> bool {
        let dt = self.dt;
        let sim_time = self.time;
        let ghost_offset = self.ghost.as_ref().filter(|g| g.entity == e).map_or(0.0, |g| g.headstart);
        let Some(en) = self.entities.get(e) else { return true };
        let speed = en.speed;
        let old_s = f.s;
        let len = f.path.length();
        let mut new_speed = speed;
        // esmini's FollowTrajectoryAction::Move: without time stamps the entity moves along the
        // path in the direction sign(speed) × the heading sign fixed at the start (esmini's SIGN:
        // zero counts as positive). Started reversing, it advances along the path while its
        // speed stays negative and comes back once the speed turns positive.
        let direction = if speed < 0.0 { -1.0 } else { 1.0 } * f.heading_sign;
        match f.timing {
            None => {
                f.s = move_s(&f.path, f.s, direction * speed.abs() * dt);
            }
            Some(m) => {
                match m.domain {
                    TimeDomain::Relative => f.time += m.scale * dt,
                    // esmini's FollowTrajectoryAction::Move: a ghost reads absolute time stamps
                    // its head start later (timeOffset), so it is where its entity will be.
                    TimeDomain::Absolute => f.time = (sim_time + dt) * m.scale + ghost_offset,
                }
                f.s = f.s_at_time(f.time + m.offset).unwrap_or(f.s);
                let end = f.path.time_range().map_or(0.0, |r| r.1);
                if dt > SMALL && f.time + m.offset < end + SMALL {
                    new_speed = (f.s - old_s).abs() / dt;
                }
            }
        }
        let done = match f.timing {
            // esmini's FollowTrajectoryAction::Step: the end ahead, or the start when moving back.
            None => !f.path.is_closed() && dt > 0.0 && speed != 0.0 && ((direction > 0.0 && f.s > len - SMALL) || (direction < 0.0 && f.s < SMALL)),
            // Summed steps drift below the last stamp by rounding; esmini's sum reaches it.
            Some(_) => f.path.time_range().is_some_and(|r| f.time >= r.1 - 1e-9),
        };
        // A timed path that ends leaves the entity at its end, also when it is marked closed.
        let at_end = done && f.timing.is_some() && f.path.is_closed() && f.s >= len - SMALL;
        let p = if at_end { f.path.end_pose() } else { f.path.pose_at(f.s) };
        let (mut x, mut y) = (p.x, p.y);
        // The entity keeps facing the way it faced at the start (esmini's Move: turned by π
        // while the initial heading sign is negative), whatever the speed's sign now.
        let heading = if f.heading_sign < 0.0 { p.heading + std::f64::consts::PI } else { p.heading };
        if done {
            // The rest of the step's distance continues along the final heading.
            let rest = match f.timing {
                None => speed.abs() * dt - (f.s - old_s).abs(),
                Some(_) => (f.time - f.path.time_range().map_or(0.0, |r| r.1)).max(0.0) * new_speed,
            };
            x += rest * p.heading.cos();
            y += rest * p.heading.sin();
        }
        let net = self.net;
        let en = &mut self.entities[e];
        en.set_world(net, x, y, None, heading);
        en.speed = new_speed;
        en.moved_by_action = true;
        done
    }
}

/// Whether a polyline vertex of `traj` gives a heading of its own.
fn explicit_headings(traj: &Trajectory) -> bool {
    use openscenario::Position as P;
    match &traj.shape {
        openscenario::Shape::Polyline(vs) => vs.iter().any(|v| match &v.position {
            P::World { h, .. } => h.is_some(),
            P::RelativeWorld { orientation, .. }
            | P::RelativeObject { orientation, .. }
            | P::Road { orientation, .. }
            | P::RelativeRoad { orientation, .. }
            | P::Lane { orientation, .. }
            | P::RelativeLane { orientation, .. } => orientation.is_some_and(|o| o.h.is_some()),
            _ => false,
        }),
        _ => false,
    }
}

/// Whether a polyline vertex of `traj` gives a height of its own.
fn elevated(traj: &Trajectory) -> bool {
    use openscenario::Position as P;
    match &traj.shape {
        openscenario::Shape::Polyline(vs) => vs.iter().any(|v| match &v.position {
            P::World { z, .. } => z.is_some(),
            P::RelativeWorld { dz, .. } | P::RelativeObject { dz, .. } => dz.is_some(),
            _ => false,
        }),
        _ => false,
    }
}

/// Move `ds` along the path: wrapped on a closed path, clamped on an open one.
fn move_s(path: &Path, s: f64, ds: f64) -> f64 {
    if path.is_closed() {
        path.normalize_s(s + ds)
    } else {
        (s + ds).clamp(0.0, path.length())
    }
}

/// Speed along the first timed segment at or after arc length `s`.
fn start_speed(path: &Path, s: f64) -> f64 {
    let Some(tt) = path.time_table() else { return 0.0 };
    let pts = tt.points();
    for w in pts.windows(2) {
        if let [a, b] = w {
            if b.0 > s - SMALL && b.1 > a.1 + SMALL {
                return (b.0 - a.0) / (b.1 - a.1);
            }
        }
    }
    0.0
}
