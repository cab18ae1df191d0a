//! LongitudinalDistanceAction: keep a distance (or a time gap, converted with the reference
//! entity's speed) behind or ahead of a reference entity.
//!
//! As esmini: without acceleration limits the actor is put at the requested distance at once
//! and takes the reference's speed; with limits a critically damped spring pulls the distance
//! error to zero (stiffness 0.4 × the limit in the direction of the pull), its acceleration
//! clipped to the limits and its change per second to the jerk limits, and the speed to the
//! maximum speed. A freespace distance is the bounding boxes' gap along the actor's heading in
//! every coordinate system (esmini's). "any" displacement keeps the side the actor is on when the action starts. A
//! non-continuous action ends when the distance is within 0.1 m.

pub(crate) mod state;

use state::LongDistanceRt;

use super::dynamic_constraints::{limits, Performance};
use super::state::{ActionRt, Kept};
use crate::conditions::distance::between;
use crate::roads::move_along_s_drawn;
use crate::sim::Sim;
use openscenario::{CoordinateSystem, DynamicConstraints, LongitudinalDisplacement, RelativeDistanceType};

const LARGE: f64 = super::dynamic_constraints::UNLIMITED;
const SPRING: f64 = 0.4;
/// Distance error below which a non-continuous action is done, m.
const THRESHOLD: f64 = 0.1;

/// The longitudinal action's parameters as the model gives them.
pub(crate) struct LongDistanceSpec<'s> {
    pub entity: &'s str,
    pub distance: Option<f64>,
    pub time_gap: Option<f64>,
    pub freespace: bool,
    pub continuous: bool,
    pub coordinate_system: Option<CoordinateSystem>,
    pub displacement: Option<LongitudinalDisplacement>,
    pub constraints: Option<&'s DynamicConstraints>,
}

impl<'a> Sim<'a> {
    fn long_gap(&self, e: usize, r: &LongDistanceRt) -> f64 {
        match (self.entities.get(e), self.entities.get(r.target)) {
            // LongDistanceAction::Step measures a freespace distance with
            // Object::FreeSpaceDistance whatever the coordinate system: the gap between the
            // bounding boxes along the actor's own heading (CollisionAndRelativeDistLatLong),
            // so a reference facing the other way is measured to its front, not its rear.
            (Some(a), Some(b)) if r.freespace => between(self.net, a, b, CoordinateSystem::Entity, RelativeDistanceType::Longitudinal, true),
            (Some(a), Some(b)) => between(self.net, a, b, r.cs, RelativeDistanceType::Longitudinal, false),
            _ => 0.0,
        }
    }

    /// The gap LongDistanceAction::Start resolves "any" by: with freespace the one Step
    /// measures (Object::FreeSpaceDistance); without, the reference's position along the
    /// actor's heading (Position::getRelativeDistance's x: RotateVec2D by −h), whatever the
    /// coordinate system. Two entities side by side at a road's end are a rounding apart there.
    fn any_side_gap(&self, e: usize, r: &LongDistanceRt) -> f64 {
        match (self.entities.get(e), self.entities.get(r.target)) {
            _ if r.freespace => self.long_gap(e, r),
            (Some(a), Some(b)) => crate::entities::in_frame((b.x - a.x, b.y - a.y), a.h).0,
            _ => 0.0,
        }
    }

