//! Entity conditions, evaluated for each triggering entity and combined by the
//! triggering-entities rule (any: one true is enough; all: every one must be true).

use super::boxes::{boxes_overlap, corners};
use super::distance::{between, between_chains, chain_to_point, to_point_with_hint};
use super::ConditionRt;
use crate::controllers::natural_driver::view::LARGE_NUMBER;
// esmini's SMALL_NUMBER (1e-6): the tolerances of TrigByTimeHeadway, Object::TimeToCollision,
// TrigByEndOfRoad and TrigByAngle (OSCCondition.cpp, Entities.cpp).
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL;
use crate::entities::Entity;
use crate::entities::{in_frame, EntityKind};
use crate::positions::resolve;
use crate::rules::compare;
use crate::sim::Sim;
use openscenario::{
    CollisionTarget, CoordinateSystem, DistanceOptions, EntityCondition as C, ObjectType, RelativeDistanceType, TriggeringEntitiesRule, TtcTarget,
};

fn cs_of(o: &DistanceOptions) -> CoordinateSystem {
    match (o.coordinate_system, o.along_route) {
        (Some(cs), _) => cs,
        (None, Some(true)) => CoordinateSystem::Road,
        _ => CoordinateSystem::Entity,
    }
}

impl<'a> Sim<'a> {
    pub(super) fn check_entity(&mut self, c: &mut ConditionRt<'a>, rule: TriggeringEntitiesRule, cond: &'a C) -> bool {
        if c.triggering.is_empty() {
            return self.warn_once(c, "no known triggering entity".into());
        }
        let needs_other = matches!(cond, C::TimeHeadway { .. } | C::RelativeSpeed { .. } | C::RelativeDistance { .. })
            || matches!(cond, C::TimeToCollision { target: TtcTarget::Entity(_), .. })
            || matches!(cond, C::Collision { target: CollisionTarget::Entity(_) });
        if needs_other && c.other.is_none() {
            return self.warn_once(c, "the referenced entity is unknown".into());
        }
        // Positions are resolved once per evaluation (they may be relative to moving entities).
        let mut wanted_attitude = None;
        let point = match cond {
            // esmini's TrigByTimeToCollision::CheckCondition reads its position's x and y without
            // Position::EvaluateRelation (TrigByReachPosition and TrigByDistance call it), and a
            // position relative to an entity is only ever set up as a relation (the
            // OSCPositionRelative* constructors): its point stays at Position::Init's origin.
            C::TimeToCollision { target: TtcTarget::Position(position), .. } if relative_to_entity(position) => Some((0.0, 0.0)),
            C::ReachPosition { position, .. } | C::Distance { position, .. } | C::TimeToCollision { target: TtcTarget::Position(position), .. } => {
                match resolve(position, self.net, &self.entities) {
                    Ok(p) => {
                        if matches!(cond, C::ReachPosition { .. }) && super::reach_orientation::has_orientation(position) {
                            wanted_attitude = Some(super::reach_orientation::position_attitude(self.net, &p));
                        }
                        Some((p.x, p.y))
                    }
                    Err(e) => return self.warn_once(c, e),
                }
            }
            _ => None,
        };
        // esmini 3.6 reads no RelativeAngleCondition
        if let C::RelativeAngle { .. } = cond {
            return self.warn_once(c, format!("{} is not supported; it never becomes true", cond.element_name()));
        }
        let clearance = super::clearance::Clearance::of(cond);
        // esmini's TrigByRelativeClearance keeps whether an entity was found in the area from
        // one triggering entity to the next (see relative_clearance)
        let mut clearance_found = false;
        // esmini's TrigByStandStill and TrigByOffRoad set their current duration only for an
        // entity standing (off the road) and keep it for the next ones: an entity that is not
        // counts with the duration of the last one that was (under the rule `all`, a moving
        // entity after one that has stood long enough meets the condition too).
        let mut held_duration = 0.0;
        let mut result = false;
        let sticky = matches!(cond, C::ReachPosition { .. } | C::EndOfRoad { .. } | C::Collision { .. });
        c.hits.clear();
        let exists = |s: &Self, i: usize| s.entities.get(i).is_some_and(|e| e.active);
        for i in 0..c.triggering.len() {
            let idx = c.triggering[i];
            // esmini skips a triggering entity that does not exist (deleted), and every one
            // while the referenced entity does not exist.
            if !exists(self, idx) || c.other.is_some_and(|o| !exists(self, o)) {
                continue;
            }
            // esmini's TrigByAngle skips an entity without a trajectory in the trajectory frame.
            if matches!(cond, C::Angle { coordinate_system: Some(CoordinateSystem::Trajectory), .. }) && self.trajectory_heading(idx).is_none() {
                continue;
            }
            let r = match (&clearance, cond) {
                (Some(cl), _) => Some(self.relative_clearance(idx, cl, &mut clearance_found)),
                // strictly longer than the duration, on esmini's accumulated clock
                // (`Sim::clock`; an exact duration of whole steps is usually one step short there)
                (None, C::StandStill { duration } | C::Offroad { duration }) => {
                    let stand_still = matches!(cond, C::StandStill { .. });
                    let since = self.entities.get(idx).and_then(|e| if stand_still { e.standstill_since } else { e.offroad_since });
                    if let Some(since) = since {
                        held_duration = self.clock - since;
                    }
                    Some(held_duration > *duration)
                }
                (None, _) => {
                    let r = self.check_one(idx, c.other, point, cond);
                    match wanted_attitude {
                        Some(wanted) => r.map(|r| r && self.faces_as(idx, wanted)),
                        None => r,
                    }
                }
            };
            // esmini's TrigByTimeHeadway and TrigByTimeToCollision: an entity whose measure is
            // not defined makes the result false but leaves the triggering-entities rule
            // undecided, so the next entity is checked even under the rule `all`.
            let Some(r) = r else {
                result = false;
                continue;
            };
            // esmini's TrigByReachPosition, TrigByEndOfRoad and TrigByCollision only ever set
            // their result to true inside the loop over the triggering entities: once one
            // entity meets the condition the result stays true, so with the rule `all` the
            // first entity checked decides, and the later ones count as triggering too.
            result = if sticky { result || r } else { r };
            if result {
                c.hits.push(idx);
            }
            match rule {
                TriggeringEntitiesRule::Any if result => break,
                TriggeringEntitiesRule::All if !result => break,
                _ => {}
            }
        }
        if result {
            std::mem::swap(&mut c.fired_by, &mut c.hits);
        }
        result
    }

