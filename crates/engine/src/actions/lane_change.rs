//! LaneChangeAction: the entity's offset, measured from the centre of the target lane, follows
//! the transition shape from where it starts to the target lane offset, over time or distance
//! (a rate is read as a lateral speed). Each step moves the entity by speed·dt split into its
//! lateral and longitudinal parts, turns it by the slope of the path, and re-attaches it to
//! the lane it is actually in; where the shape asks for more sideways motion than speed·dt,
//! the entity moves sideways only, by speed·dt along a straight line (esmini 3.6's fallback).
//! The action ends at the target, or where the road ends.

pub(crate) mod state;

use state::LaneChangeRt;

use super::state::ActionRt;
use crate::dynamics::{sign, Transition, ESMINI_SMALL_NUMBER, SMALL};
use crate::positions::step_lane;
use crate::roads::lane_geometry::{lane_borders, lane_center_t};
use crate::roads::{move_along_s_drawn, LanePos, MoveStatus};
use crate::sim::Sim;
use opendrive::RoadNetwork;
use openscenario::{DynamicsDimension, DynamicsShape, LaneChangeTarget, TransitionDynamics};
use std::f64::consts::FRAC_PI_2;

/// Re-express `lp` in the lane of its road that contains its lateral position.
pub(crate) fn relane(net: &RoadNetwork, lp: &mut LanePos) {
    let Some(road) = net.roads.get(lp.road) else { return };
    let s = lp.s.clamp(0.0, road.length);
    let section = road.section_index_at(s);
    let Some(t) = lane_center_t(road, lp.lane_id, s).map(|c| c + lp.offset) else { return };
    let Some(sec) = road.lane_sections.get(section) else { return };
    for lane in sec.left.iter().chain(sec.right.iter()) {
        if let Some(bo) = lane_borders(road, section, lane.id, s) {
            let (a, b) = (bo.inner, bo.outer);
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            if hi > lo && t >= lo && t <= hi {
                lp.lane_id = lane.id;
                lp.offset = t - bo.center;
                return;
            }
        }
    }
}

/// Re-express `lp` in the lane esmini attaches the entity to after a lane change step without
/// a route (LatLaneChangeAction::Step: Position::XYZ2TrackPos): the lane of the types the entity
/// snaps to that contains its point, else the nearest (roads/lane_snap.rs) — a car steered onto
/// a border lane or a sidewalk stays in the driving lane beside it, at a large offset, and the
/// vehicles in that lane stay ahead of it.
fn snap_lane(net: &RoadNetwork, lp: &mut LanePos, sidewalks: bool) {
    let Some(road) = net.roads.get(lp.road) else { return };
    let s = lp.s.clamp(0.0, road.length);
    let Some(t) = lane_center_t(road, lp.lane_id, s).map(|c| c + lp.offset) else { return };
    match crate::roads::lane_snap::snap(road, road.section_index_at(s), s, t, sidewalks) {
        Some((lane_id, offset)) => {
            lp.lane_id = lane_id;
            lp.offset = offset;
        }
        None => relane(net, lp),
    }
}

/// The road XYZ2TrackPos attaches the entity to after a lane change step without a route when
/// that is not the road its internal position moved along (LatLaneChangeAction::Step): the
/// search over every road (`roads::locate`: the current road holds a point less than 2 m beside
/// it, a road not directly connected weighs 3 m more). A lane change carried into a direct
/// junction's straight arm while the entity is still over the arm beside it leaves it on that
/// other road. Only the attachment moves: XYZ2TrackPos keeps the point and the heading (SetX,
/// SetY; its SetTrackPosMode evaluates no angle), and the heading relative to the road stays
/// the one set on the internal position's road, so the direction (`dir`) is kept too. The
/// internal position goes on along its own road. Also whether the point is on that road.
fn attached_elsewhere(net: &RoadNetwork, en: &crate::entities::Entity, attached: &LanePos, sidewalks: bool) -> Option<(LanePos, bool)> {
    // Inside a real lane away from the road's ends the search would keep the road: skip it.
    if en.on_road && crate::roads::locate::stays_on_its_road(net, attached.road, attached.s) {
        return None;
    }
    let here = (attached.road, attached.s, attached.lane_id);
    let found = crate::roads::locate::world_to_lane_at(net, en.x, en.y, Some(en.z), Some((attached.road, attached.s)), Some(here))?;
    if found.road == attached.road {
        return None;
    }
    let (lane_id, offset) = crate::roads::lane_snap::snap_located(net, &found, sidewalks);
    let on_road = net.roads.get(found.road).is_some_and(|r| !crate::roads::offroad::is_off_road(r, found.s, found.t));
    Some((LanePos { road: found.road, lane_id, s: found.s, offset, dir: attached.dir }, on_road))
}