    pub(super) fn start_long_distance(&mut self, slot: usize, e: usize, spec: &LongDistanceSpec) -> ActionRt {
        let Some(target) = self.entity_index(spec.entity) else {
            self.warn_action(slot, format!("LongitudinalDistanceAction: unknown entity `{}`", spec.entity));
            return ActionRt::Done;
        };
        let (value, time_gap) = match (spec.distance, spec.time_gap) {
            (Some(d), _) => (d, false),
            (None, Some(t)) => (t, true),
            (None, None) => {
                self.warn_action(slot, "LongitudinalDistanceAction needs a distance or a timeGap; the action completes at once".into());
                return ActionRt::Done;
            }
        };
        // ScenarioReader::parseDynamicConstraints with the actor: its performance fills in and
        // caps the limits.
        let performance = self.entities.get(e).map_or(Performance::NONE, |en| Performance { speed: en.max_speed, acc: en.max_acc, dec: en.max_dec });
        let c = limits(spec.constraints, performance);
        let mut rt = LongDistanceRt {
            target,
            value,
            time_gap,
            freespace: spec.freespace,
            continuous: spec.continuous,
            cs: spec.coordinate_system.unwrap_or(CoordinateSystem::Entity),
            side: Some(1.0),
            max_acc: c.acc,
            max_dec: c.dec,
            max_acc_rate: c.acc_rate,
            max_dec_rate: c.dec_rate,
            max_speed: c.speed,
            acceleration: 0.0,
        };
        // Before 1.1 esmini reads no displacement and keeps the sign of the distance or time
        // gap (ScenarioReader::parseOSCPrivateAction, LongDistanceAction::Step: displacement
        // NONE); from 1.1 on it takes the magnitude and the displacement's side.
        rt.side = match spec.displacement.unwrap_or(LongitudinalDisplacement::TrailingReferencedEntity) {
            _ if self.scenario.header.rev_minor < 1 => None,
            LongitudinalDisplacement::TrailingReferencedEntity => Some(1.0),
            LongitudinalDisplacement::LeadingReferencedEntity => Some(-1.0),
            LongitudinalDisplacement::Any => {
                if self.any_side_gap(e, &rt) < 0.0 {
                    Some(-1.0)
                } else {
                    Some(1.0)
                }
            }
        };
        if let Some(Kept::LongDistance(k)) = self.actions.get(slot).and_then(|s| s.kept_for(e)) {
            // The object's state from the last execution (LongDistanceKept).
            rt.side = k.side;
            rt.acceleration = k.acceleration;
        }
        ActionRt::LongDistance(Box::new(rt))
    }

    /// One step; true when the action is done.
    pub(super) fn step_long_distance(&mut self, e: usize, r: &mut LongDistanceRt) -> bool {
        let dt = self.dt;
        let distance = self.long_gap(e, r);
        let (Some(me), Some(other)) = (self.entities.get(e), self.entities.get(r.target)) else { return true };
        let (speed, ref_speed) = (me.speed, other.speed);
        let written = if r.time_gap { ref_speed.abs() * r.value } else { r.value };
        let requested = match r.side {
            Some(side) => side * written.abs(),
            None => written,
        };
        let diff = distance - requested;
        let done = !r.continuous && diff.abs() < THRESHOLD;
        if r.max_acc >= LARGE && r.max_dec >= LARGE {
            let net = self.net;
            if let Some(en) = self.entities.get_mut(e) {
                match (net, en.lane) {
                    (Some(net), Some(mut lp)) => {
                        // LongDistanceAction::Step: pos_.MoveAlongS(distance_diff), junction
                        // selector angle −1: an arm is drawn (after a route's).
                        move_along_s_drawn(net, &mut lp, diff, en.route.as_deref(), &mut self.random);
                        en.set_lane_pos(net, lp);
                    }
                    _ => {
                        en.x += diff * en.h.cos();
                        en.y += diff * en.h.sin();
                    }
                }
                en.speed = ref_speed;
            }
            return done;
        }
        let tension = if diff < 0.0 { r.max_acc } else { r.max_dec };
        let k = tension * SPRING;
        let damping = 2.0 * k.sqrt();
        let mut acc = diff * k - (speed - ref_speed) * damping;
        let jerk;
        if acc < 0.0 {
            jerk = -r.max_dec_rate;
            acc = acc.max(-r.max_dec);
        } else {
            jerk = r.max_acc_rate;
            acc = acc.min(r.max_acc);
        }
        if jerk < 0.0 && acc < r.acceleration {
            acc = acc.max(r.acceleration + jerk * dt);
        } else if jerk > 0.0 && acc > r.acceleration {
            acc = acc.min(r.acceleration + jerk * dt);
        }
        r.acceleration = acc;
        let v = (speed + acc * dt).clamp(-r.max_speed, r.max_speed);
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = v;
        }
        done
    }
}