    /// The direction of the path of the trajectory entity `idx` follows, where it is now.
    fn trajectory_heading(&self, idx: usize) -> Option<f64> {
        self.running_trajectory(idx).map(|f| f.path.true_heading_at(f.s))
    }

    /// The condition for triggering entity `idx`; `None` where its measure is not defined (a
    /// time headway or time to collision of a target behind, at no distance, or moving apart).
    fn check_one(&self, idx: usize, other: Option<usize>, point: Option<(f64, f64)>, cond: &C) -> Option<bool> {
        let Some(e) = self.entities.get(idx) else { return Some(false) };
        if !e.active {
            return Some(false);
        }
        let o = other.and_then(|i| self.entities.get(i));
        let t = self.time;
        Some(match cond {
            C::Speed { value, rule, direction } => compare(directed_speed(e, *direction), *value, *rule),
            C::Angle { angle_type, angle, tolerance, coordinate_system } => {
                // esmini's TrigByAngle::CheckCondition: the angle in the frame (world by
                // default), wrapped to [−π, π], within the tolerance of the value (SMALL_NUMBER
                // slack). Pitch and roll as attitude.rs gives them.
                use openscenario::AngleType as A;
                let (pitch, roll) = if *angle_type == A::Heading { (0.0, 0.0) } else { self.pitch_roll(idx) };
                let own = match angle_type {
                    A::Heading => e.h,
                    A::Pitch => pitch,
                    A::Roll => roll,
                };
                let road_pr = |lp: &crate::roads::LanePos, net: &opendrive::RoadNetwork| {
                    let (p, r) = crate::attitude::road_pitch_roll(net, lp);
                    if *angle_type == A::Pitch {
                        p
                    } else {
                        r
                    }
                };
                // the lane's driving direction relative to s (esmini's GetDrivingDirectionRelativeRoad)
                let lane_dir = |lp: &crate::roads::LanePos, net: &opendrive::RoadNetwork| {
                    if net.roads.get(lp.road).is_none_or(|r| opendrive::drives_along_s(r.rule, lp.lane_id)) {
                        1.0
                    } else {
                        -1.0
                    }
                };
                // the reference line's heading (esmini's GetHRoad, set from the geometry alone):
                // on a banked road without the turn the changing roll gives the entity's own
                // heading (`LanePose::road_heading` has it), which the angle then measures
                let reference_heading = |lp: &crate::roads::LanePos, net: &opendrive::RoadNetwork| lp.reference_heading(net).unwrap_or(0.0);
                let frame = match (angle_type, coordinate_system.unwrap_or(CoordinateSystem::World), self.net, e.lane) {
                    (A::Heading, CoordinateSystem::Road, Some(net), Some(lp)) => reference_heading(&lp, net),
                    (A::Heading, CoordinateSystem::Lane, Some(net), Some(lp)) => {
                        reference_heading(&lp, net) + if lane_dir(&lp, net) > 0.0 { 0.0 } else { std::f64::consts::PI }
                    }
                    (_, CoordinateSystem::Road, Some(net), Some(lp)) => road_pr(&lp, net),
                    (_, CoordinateSystem::Lane, Some(net), Some(lp)) => road_pr(&lp, net) * lane_dir(&lp, net),
                    (_, CoordinateSystem::Entity, _, _) => own,
                    // the direction of the trajectory's current segment (esmini's GetHTrue);
                    // pitch and roll have no trajectory frame in esmini (the angle is 0)
                    (A::Heading, CoordinateSystem::Trajectory, _, _) => self.trajectory_heading(idx).unwrap_or(own),
                    (_, CoordinateSystem::Trajectory, _, _) => own,
                    _ => 0.0,
                };
                let current = crate::angles::wrap(own - frame);
                crate::angles::wrap(current - angle).abs() < tolerance + SMALL
            }
            // evaluated in check_entity: its result depends on the entities checked before
            C::RelativeClearance { .. } => false,
            C::RelativeSpeed { value, rule, direction, .. } => o.is_some_and(|o| compare(relative_speed(e, o, *direction), *value, *rule)),
            C::Acceleration { value, rule, direction } => compare(directed_acceleration(e, *direction), *value, *rule),
            // evaluated in check_entity: their duration carries over from entity to entity
            C::StandStill { .. } | C::Offroad { .. } => false,
            C::TraveledDistance { value } => e.odometer >= *value,
            C::EndOfRoad { duration } => e.end_of_road && t - e.end_of_road_since > duration - SMALL,
            C::ReachPosition { tolerance, .. } => point.is_some_and(|(x, y)| (e.x - x).hypot(e.y - y) < *tolerance),
            C::Distance { value, rule, options, position, .. } => {
                point.is_some_and(|(x, y)| compare(self.distance_to_point(idx, x, y, options, relative_to_entity(position)).abs(), *value, *rule))
            }
            C::RelativeDistance { value, rule, options, .. } => other.is_some_and(|j| compare(self.distance_between(idx, j, options).abs(), *value, *rule)),
            C::TimeHeadway { value, rule, options, .. } => {
                let Some(j) = other.filter(|_| o.is_some()) else { return Some(false) };
                let d = self.distance_between(idx, j, options);
                if d < 0.0 || e.speed < SMALL {
                    return None;
                }
                compare((d / e.speed).abs(), *value, *rule)
            }
            C::TimeToCollision { value, rule, options, .. } => {
                let (d, rel_speed) = match (o, point) {
                    (Some(o), _) => {
                        let d = other.map_or(0.0, |j| self.distance_between(idx, j, options));
                        let (ovx, ovy) = o.vel;
                        let rel = if ovx.abs() < SMALL && ovy.abs() < SMALL {
                            e.speed
                        } else {
                            let on = ovx.hypot(ovy);
                            let proj = (e.vel.0 * ovx + e.vel.1 * ovy) / on;
                            crate::dynamics::sign(e.speed) * crate::dynamics::sign(proj) * (proj - o.speed.abs())
                        };
                        (d, rel)
                    }
                    (None, Some((x, y))) => (self.distance_to_point(idx, x, y, options, true), e.speed),
                    _ => return Some(false),
                };
                if d.abs() < SMALL || rel_speed.abs() < SMALL {
                    return None;
                }
                let ttc = d / rel_speed;
                if ttc < 0.0 {
                    return None;
                }
                compare(ttc, *value, *rule)
            }
            C::Collision { target } => {
                let ca = corners(e);
                match target {
                    CollisionTarget::Entity(_) => o.is_some_and(|o| o.active && boxes_overlap(&ca, &corners(o))),
                    CollisionTarget::ByType(ty) => self.entities.iter().enumerate().any(|(j, b)| {
                        j != idx
                            && b.active
                            && matches!(
                                (ty, b.kind),
                                (ObjectType::Vehicle, EntityKind::Vehicle)
                                    | (ObjectType::Pedestrian, EntityKind::Pedestrian)
                                    | (ObjectType::MiscellaneousObject, EntityKind::Misc)
                                    | (ObjectType::External, EntityKind::External)
                            )
                            && boxes_overlap(&ca, &corners(b))
                    }),
                }
            }
            C::RelativeAngle { .. } => false,
        })
    }
}

