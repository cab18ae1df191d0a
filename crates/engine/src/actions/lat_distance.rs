//! LateralDistanceAction: keep a lateral distance to the left or right of a reference entity,
//! in the road coordinate system (t along the road) or the reference's own (entity).
//!
//! As esmini: the first step only records the position (the default controller moves the
//! entity). Then the distance error is the wanted t (reference t ± distance, ± half the two
//! widths with freespace) minus the actor's t, the reference's t and the side as seen through
//! the road path between them (`lat_state`, `roads/road_path.rs`). Without any limit the actor jumps onto it (onto the road and lane the point lies in); with
//! only a maximum speed it moves sideways at min(max speed, speed) until the error changes
//! sign; with a maximum acceleration a critically damped spring (stiffness 0.4 × the limit)
//! pulls the lateral velocity, its acceleration clipped to the limit and the lateral speed to
//! min(max speed, speed). Moving so, the actor keeps its lane id (the offset grows past the lane), moves
//! along the road by √(v² − v_lat²)·dt, and heads along its displacement. A non-continuous
//! action ends when the error is below 0.01 m. The entity coordinate system (the reference's
//! own axes, esmini's `CS_ENTITY` branch) is in `entity_frame.rs`; in the lane, trajectory and
//! world systems esmini 3.6's LatDistanceAction::Step does nothing and never ends, which is
//! what we do, with a warning.

pub(crate) mod entity_frame;
pub(crate) mod state;

use entity_frame::{entity_frame_step, Pose};
use state::{Frame, LatDistanceKept, LatDistanceRt, Phase};

use super::dynamic_constraints::{limits, Performance};
use super::state::{ActionRt, Kept};
use crate::angles::wrap;
use crate::roads::lane_geometry::lane_center_t;
use crate::roads::lane_snap;
use crate::roads::move_along_route_drawing;
use crate::roads::road_path::path_ends;
use crate::sim::Sim;
use opendrive::ContactPoint;
use openscenario::{CoordinateSystem, DynamicConstraints, LateralDisplacement};
use std::f64::consts::FRAC_PI_2;

const LARGE: f64 = super::dynamic_constraints::UNLIMITED;
const SPRING: f64 = 0.4;
/// Distance error below which a non-continuous action is done, m.
const THRESHOLD: f64 = 0.01;

/// The lateral action's parameters as the model gives them.
pub(crate) struct LatDistanceSpec<'s> {
    pub entity: &'s str,
    pub distance: Option<f64>,
    pub freespace: bool,
    pub continuous: bool,
    pub coordinate_system: Option<CoordinateSystem>,
    pub displacement: Option<LateralDisplacement>,
    pub constraints: Option<&'s DynamicConstraints>,
}

impl<'a> Sim<'a> {
    pub(super) fn start_lat_distance(&mut self, slot: usize, e: usize, spec: &LatDistanceSpec) -> ActionRt {
        let Some(target) = self.entity_index(spec.entity) else {
            self.warn_action(slot, format!("LateralDistanceAction: unknown entity `{}`", spec.entity));
            return ActionRt::Done;
        };
        let frame = match spec.coordinate_system.unwrap_or(CoordinateSystem::Entity) {
            CoordinateSystem::Road => Frame::Road,
            CoordinateSystem::Entity => Frame::Entity,
            other => {
                self.warn_action(
                    slot,
                    format!("LateralDistanceAction: coordinate system `{other:?}` is not supported (nor by esmini 3.6, which then leaves the entity to its default controller): the action runs without effect"),
                );
                Frame::Idle
            }
        };
        let (Some(a), Some(b)) = (self.entities.get(e), self.entities.get(target)) else { return ActionRt::Done };
        // ScenarioReader::parseOSCPrivateAction: before 1.1 esmini reads no displacement and
        // keeps the distance's sign; from 1.1 on it takes its magnitude, and a missing
        // displacement is "any", which LatDistanceAction::Start takes as left.
        let displacement = if self.scenario.header.rev_minor < 1 {
            Displacement::Unread
        } else if spec.displacement == Some(LateralDisplacement::RightToReferencedEntity) {
            Displacement::Right
        } else {
            Displacement::Left
        };
        let kept = match self.actions.get(slot).and_then(|s| s.kept_for(e)) {
            Some(Kept::LatDistance(k)) => k,
            _ => {
                let distance = spec.distance.unwrap_or(0.0);
                let distance = if displacement == Displacement::Unread { distance } else { distance.abs() };
                LatDistanceKept { distance, sign: 0.0, lat_vel: 0.0, acceleration: 0.0 }
            }
        };
        let half_widths = if spec.freespace { (a.bbox[4] + b.bbox[4]) / 2.0 } else { 0.0 };
        let (esmini_distance, esmini_sign) = esmini_start(kept.distance, kept.sign, frame, displacement, half_widths);
        // Our wanted t is + to the left; esmini's road-frame distance is − to the left.
        let wanted = if frame == Frame::Road { -esmini_distance } else { esmini_distance };
        // ScenarioReader::parseDynamicConstraints without an entity: a missing limit is none.
        let c = limits(spec.constraints, Performance::NONE);
        let (max_acc, max_speed, max_dec) = (c.acc, c.speed, c.dec);
        ActionRt::LatDistance(Box::new(LatDistanceRt {
            slot,
            target,
            frame,
            wanted,
            continuous: spec.continuous,
            max_acc,
            max_acc_rate: c.acc_rate,
            max_speed,
            rigid: max_speed >= LARGE && max_acc >= LARGE && max_dec >= LARGE,
            phase: Phase::Init,
            lat_vel: kept.lat_vel,
            acceleration: kept.acceleration,
            old: (a.x, a.y),
            esmini_distance,
            esmini_sign,
        }))
    }

