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
use crate::angles::wrap;
use crate::dynamics::{ESMINI_SMALL_NUMBER, SMALL};
use crate::sim::Sim;
use openscenario::{FollowingMode, ReferenceContext, TimeReference, Trajectory};
use trajectory::{Interpolation, Path, Pose, TimeDomain, TimeMapping};

impl FollowTrajectoryRt {
    fn s_at_time(&self, t: f64) -> Option<f64> {
        match &self.vertices {
            Some(v) if !self.path.is_closed() => Some(polyline_s_at_time(v, self.path.length(), t)),
            // esmini evaluates a clothoid (spline) at a time outside [start, end] at its end,
            // saying "Requested time … outside range": an offset that puts the time before the
            // first stamp parks the entity at the far end until the time comes in range.
            _ if self.end_outside_times && self.path.time_range().is_some_and(|(a, b)| !(t >= a && t <= b)) => Some(self.path.length()),
            // esmini's ClothoidShape::Evaluate takes the start time off twice: with a start time
            // above zero the entity waits at the path's start (Spiral::EvaluateDS clamps) until
            // the time reaches twice the start time, and the stop time comes before the end.
            _ => match self.clothoid_times.filter(|(a, b)| b - a > 0.0) {
                Some((a, b)) => Some(self.path.length() * (t - 2.0 * a) / (b - a)),
                None => self.path.s_at_time(t),
            },
        }
    }
}

use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;

/// esmini's SIGN: zero counts as positive.
fn esmini_sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// A timed polyline's vertices as esmini's PolyLineShape::CalculatePolyLine times them:
/// (s, t, speed, acceleration towards the next). `follow` mode: the speed starts at the
/// entity's (`initial_speed`) and stays continuous, each segment at a constant acceleration; a
/// segment that would turn the speed's sign (too much time for its distance) brakes to a stop
/// at its end instead (a = −v²/2d, arriving early); a segment without distance stops the
/// entity. `position` mode: each vertex at its segment's mean speed, no acceleration, the
/// last vertex at rest.
fn polyline_timing(path: &Path, follow: bool, initial_speed: f64) -> Option<Vec<(f64, f64, f64, f64)>> {
    let pts = path.time_table()?.points();
    let mut out: Vec<(f64, f64, f64, f64)> = pts.iter().map(|&(s, t)| (s, t, 0.0, 0.0)).collect();
    if follow {
        let mut v = initial_speed;
        if let Some(first) = out.first_mut() {
            first.2 = v;
        }
        for i in 1..out.len() {
            let (d, dt) = (out[i].0 - out[i - 1].0, out[i].1 - out[i - 1].1);
            let mut acc = 0.0;
            if d.abs() > SMALL_NUMBER {
                acc = 2.0 * (d - v * dt) / (dt * dt);
                if esmini_sign(v + acc * dt) != esmini_sign(v) {
                    acc = -(v * v) / (2.0 * d);
                    v = 0.0;
                } else {
                    v += acc * dt;
                }
            } else {
                v = 0.0;
            }
            out[i - 1].3 = if acc.is_finite() { acc } else { 0.0 };
            out[i].2 = if v.is_finite() { v } else { 0.0 };
        }
    } else {
        for i in 0..out.len().saturating_sub(1) {
            let (d, dt) = (out[i + 1].0 - out[i].0, out[i + 1].1 - out[i].1);
            out[i].2 = if dt > SMALL_NUMBER { d / dt } else { 0.0 };
        }
    }
    Some(out)
}

/// esmini's PolyLineShape::Evaluate by time `t`: past the last vertex's time the end; else the
/// first vertex whose next one is not earlier than `t` (walking the vertices as written),
/// moved on by its speed and acceleration — stopping where a braking speed reaches zero. The
/// distance is not held to the vertex's segment: a vertex that starts a stand-still with
/// speed left moves on at that speed until the next stamp (esmini's), then the entity jumps
/// back to where the stamps put it.
fn polyline_s_at_time(v: &[(f64, f64, f64, f64)], length: f64, t: f64) -> f64 {
    let Some(last) = v.last() else { return 0.0 };
    if t > last.1 {
        return length;
    }
    let ordered = v.windows(2).all(|w| w[0].1 <= w[1].1);
    let i = if ordered { v[1..].partition_point(|q| q.1 < t) } else { v[1..].iter().take_while(|q| q.1 < t).count() };
    let Some(&(s0, t0, v0, a)) = v.get(i) else { return last.0 };
    let mut tau = (t - t0).max(0.0);
    if a < 0.0 {
        tau = tau.min(-v0 / a);
    }
    (s0 + v0 * tau + 0.5 * a * tau * tau).clamp(0.0, length)
}