/// Where XYZ2TrackPos leaves the position on its own road: at the s it interpolates on the
/// lane-0 OSI segment (between the vertices' normals, by angle), x and y kept. On curved
/// geometry that is millimetres to centimetres from the exact projection; the internal position
/// goes on from its exact s, but whatever moves the entity from its position after this step
/// (an ACC in override mode, the first default move after the change) starts from this s. The
/// lane and t stay the exact projection's (moving s by centimetres along a curve moves t by less
/// than a micrometre); the offset is taken from the lane centre at the new s.
fn on_own_road_segment(net: &RoadNetwork, en: &crate::entities::Entity, attached: &LanePos) -> Option<LanePos> {
    let s = crate::roads::locate::segment_s_near(net, attached.road, en.x, en.y, attached.s)?;
    if s == attached.s {
        return None;
    }
    let road = net.roads.get(attached.road)?;
    let centre = |s| crate::roads::lane_geometry::lane_center_t(road, attached.lane_id, s);
    let offset = match (centre(attached.s), centre(s)) {
        (Some(a), Some(b)) => attached.offset + a - b,
        _ => attached.offset,
    };
    Some(LanePos { s, offset, ..*attached })
}

/// The lane a position locked on its lane (a looming controller's) is attached to after a lane
/// change step: esmini's XYZ2TrackPos with `lockOnLane_` takes the lane of the snapped-to types
/// nearest the centre of the lane the position is in (`fixed_t`), keeps the offset from that
/// centre and the point itself (SetX/SetY) — a lane change onto a border lane leaves the entity
/// in the driving lane beside it.
fn locked_lane_id(net: &RoadNetwork, lp: &LanePos, sidewalks: bool) -> Option<i32> {
    let road = net.roads.get(lp.road)?;
    let s = lp.s.clamp(0.0, road.length);
    let fixed_t = lane_center_t(road, lp.lane_id, s)?;
    crate::roads::lane_snap::snap(road, road.section_index_at(s), s, fixed_t, sidewalks).map(|(id, _)| id)
}

/// The lateral position (t) esmini gives the centre of a lane that does not exist: width 0 at
/// the outer border of the last lane before it on its side (LaneSection::GetCenterOffset with
/// GetWidth 0 for a missing lane). `None` for lane 0 or a road without sections.
fn phantom_lane_center(road: &opendrive::Road, lane_id: i32, s: f64) -> Option<f64> {
    if lane_id == 0 {
        return None;
    }
    let section = road.section_index_at(s);
    let sec = road.lane_sections.get(section)?;
    let side = if lane_id > 0 { &sec.left } else { &sec.right };
    let inner = side.iter().filter(|l| l.id.abs() < lane_id.abs()).max_by_key(|l| l.id.abs());
    match inner {
        Some(l) => lane_borders(road, section, l.id, s).map(|b| b.outer),
        None => Some(road.lane_offset_at(s)),
    }
}