impl Sim<'_> {
    /// The distance of a condition from entity `idx` to entity `other`; with freespace esmini
    /// measures from every vehicle of both towing chains (Object::Distance).
    fn distance_between(&self, idx: usize, other: usize, options: &DistanceOptions) -> f64 {
        let kind = options.relative_distance_type.unwrap_or(RelativeDistanceType::EuclidianDistance);
        let (Some(e), Some(o)) = (self.entities.get(idx), self.entities.get(other)) else { return LARGE_NUMBER };
        if !options.freespace {
            return between(self.net, e, o, cs_of(options), kind, false);
        }
        let pivots: Vec<&Entity> = self.towing_chain(idx).into_iter().filter_map(|i| self.entities.get(i)).collect();
        // esmini walks the target's trailers from the target itself
        let targets: Vec<&Entity> = std::iter::once(other)
            .chain(self.towing_chain(other).into_iter().skip_while(|&i| i != other).skip(1))
            .filter_map(|i| self.entities.get(i))
            .collect();
        between_chains(self.net, &pivots, &targets, cs_of(options), kind)
    }

    /// The distance of a condition from entity `idx` to the point (x, y), with freespace from
    /// every vehicle of its towing chain.
    fn distance_to_point(&self, idx: usize, x: f64, y: f64, options: &DistanceOptions, moving: bool) -> f64 {
        let kind = options.relative_distance_type.unwrap_or(RelativeDistanceType::EuclidianDistance);
        let Some(e) = self.entities.get(idx) else { return LARGE_NUMBER };
        if !options.freespace {
            return to_point_with_hint(self.net, e, x, y, cs_of(options), kind, false, moving);
        }
        let pivots: Vec<&Entity> = self.towing_chain(idx).into_iter().filter_map(|i| self.entities.get(i)).collect();
        chain_to_point(self.net, &pivots, x, y, cs_of(options), kind)
    }
}