/// Build a trajectory's path from the current state of the run.
pub(crate) fn build_path(sim: &Sim, slot: usize, traj: &Trajectory, current: Pose) -> Result<Path, String> {
    let net = sim.net;
    let entities = &sim.entities;
    // A trajectory handed over to a ghost reads a polyline's vertices and a clothoid's start
    // relative to the ghost where they are relative to its entity (FollowTrajectoryAction::
    // ReplaceObjectRefs covers only these two shapes).
    let handed_over = matches!(traj.shape, openscenario::Shape::Polyline(_) | openscenario::Shape::Clothoid { .. });
    let resolver = |p: &openscenario::Position| match sim.action_ref_position(slot, p).filter(|_| handed_over) {
        Some(q) => crate::trajectory_position::vertex_pose(&q, net, entities),
        None => crate::trajectory_position::vertex_pose(p, net, entities),
    };
    let place = |p: Pose| crate::trajectory_position::placed_pose(net, p);
    Path::from_trajectory_placed(traj, current, &resolver, &place).map_err(|e| e.to_string())
}

impl<'a> Sim<'a> {
    /// The trajectory entity `e` follows now, if any: esmini's `Position::GetTrajectory`, set
    /// while a FollowTrajectoryAction of the entity runs (FollowTrajectoryAction::Start, End).
    pub(crate) fn running_trajectory(&self, e: usize) -> Option<&FollowTrajectoryRt> {
        self.actions.iter().filter(|a| a.running).flat_map(|a| a.instances.iter()).find_map(|inst| match &inst.rt {
            ActionRt::FollowTrajectory(f) if inst.entity == Some(e) => Some(&**f),
            _ => None,
        })
    }

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
        let path = match build_path(self, slot, traj, current) {
            // esmini's FollowTrajectoryAction::Start: a polyline's heading turns over whole
            // segments in the `follow` mode, across corners only in the `position` mode.
            Ok(mut p) => {
                p.set_interpolation(if mode == FollowingMode::Follow { Interpolation::Segment } else { Interpolation::Corner });
                p
            }
            Err(msg) => {
                self.warn_action(slot, format!("FollowTrajectoryAction: trajectory `{}` cannot be followed: {msg}", traj.name));
                return ActionRt::Done;
            }
        };
        for w in &path.warnings {
            let msg = format!("trajectory `{}`: {w}", traj.name);
            self.warn_action(slot, msg);
        }
        let span = path.time_range().map_or(0.0, |r| r.1 - r.0);
        let timing = match time_ref {
            // esmini's ScenarioReader: a trajectory whose stamps span no time is followed without
            // its time reference.
            TimeReference::Timing { .. } if path.is_timed() && span < SMALL_NUMBER => {
                self.warn_action(
                    slot,
                    format!("FollowTrajectoryAction: trajectory `{}` spans no time; its time reference is ignored, as esmini ignores it", traj.name),
                );
                None
            }
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
        // esmini's trajectory time at the start s: at (or within SMALL_NUMBER of) a polyline's end
        // it is the last vertex's time (PolyLineBase::Evaluate), so a path without length
        // that is timed relatively is over at once.
        let at_end = path.is_polyline() && s > path.length() - SMALL_NUMBER;
        let time = if at_end { path.time_range().map_or(0.0, |r| r.1) } else { time_at_start(traj, &path, s).unwrap_or(0.0) };
        // esmini's FollowTrajectoryAction::Start: without time stamps the speed's sign picks the
        // way the entity faces (against the path when reversing), and that sign is kept for
        // the whole action.
        let speed_sign = if timing.is_none() && entity_speed < 0.0 { -1.0 } else { 1.0 };
        // Started reversing on a polyline whose first vertex gives its heading, esmini faces the
        // entity as the vertices say (IsHSetExplicitly: the mode of the vertex the first
        // segment starts at) and takes its motion's sign from how that heading lies to the path
        // (initialHeadingSign_: against it when more than π/2 off): along a path whose headings
        // point forward the entity backs off the start and the action ends at once.
        let VertexHeadings { some: some_headings, all: all_headings, first: first_heading } = vertex_headings(traj);
        // The vertex the start lies on gives the heading (esmini's IsHSetExplicitly).
        let heading_given_at_start = all_headings || (s == 0.0 && first_heading);
        let faces_vertex_headings = speed_sign < 0.0 && heading_given_at_start;
        if speed_sign < 0.0 && some_headings && !all_headings {
            let how = if faces_vertex_headings {
                "the entity faces as its first vertex says and moves by how that heading lies to the path"
            } else {
                "the entity faces against the path and advances along it"
            };
            self.warn_action(
                slot,
                format!("FollowTrajectoryAction: trajectory `{}` is started reversing and some of its vertices give headings; esmini's motion along partly explicit vertex headings is not modelled where they change ({how})", traj.name),
            );
        }
        // A timed polyline is timed vertex by vertex (PolyLineShape::CalculatePolyLine); the other
        // shapes' time runs linearly with their length.
        let vertices = if timing.is_some() && path.is_polyline() { polyline_timing(&path, mode == FollowingMode::Follow, entity_speed) } else { None };
        let start_speed = timing.map(|_| start_speed(s, vertices.as_deref()));
        let p = path.pose_at(s);
        // esmini's Start: a timed trajectory's speed takes its sign from how the heading its
        // vertices give lies to the path (speedSign, only where the heading is explicit).
        let timed_sign = if heading_given_at_start { facing_sign(p.heading, path.true_heading_reaching(s)) } else { 1.0 };
        let (heading, heading_sign) = if faces_vertex_headings {
            (p.heading, facing_sign(p.heading, path.true_heading_at(s)))
        } else {
            (p.heading + if speed_sign < 0.0 { std::f64::consts::PI } else { 0.0 }, speed_sign)
        };
        self.place_on_trajectory(e, p.x, p.y, heading);
        let net = self.net;
        let en = &mut self.entities[e];
        en.placed_end_status = net.and_then(|n| en.end_status_from_world(n));
        if let Some(v) = start_speed {
            // Object::SetSpeed marks the speed as set (SPEED dirty bit): prepareGroundTruth
            // derives none from the placement jump, also when the action ends in this step.
            // A timed path whose vertex headings face against it starts with a negative speed.
            en.speed = timed_sign * v;
            en.speed_set = true;
        }

        let clock = esmini_clock(self.time_origin(), self.dt, self.time);
        let end_outside_times = matches!(traj.shape, openscenario::Shape::Clothoid { .. } | openscenario::Shape::ClothoidSpline { .. });
        let clothoid_times = match (&traj.shape, path.time_range()) {
            (openscenario::Shape::Clothoid { .. }, Some(r)) => Some(r),
            _ => None,
        };
        ActionRt::FollowTrajectory(Box::new(FollowTrajectoryRt {
            path,
            s,
            timing,
            time,
            clock,
            vertices,
            heading_sign,
            faces_vertex_headings,
            elevated: elevated(traj),
            end_outside_times,
            clothoid_times,
            true_heading_at: None,
        }))
    }