impl<'a> Sim<'a> {
    pub(super) fn start_lane_change(&mut self, slot: usize, e: usize, d: &TransitionDynamics, target: &LaneChangeTarget, target_offset: f64) -> ActionRt {
        let Some(net) = self.net else {
            self.warn_action(slot, "LaneChangeAction needs a road network".into());
            return ActionRt::Done;
        };
        let Some(lp) = self.entities.get(e).and_then(|x| x.lane) else {
            self.warn_action(slot, "LaneChangeAction: the entity is not on a road".into());
            return ActionRt::Done;
        };
        let target_lane = match target {
            LaneChangeTarget::Absolute { lane_id } => *lane_id,
            LaneChangeTarget::Relative { entity, value } => {
                let ref_index = self.action_ref_index(slot, entity);
                if ref_index.is_some_and(|i| self.entities[i].roadless && self.entities[i].lane.is_none()) {
                    from_unplaced_reference(*value)
                } else {
                    let Some(r) = ref_index.and_then(|i| self.entities[i].lane) else {
                        self.warn_action(slot, format!("LaneChangeAction: reference entity `{entity}` unknown or off the road"));
                        return ActionRt::Done;
                    };
                    let forward = if r.dir < 0.0 { -1 } else { 1 };
                    // A positive value is to the left of the reference entity's driving direction.
                    step_lane(r.lane_id, value * forward)
                }
            }
        };
        let Some(road) = net.roads.get(lp.road) else { return ActionRt::Done };
        let s = lp.s.clamp(0.0, road.length);
        let Some(cur_c) = lane_center_t(road, lp.lane_id, s) else { return ActionRt::Done };
        let (tgt_c, internal_lane) = match lane_center_t(road, target_lane, s) {
            Some(c) => (c, target_lane),
            None => {
                // esmini (LatLaneChangeAction::Start, Position::ForceLaneId) measures a missing
                // lane as one of width 0 beyond the last lane of its side; the failed SetLanePos
                // then keeps the entity's own lane, so the offset from that phantom centre is
                // applied in the lane it is in: a jump towards the centre, then a drift back.
                let Some(c) = phantom_lane_center(road, target_lane, s) else {
                    self.warn_action(slot, format!("LaneChangeAction: lane {target_lane} does not exist on road `{}` here", road.id));
                    return ActionRt::Done;
                };
                self.warn_action(
                    slot,
                    format!("LaneChangeAction: lane {target_lane} does not exist on road `{}` here; as esmini, the entity is moved as if it were a lane of width 0 at the road's edge", road.id),
                );
                (c, lp.lane_id)
            }
        };
        let offset_in_target = cur_c + lp.offset - tgt_c;
        let internal = LanePos { lane_id: internal_lane, offset: offset_in_target, ..lp };
        let lane_sign = sign(f64::from(target_lane));
        let mut t = Transition::new(d.shape, d.dimension, d.value);
        if d.dimension == DynamicsDimension::Rate {
            // A rate is the peak lateral speed: the span is the time in which the shape covers
            // the distance with that peak (esmini's TransitionDynamics::UpdateRate via
            // GetTargetParamValByPrimPeak: π·d/2r sinusoidal, 1.5·d/r cubic, d/r linear).
            t.dimension = DynamicsDimension::Time;
            let dist = (target_offset - offset_in_target).abs();
            let span = match d.shape {
                DynamicsShape::Sinusoidal => std::f64::consts::FRAC_PI_2 * dist,
                DynamicsShape::Cubic => 1.5 * dist,
                _ => dist,
            };
            t.set_param_target(if d.value.abs() > SMALL { span / d.value.abs() } else { 0.0 });
        }
        t.set_start(lane_sign * offset_in_target);
        t.set_target(lane_sign * target_offset);
        if let Some(en) = self.entities.get_mut(e) {
            // LatLaneChangeAction::Start "aligns to road": SetHeadingRelativeRoadDirection(0)
            // evaluates the heading at once (EvaluateHPR), facing the way the entity faced
            // along the road, so an entity standing still (whose Step then returns early) turns
            // to the road's direction already.
            if en.align_with_lane(net) {
                en.heading_abs = false;
            }
        }
        let missing_lane_sign = (internal_lane != target_lane).then_some(lane_sign);
        ActionRt::LaneChange(LaneChangeRt { transition: t, internal, missing_lane_sign })
    }