    /// (actor t, reference t as seen from the actor's road, sign of the wanted side, reference
    /// lateral velocity); `None` off the roads or when no road path joins the two.
    ///
    /// esmini's LatDistanceAction::GetDistanceError over Position::Delta, which runs from the
    /// reference to the actor: the reference's t changes sign where the path turns the lane ids
    /// around (RoadPath lane mapping). The two count as driving the same way when the
    /// reference's facing equals the actor's — where the reference's facing is, across roads,
    /// "forward" exactly when the path leaves the last road before the actor's by its start —
    /// turned around when the path starts behind the reference (RoadPath::Calculate's
    /// direction −1). The wanted side keeps its sign when the actor faces forward on its road
    /// exactly when they drive the same way.
    fn lat_state(&self, e: usize, r: &LatDistanceRt) -> Option<(f64, f64, f64, f64)> {
        let net = self.net?;
        let a_en = self.entities.get(e)?;
        let a = a_en.lane?;
        let b_en = self.entities.get(r.target)?;
        let b = b_en.lane?;
        let t_of = |p: &crate::roads::LanePos| net.roads.get(p.road).and_then(|rd| lane_center_t(rd, p.lane_id, p.s)).map(|c| c + p.offset);
        let forward = |h: f64, p: &crate::roads::LanePos| p.pose(net).is_some_and(|q| is_angle_forward(h - q.road_heading));
        // esmini's lateral velocity of the reference is taken in its own frame (≈ 0 for a
        // vehicle, even during a lane change: it moves along its heading).
        let vel_lat = -b_en.vel.0 * b_en.h.sin() + b_en.vel.1 * b_en.h.cos();
        let (ta, tb) = (t_of(&a)?, t_of(&b)?);
        let ref_forward = forward(b_en.h, &b);
        let actor_forward = forward(a_en.h, &a);
        let (ref_t, same_direction) = if a.road == b.road {
            (tb, ref_forward == actor_forward)
        } else {
            let path = path_ends(net, b.road, b.s, b.lane_id, a.road)?;
            // Position::Delta: lanes of A mapped along the path to B's road.
            let ref_t = if path.dt_flips(net, a.road, a.s, b.lane_id) { -tb } else { tb };
            let a_forward = path.last_exit == ContactPoint::Start;
            // RoadPath::Calculate's direction: the path starts ahead of A (leaves A's road by
            // the end A faces) or behind it.
            let ahead = (path.first_exit == ContactPoint::End) == ref_forward;
            (ref_t, (a_forward == actor_forward) == ahead)
        };
        let side = if actor_forward == same_direction { 1.0 } else { -1.0 };
        Some((ta, ref_t, side, vel_lat))
    }