    pub(super) fn step_follow_trajectory(&mut self, e: usize, f: &mut FollowTrajectoryRt) -> bool {
        let dt = self.dt;
        let ghost_offset = self.ghost.as_ref().filter(|g| g.entity == e).map_or(0.0, |g| g.headstart);
        let Some(en) = self.entities.get(e) else { return true };
        let speed = en.speed;
        let old_s = f.s;
        let len = f.path.length();
        let mut new_speed = speed;
        let mut raw_s = None;
        // esmini's FollowTrajectoryAction::Move: without time stamps the entity moves along the
        // path in the direction sign(speed) × the heading sign fixed at the start (esmini's SIGN:
        // zero counts as positive). Started reversing, it advances along the path while its
        // speed stays negative and comes back once the speed turns positive.
        let direction = if speed < 0.0 { -1.0 } else { 1.0 } * f.heading_sign;
        // esmini's Move: while a controller in override mode holds the longitudinal domain (an
        // ACC in override mode), a timed trajectory is followed as an untimed one, at the
        // entity's speed: its clock stands still (so its time stamps never end it) and the
        // speed stays the controller's.
        let speed_held = f.timing.is_some() && self.long_domain_overridden(e);
        let heading_direction = if f.timing.is_some() {
            let true_heading = match f.true_heading_at {
                Some((s, h)) if s.to_bits() == old_s.to_bits() => h,
                _ => f.path.true_heading_reaching(old_s),
            };
            facing_sign(en.h, true_heading)
        } else {
            1.0
        };
        match f.timing.filter(|_| !speed_held) {
            None => {
                let ds = direction * speed.abs() * dt;
                // esmini's PolyLineBase::Evaluate keeps an s below a polyline's start as it is
                // (the pose stays at the first vertex): backing off the start leaves no distance
                // over for the step's rest.
                if f.path.is_polyline() && !f.path.is_closed() && f.s + ds < 0.0 {
                    raw_s = Some(f.s + ds);
                }
                f.s = move_s(&f.path, f.s, ds);
            }
            Some(m) => {
                match m.domain {
                    TimeDomain::Relative => f.time += m.scale * dt,
                    // esmini's FollowTrajectoryAction::Move: a ghost reads absolute time stamps
                    // its head start later (timeOffset), so it is where its entity will be.
                    TimeDomain::Absolute => f.time = (f.clock + dt) * m.scale + ghost_offset,
                }
                f.s = f.s_at_time(f.time + m.offset).unwrap_or(f.s);
                let end = f.path.time_range().map_or(0.0, |r| r.1);
                // esmini's Move updates the speed while the trajectory time (relative: with
                // the offset; absolute: without it) has not passed the last stamp.
                let reached = match m.domain {
                    TimeDomain::Relative => f.time + m.offset,
                    TimeDomain::Absolute => f.time,
                };
                if dt > ESMINI_SMALL_NUMBER && reached < end + ESMINI_SMALL_NUMBER {
                    // Relative timing takes the speed's sign from the way s moved (esmini's
                    // movingDirection_ = SIGN(Δs)); absolute timing keeps it positive. Both
                    // turn it when the entity, before the move, faced more than π/2 away from
                    // the path where it stood (headingDirection: vertices whose headings point
                    // against the path, or a polyline turning back further than the entity).
                    let sign = match m.domain {
                        TimeDomain::Relative => esmini_sign(f.s - old_s),
                        TimeDomain::Absolute => 1.0,
                    };
                    new_speed = sign * heading_direction * (f.s - old_s).abs() / dt;
                }
            }
        }
        // esmini's Step ends a timed trajectory when its time plus the offset passes the last
        // stamp (TimeReference offset included).
        let time_offset = f.timing.map_or(0.0, |m| m.offset);
        let done = match f.timing {
            // esmini's FollowTrajectoryAction::Step: the end ahead, or the start when moving back.
            None => {
                !f.path.is_closed()
                    && dt > 0.0
                    && speed != 0.0
                    && ((direction > 0.0 && f.s > len - ESMINI_SMALL_NUMBER) || (direction < 0.0 && f.s < ESMINI_SMALL_NUMBER))
            }
            // esmini's end test, within its SMALL_NUMBER of the last stamp (which also takes
            // summed steps that drift below the stamp by rounding).
            Some(_) => f.path.time_range().is_some_and(|r| f.time + time_offset > r.1 - ESMINI_SMALL_NUMBER),
        };
        // A timed path that ends leaves the entity at its end, also when it is marked closed.
        let at_end = done && f.timing.is_some() && f.path.is_closed() && f.s >= len - SMALL;
        // A clothoid's s may run below zero (clothoid_times); its pose stays at the start.
        let pose_s = if f.clothoid_times.is_some() { f.s.clamp(0.0, len) } else { f.s };
        let p = if at_end { f.path.end_pose() } else { f.path.pose_at(pose_s) };
        f.true_heading_at = (!at_end && !f.path.is_polyline()).then_some((pose_s, p.heading));
        let (mut x, mut y) = (p.x, p.y);
        // The entity keeps facing the way it faced at the start (esmini's Move: turned by π
        // while the initial heading sign is negative), whatever the speed's sign now.
        let heading = if f.heading_sign < 0.0 && !f.faces_vertex_headings { p.heading + std::f64::consts::PI } else { p.heading };
        if done {
            // The rest of the step's distance continues along the final heading.
            let rest = match f.timing {
                None => speed.abs() * dt - (raw_s.unwrap_or(f.s) - old_s).abs(),
                Some(_) => (f.time + time_offset - f.path.time_range().map_or(0.0, |r| r.1)).max(0.0) * new_speed,
            };
            x += rest * p.heading.cos();
            y += rest * p.heading.sin();
        }
        let locked = self.place_on_trajectory(e, x, y, heading);
        let net = self.net;
        let en = &mut self.entities[e];
        // At the trajectory's end the position the default controller goes on from keeps the s
        // esmini's XYZ2TrackPos interpolated on the lane-0 OSI segment, not the exact
        // projection's (before a tight curve the two differ by a metre).
        if done {
            if let (Some(n), Some(lp)) = (net, en.lane) {
                if let Some(found) = crate::roads::locate::world_to_lane_on_segment(n, x, y, en.z, (lp.road, lp.s, lp.lane_id)) {
                    if found.road == lp.road {
                        let sidewalks = en.kind == crate::entities::EntityKind::Pedestrian;
                        let (lane_id, offset) = crate::roads::lane_snap::snap_located(n, &found, sidewalks);
                        // Locked on its lane (looming): the lane stays, the offset is measured from it.
                        let kept = if locked && lane_id != lp.lane_id {
                            n.roads.get(lp.road).and_then(|road| {
                                let section = road.section_index_at(found.s);
                                let snapped = crate::roads::lane_geometry::lane_borders(road, section, lane_id, found.s)?;
                                let held = crate::roads::lane_geometry::lane_borders(road, section, lp.lane_id, found.s)?;
                                Some((lp.lane_id, snapped.center + offset - held.center))
                            })
                        } else {
                            None
                        };
                        let (lane_id, offset) = kept.unwrap_or((lane_id, offset));
                        en.lane = Some(crate::roads::LanePos { lane_id, s: found.s, offset, ..lp });
                    }
                }
            }
        }
        en.placed_end_status = net.and_then(|n| en.end_status_from_world(n));
        en.speed = new_speed;
        en.moved_by_action = true;
        // ScenarioEngine::step, after every move: an entity whose position lies past the end of
        // the road (POS_STATUS_END_OF_ROAD), already flagged there, and that did not move in the
        // last step (its velocity, measured then, is zero) is stopped. A trajectory that ends
        // past a dead end so leaves the entity standing where it is, rather than driving on
        // along the road from the road's end.
        if let (Some(net), Some(_)) = (net, en.lane) {
            en.set_end_status_from_world(net);
            en.stop_if_stuck_at_road_end();
        }
        f.clock += dt;
        done
    }
}