/// Whether `position` is placed relative to an entity (a RelativeWorld-, RelativeObject-,
/// RelativeRoad- or RelativeLanePosition).
fn relative_to_entity(position: &openscenario::Position) -> bool {
    use openscenario::Position as P;
    matches!(position, P::RelativeWorld { .. } | P::RelativeObject { .. } | P::RelativeRoad { .. } | P::RelativeLane { .. })
}

/// A SpeedCondition's speed: the signed speed, or with a direction the velocity along the
/// entity's own axes, vertical the world one (esmini's TrigBySpeed::CheckCondition, GetVelZ).
fn directed_speed(e: &crate::entities::Entity, direction: Option<openscenario::DirectionalDimension>) -> f64 {
    use openscenario::DirectionalDimension as D;
    match direction {
        None => e.speed,
        Some(D::Longitudinal) => in_frame(e.vel, e.h).0,
        Some(D::Lateral) => in_frame(e.vel, e.h).1,
        Some(D::Vertical) => e.vel_z,
    }
}

/// An AccelerationCondition's acceleration, from the entity's acceleration vector (the change
/// of its world velocity over the last step) as esmini's TrigByAcceleration::CheckCondition
/// reads it: without a direction Position::GetAcc — the vector's length, signed as its
/// component along the heading (so a car at constant speed in a curve has its centripetal
/// acceleration, positive or not by its sign along the heading); with one, the component along
/// the entity's own axes (GetAccLong, GetAccLat), vertical the world one (GetAccZ: on a slope the
/// step after a teleport, whose velocity has no vertical part, jumps by the vertical speed / dt).
fn directed_acceleration(e: &crate::entities::Entity, direction: Option<openscenario::DirectionalDimension>) -> f64 {
    use openscenario::DirectionalDimension as D;
    let (along, lateral) = in_frame(e.acc_vec, e.h);
    match direction {
        // Position::GetAcc: the magnitude signed by the component along the heading with
        // CommonMini's SIGN, which is +1 for 0 (a purely sideways acceleration is positive)
        None => {
            let sign = if along < 0.0 { -1.0 } else { 1.0 };
            sign * e.acc_vec.0.hypot(e.acc_vec.1)
        }
        Some(D::Longitudinal) => along,
        Some(D::Lateral) => lateral,
        Some(D::Vertical) => e.acc_z,
    }
}

/// A RelativeSpeedCondition's value: the speed difference, or with a direction the triggering
/// entity's velocity in the reference entity's frame less the reference's own
/// (esmini's TrigByRelativeSpeed::CheckCondition).
fn relative_speed(e: &crate::entities::Entity, o: &crate::entities::Entity, direction: Option<openscenario::DirectionalDimension>) -> f64 {
    use openscenario::DirectionalDimension as D;
    match direction {
        None => e.speed - o.speed,
        Some(D::Longitudinal) => in_frame(e.vel, o.h).0 - in_frame(o.vel, o.h).0,
        Some(D::Lateral) => in_frame(e.vel, o.h).1 - in_frame(o.vel, o.h).1,
        Some(D::Vertical) => e.vel_z - o.vel_z,
    }
}