    pub(super) fn step_lat_distance(&mut self, e: usize, r: &mut LatDistanceRt) -> bool {
        match r.frame {
            Frame::Road => self.step_lat_distance_road(e, r),
            Frame::Entity => {
                self.step_lat_distance_entity(e, r);
                false
            }
            Frame::Idle => false,
        }
    }

    /// The entity coordinate system (`entity_frame.rs`): the actor is put where esmini's step
    /// puts it, facing as it says, and attached to the lane it is over.
    fn step_lat_distance_entity(&mut self, e: usize, r: &LatDistanceRt) {
        let (Some(a), Some(b)) = (self.entities.get(e), self.entities.get(r.target)) else { return };
        let actor = Pose { x: a.x, y: a.y, h: crate::entities::position_heading_by_mode(self.net, a) };
        let reference = Pose { x: b.x, y: b.y, h: crate::entities::position_heading_by_mode(self.net, b) };
        let to = entity_frame_step(actor, reference, r.wanted, a.speed, r.max_acc, LARGE, self.dt);
        let net = self.net;
        let Some(en) = self.entities.get_mut(e) else { return };
        let z = if net.is_some() { None } else { Some(en.z) };
        en.set_world(net, to.x, to.y, z, to.h);
        en.moved_by_action = true;
        // Position::SetInertiaPos: ScenarioEngine::step then stops only one stuck past the end.
        if let Some(net) = net {
            en.set_end_status_from_world(net);
        }
    }

    fn step_lat_distance_road(&mut self, e: usize, r: &mut LatDistanceRt) -> bool {
        let dt = self.dt;
        let Some(net) = self.net else { return true };
        let Some((ta, tb, side, vel_lat)) = self.lat_state(e, r) else {
            // esmini's GetDistanceError: no road path between the two ends the action.
            self.warn_action(r.slot, "LateralDistanceAction: no road path joins the actor and the reference; the action ends".into());
            return true;
        };
        let Some(en) = self.entities.get_mut(e) else { return true };
        let Some(mut lp) = en.lane else { return true };
        let error = tb + side * r.wanted - ta;
        match r.phase {
            Phase::Init => {
                r.phase = if r.rigid { Phase::Rigid } else { Phase::Dynamic };
                r.old = (en.x, en.y);
                return false;
            }
            Phase::Rigid => {
                // LatDistanceAction::GetDesiredRoadPos: the point `error` across the road
                // heading from where the actor is, looked up afresh (XYZ2TrackPos on a new
                // Position: the nearest road, snapped to its nearest driving lane), whose
                // road, lane, s and offset the actor takes — near a junction another road.
                let mut desired = None;
                if let Some(q) = lp.pose(net) {
                    // GetRoadH: Geometry::EvaluateDS's heading from GetHdg, the file's hdg in
                    // [0, 2π) (GetAngleInInterval2PI): its sine and cosine to esmini's bits.
                    // (the reference line's own heading: no turn from a changing superelevation)
                    let h_ref = lp.reference_heading(net).unwrap_or(q.road_heading);
                    let h_road = crate::angles::wrap_2pi(h_ref);
                    let (x, y) = (en.x - h_road.sin() * error, en.y + h_road.cos() * error);
                    desired = Some((x, y));
                    if let Some(p) = crate::roads::locate::world_to_lane(net, x, y, None) {
                        let (lane_id, offset) = lane_snap::snap_located(net, &p, false);
                        let dir = if is_angle_forward(en.h - p.heading) { 1.0 } else { -1.0 };
                        lp = crate::roads::LanePos { road: p.road, lane_id, s: p.s, offset, dir };
                    }
                }
                en.set_lane_pos(net, lp);
                let done = !r.continuous && error.abs() < THRESHOLD;
                // The heading is the direction to the desired point as XYZ2TrackPos holds it
                // (the point as given, not the lane position taken from it): across a road
                // along x that is exactly a right angle, which IsAngleForward counts as forward.
                let to = desired.unwrap_or((en.x, en.y));
                Self::head_along(net, en, r, to);
                return done;
            }
            Phase::Dynamic => {}
        }
        let mut done = false;
        // esmini keeps SMALL_NUMBER (1e-6) of longitudinal speed when the lateral speed is capped
        let speed_cap = r.max_speed.min(en.speed) - crate::dynamics::ESMINI_SMALL_NUMBER;
        if r.max_acc < LARGE {
            let k = SPRING * r.max_acc;
            let a_spring = k * error - 2.0 * k.sqrt() * (r.lat_vel - vel_lat);
            let da = (a_spring - r.acceleration).clamp(-r.max_acc_rate * dt, r.max_acc_rate * dt);
            r.acceleration = (r.acceleration + da).clamp(-r.max_acc, r.max_acc);
            r.lat_vel = (r.lat_vel + r.acceleration * dt).clamp(-speed_cap.abs(), speed_cap.abs());
            done = !r.continuous && error.abs() < THRESHOLD;
        } else {
            r.lat_vel = if error < 0.0 { -speed_cap } else { speed_cap };
            let d = r.lat_vel * dt;
            if (error - d < 0.0) != (error < 0.0) {
                r.lat_vel = if dt > 0.0 { error / dt } else { 0.0 };
                done = !r.continuous;
            }
        }
        let long_vel = (en.speed * en.speed - r.lat_vel * r.lat_vel).max(0.0).sqrt();
        // Object::MoveAlongS moves in the heading's direction (MoveDirectionMode::
        // HEADING_DIRECTION: IsAngleForward of the heading relative to the road), and the
        // heading is the last step's displacement: stuck at a dead end, the offset alone moves
        // the entity, its heading turns across the road and it may drive back the other way.
        if let Some(q) = lp.pose(net) {
            lp.dir = if is_angle_forward(en.h - q.road_heading) { 1.0 } else { -1.0 };
        }
        // Object::MoveAlongS as the default controller's move: along an assigned route at a
        // junction, a tie of arms decided by esmini's generator.
        let pedestrian = en.kind == crate::entities::EntityKind::Pedestrian;
        move_along_route_drawing(net, &mut lp, long_vel * dt, en.route.as_deref(), &mut self.random, pedestrian);
        lp.offset += r.lat_vel * dt;
        en.set_lane_pos(net, lp);
        let to = (en.x, en.y);
        Self::head_along(net, en, r, to);
        en.moved_by_action = true;
        done
    }