/// −1 when `heading` lies more than π/2 (and esmini's SMALL_NUMBER) from the path's own
/// direction `true_heading`, else +1 (FollowTrajectoryAction's speedSign and headingDirection).
fn facing_sign(heading: f64, true_heading: f64) -> f64 {
    if wrap(heading - true_heading).abs() > std::f64::consts::FRAC_PI_2 + ESMINI_SMALL_NUMBER {
        -1.0
    } else {
        1.0
    }
}

/// esmini's simulation clock at `time`: the steps of `dt` from `origin` summed one by one,
/// with the rounding that sum has (1.49 + 0.01 is 1.5 exactly, the sum of 150 steps of 0.01
/// a hair above), which decides the segment an absolute time stamp falls in.
fn esmini_clock(origin: f64, dt: f64, time: f64) -> f64 {
    if dt <= 0.0 {
        return time;
    }
    let n = ((time - origin) / dt).round().max(0.0) as u64;
    (0..n).fold(origin, |t, _| t + dt)
}

/// The trajectory time esmini reads where the entity is put on the path (RMTrajectory::GetTime
/// after Position::SetTrajectoryS): the time of the shape's one-metre polyline at `s`. A
/// Clothoid's and a ClothoidSpline's polyline times its vertices linearly by their distance,
/// `first + (s_vertex / length) · last` (ClothoidShape and ClothoidSplineShape::
/// CalculatePolyLine), where `last` is the clothoid's stopTime, or the spline's last segment's
/// timeStart (not its timeEnd); the last vertex sits at the whole metres of the length. Only
/// that start time differs from the time the shape is evaluated by (segment by segment), so a
/// relatively timed trajectory started at an initial distance offset jumps back or forth at
/// once; polylines and NURBS time their vertices as the path's time table does.
fn time_at_start(traj: &Trajectory, path: &Path, s: f64) -> Option<f64> {
    let points = path.time_table()?.points();
    let first = points.first()?.1;
    let last = match &traj.shape {
        openscenario::Shape::Clothoid { .. } => points.last()?.1,
        openscenario::Shape::ClothoidSpline { .. } => points.len().checked_sub(2).and_then(|i| points.get(i))?.1,
        _ => return path.time_at(s),
    };
    let length = path.length();
    if length <= 0.0 {
        return Some(first);
    }
    Some(first + s.clamp(0.0, length.floor()) / length * last)
}