    pub(crate) fn step_lane_change(&mut self, e: usize, l: &mut LaneChangeRt) -> bool {
        let Some(net) = self.net else { return true };
        let Some(en) = self.entities.get(e) else { return true };
        let speed = en.speed;
        if speed.abs() < ESMINI_SMALL_NUMBER {
            // LatLaneChangeAction::Step marks the longitudinal domain as owned (dirty bits) before
            // it returns at standstill: the default controller moves nothing this step, and an
            // entity stopped at a dead end stays stopped whatever speed a later action sets.
            if let Some(en) = self.entities.get_mut(e) {
                en.moved_by_action = true;
            }
            return false;
        }
        // esmini puts the entity back on its internal position with Position::SetLanePos, which
        // keeps the entity's heading relative to the road it is on (LatLaneChangeAction::Step):
        // where a controller moved it on since (an ACC in override mode: MoveAlongS) onto a road
        // that runs the other way, it faces the other way on the internal position's road and
        // the step moves it back.
        if let Some(cur) = en.lane {
            l.internal.dir = cur.dir;
        }
        let dt = self.dt;
        let t = &mut l.transition;
        let step_len = (speed * dt).abs();
        let time_like = t.dimension != DynamicsDimension::Distance;
        // esmini 3.6.0, over time (or rate), LatLaneChangeAction::Step: the step's lateral part
        // is the rate at the start of the step times dt, its longitudinal part what is left of
        // speed·dt, and the heading the direction of that step. The transition is never
        // stretched to the speed (esmini calls no SetMaxRate on it).
        let rate_before = t.scaled_derivative();
        // A step shape, or an empty span over time, puts the entity on the target at once and
        // keeps its whole longitudinal motion (TransitionDynamics::Evaluate/EvaluatePrim).
        let instant = t.shape == DynamicsShape::Step || (time_like && t.param_target < ESMINI_SMALL_NUMBER);
        let d_lat_wanted = dt * rate_before.abs();
        let lagged = time_like && !instant && d_lat_wanted < step_len + ESMINI_SMALL_NUMBER;
        // More sideways motion than speed·dt: esmini drops the longitudinal motion, moves the
        // parameter by speed·dt on a straight line from start to target and evaluates the
        // linear shape there, heading (almost) square to the road ("requested lateral motion
        // too large wrt speed").
        let too_fast = time_like && !instant && !lagged;
        let agnostic = if instant {
            t.step(dt);
            t.target
        } else if too_fast {
            let span = (t.target - t.start).abs();
            t.step(if span > 0.0 { step_len * t.param_target / span } else { t.param_target });
            t.start + t.param * (t.target - t.start) / crate::dynamics::avoid_zero(t.param_target)
        } else if time_like {
            t.step(dt);
            t.value()
        } else {
            // esmini counts the distance along the road: the step's length projected by the
            // slope at the start of the step (LatLaneChangeAction::Step, DISTANCE branch).
            t.step(step_len / (1.0 + rate_before * rate_before).sqrt());
            t.value()
        };
        let lane_sign = sign(f64::from(l.internal.lane_id));
        // In the first step to a missing lane esmini's Position::SetLanePos fails on the target
        // lane's id but has already stored the offset made for it (sign of the target lane), which
        // the move along s then applies in the entity's own lane; from the next step on, the
        // internal position is in the entity's lane (LatLaneChangeAction::Step).
        l.internal.offset = agnostic * l.missing_lane_sign.take().unwrap_or(lane_sign);
        let d_long = if instant {
            sign(speed) * step_len
        } else if time_like {
            sign(speed) * (step_len * step_len - d_lat_wanted.min(step_len).powi(2)).sqrt()
        } else {
            // Over distance the longitudinal part is the step projected by the slope at its
            // start, also in the last step, where the clamped parameter moves less sideways.
            sign(speed) * step_len / (1.0 + rate_before * rate_before).sqrt()
        };
        // esmini moves with junction selector angle −1 here: into a junction without a route
        // the arm is drawn, straight on or not (LatLaneChangeAction::Step).
        let route = self.entities.get(e).and_then(|en| en.route.as_deref());
        let status = move_along_s_drawn(net, &mut l.internal, d_long, route, &mut self.random);
        let done = t.done(agnostic);
        let yaw = if done {
            0.0
        } else {
            let angle = if too_fast {
                sign(speed) * sign(rate_before) * (FRAC_PI_2 - ESMINI_SMALL_NUMBER)
            } else if time_like {
                (sign(speed) * sign(rate_before) * d_lat_wanted).atan2(d_long.abs())
            } else {
                rate_before.atan()
            };
            // esmini turns by the lane the move ended in (Position::GetLaneId after MoveAlongS):
            // entering a road the other way round flips both the direction and the lane's side.
            l.internal.dir * sign(f64::from(l.internal.lane_id)) * angle
        };
        let mut attached = l.internal;
        // XYZ2TrackPos re-attaches the position to the lane it is in, or, locked on its lane
        // (a looming controller's), to the lane nearest the target lane's centre (`locked_lane_id`).
        let locked = self.lane_locked(e);
        // What moves the entity from its position reads the s XYZ2TrackPos leaves: a controller
        // every step, the default controller after the last one. Elsewhere the exact s stands
        // in for it (millimetres on a curve, in the trace's s column and road-frame conditions).
        let segment_s_read = done || (self.any_controller && self.controllers_of(e).next().is_some());
        let en = &mut self.entities[e];
        // With a route esmini skips that re-attachment: the entity is in the target lane from
        // the first step, at the offset still to go (so an ACC no longer follows the vehicle
        // in the lane it leaves).
        let sidewalks = en.kind == crate::entities::EntityKind::Pedestrian;
        if !locked && en.route.is_none() {
            snap_lane(net, &mut attached, sidewalks);
        }
        en.yaw_offset = yaw;
        en.set_lane_pos(net, attached);
        if !locked && en.route.is_none() {
            if let Some((other, on_road)) = attached_elsewhere(net, en, &attached, sidewalks) {
                en.lane = Some(other);
                en.on_road = on_road;
                attached = other;
            } else if segment_s_read {
                if let Some(lp) = on_own_road_segment(net, en, &attached) {
                    en.lane = Some(lp);
                }
            }
        }
        if locked && en.route.is_none() {
            if let (Some(lp), Some(id)) = (en.lane.as_mut(), locked_lane_id(net, &attached, sidewalks)) {
                lp.lane_id = id;
            }
        }
        // esmini turns the entity (SetHeadingRelativeRoadDirection: EvaluateHPR adds GetHOffset)
        // while its position is still on the internal position's lane, the target lane, and
        // XYZ2TrackPos then keeps that heading: the drift is the target lane's.
        if l.internal.road == attached.road && l.internal.lane_id != attached.lane_id {
            if let Some(p) = attached.pose(net) {
                let drift = crate::positions::lane_drift(net, l.internal.road, l.internal.lane_id, l.internal.s);
                en.h = crate::angles::wrap_2pi(attached.facing_heading(&p) + en.yaw_offset + drift);
            }
        }
        en.moved_by_action = true;
        // esmini ends the lane change where the road ends (POS_STATUS_END_OF_ROAD →
        // OSCAction::End), the offset reached so far kept; the speed is left to the default
        // controller, which stops an entity stuck there. The status is the one the step leaves:
        // with a route, MoveAlongS's (a move stopped at a dead end, or one that ends within
        // SMALL_NUMBER of an end without a link element, a step too short to move included);
        // without, that of the re-attachment after it (LatLaneChangeAction::Step calls
        // XYZ2TrackPos before it tests the status), set only at an end without a link element:
        // at an end whose link leads to a road the map lacks, the lane change goes on,
        // sideways only, until its offset is reached.
        let past = if en.route.is_some() {
            status == MoveStatus::EndOfRoad || crate::roads::past_end::unlinked_end_at(net, l.internal.road, l.internal.s)
        } else {
            crate::roads::past_end::unlinked_end_at(net, attached.road, attached.s)
        };
        if past {
            en.at_road_end = true;
            return true;
        }
        done
    }
}

/// The target lane of a lane change `value` lanes from a reference entity esmini never placed
/// (a RoutePosition FromCurrentEntity, which esmini 3.6.0 does not implement): Position's
/// defaults, lane 0 facing along s. LatLaneChangeAction::Start adds the value to lane 0 and,
/// as esmini's SIGN(0) is +1, skips the centre lane on the way right: −1 → −2, 0 → 1.
fn from_unplaced_reference(value: i32) -> i32 {
    match value {
        0 => 1,
        v if v < 0 => v - 1,
        v => v,
    }
}