    /// esmini's SetHeading(atan2 of the displacement since the last step): an absolute
    /// heading, so the angle it makes with the road stays through the default controller's
    /// move in this step (a rigid jump's row faces along the jump, and a lateral speed
    /// condition sees none) and after the action, until something turns the entity again.
    /// Without any displacement here esmini's is a rounding error whose atan2 we cannot
    /// reproduce; the heading is kept. `to`: the point the displacement ends at (the entity's
    /// position, or the point a rigid jump aimed at).
    fn head_along(net: &opendrive::RoadNetwork, en: &mut crate::entities::Entity, r: &mut LatDistanceRt, to: (f64, f64)) {
        let (dx, dy) = (to.0 - r.old.0, to.1 - r.old.1);
        if dx * dx + dy * dy > 0.0 {
            en.set_heading_on_lane(net, dy.atan2(dx));
        }
        r.old = (en.x, en.y);
    }
}

/// The side LatDistanceAction::Start reads from the displacement.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Displacement {
    Left,
    Right,
    /// Before 1.1 (DisplacementType::NONE): neither side; the distance keeps its sign.
    Unread,
}

/// LatDistanceAction::Start on the distance and side sign its object holds (the parsed
/// distance at the first execution, what the last Start left at the next): in the entity frame
/// the freespace half-widths are added, then the sign turned for the right side; in the road
/// frame the distance is made negative for the left side (positive for the right) and the
/// half-widths added on that side. Start changes the object's own distance, so an event
/// executed again adds the half-widths again.
fn esmini_start(distance: f64, sign: f64, frame: Frame, displacement: Displacement, half_widths: f64) -> (f64, f64) {
    match frame {
        Frame::Entity => {
            let d = distance + half_widths;
            (if displacement == Displacement::Right { -d } else { d }, sign)
        }
        Frame::Road => {
            let (d, sign) = match displacement {
                Displacement::Left => (-distance.abs(), -1.0),
                Displacement::Right => (distance.abs(), 1.0),
                Displacement::Unread => (distance, sign),
            };
            (d + sign * half_widths, sign)
        }
        Frame::Idle => (distance, sign),
    }
}

/// esmini's IsAngleForward: an angle not strictly between π/2 and 3π/2 (after wrapping).
fn is_angle_forward(angle: f64) -> bool {
    wrap(angle).abs() <= FRAC_PI_2
}