/// Which polyline vertices of `traj` give a heading of their own (none for other shapes and
/// an empty polyline). A NURBS curve counts as giving its heading everywhere when its first
/// control point gives one: esmini's NurbsShape::EvaluateInternal takes every evaluated point's
/// position mode from the first control point whose parameter the point has passed, which is
/// always the first, so IsHSetExplicitly answers for the whole curve by it.
struct VertexHeadings {
    some: bool,
    all: bool,
    first: bool,
}

fn vertex_headings(traj: &Trajectory) -> VertexHeadings {
    match &traj.shape {
        openscenario::Shape::Polyline(vs) => {
            let giving = vs.iter().filter(|v| trajectory::gives_heading(&v.position)).count();
            let first = vs.first().is_some_and(|v| trajectory::gives_heading(&v.position));
            VertexHeadings { some: giving > 0, all: giving > 0 && giving == vs.len(), first }
        }
        openscenario::Shape::Nurbs { control_points, .. } => {
            let first = control_points.first().is_some_and(|c| trajectory::gives_heading(&c.position));
            VertexHeadings { some: first, all: first, first }
        }
        _ => VertexHeadings { some: false, all: false, first: false },
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

/// The speed esmini gives the entity when a timed trajectory starts at arc length `s`
/// (FollowTrajectoryAction::Start: RMTrajectory::GetSpeed): a polyline's vertex speeds (from
/// `polyline_timing`) interpolated linearly by s. The other shapes' one-metre polylines never
/// get a speed (ClothoidShape, ClothoidSplineShape and NurbsShape::CalculatePolyLine leave
/// TrajVertex::speed at 0), so they start the entity at rest: a step that moves it sets the
/// speed from the distance, but one that is already past the last stamp leaves it at 0 (no
/// distance left to run on), and a controller holding the longitudinal domain (an ACC) sees
/// the speed drop to 0 and takes that as its new set speed.
fn start_speed(s: f64, vertices: Option<&[(f64, f64, f64, f64)]>) -> f64 {
    let Some(v) = vertices else { return 0.0 };
    let i = v.partition_point(|q| q.0 < s).saturating_sub(1).min(v.len().saturating_sub(1));
    match (v.get(i), v.get(i + 1)) {
        (Some(a), Some(b)) if b.0 - a.0 > SMALL => {
            let u = ((s - a.0) / (b.0 - a.0)).clamp(0.0, 1.0);
            (1.0 - u) * a.2 + u * b.2
        }
        (Some(a), _) => a.2,
        _ => 0.0,
    }
}

impl Sim<'_> {
    /// Puts entity `e` at (x, y) on its trajectory: on its lane when a looming controller has
    /// locked it there (ControllerLooming::Step's SetLockOnLane(true) is never cleared, so
    /// XYZ2TrackPos keeps the lane and measures the offset from it), else as a fresh world
    /// position. Whether it was locked.
    fn place_on_trajectory(&mut self, e: usize, x: f64, y: f64, heading: f64) -> bool {
        let (net, locked) = (self.net, self.lane_locked(e));
        let en = &mut self.entities[e];
        if locked {
            let before = en.lane;
            en.set_world_lane_locked(net, x, y, heading, before);
        } else {
            en.set_world(net, x, y, None, heading);
        }
        locked
    }
}
