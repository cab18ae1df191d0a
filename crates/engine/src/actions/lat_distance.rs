//! LateralDistanceAction in the road coordinate system: keep a lateral distance (t along the
//! road) to the left or right of a reference entity.
//!
//! As esmini: the first step only records the position (the default controller moves the
//! entity). Then the distance error is the wanted t (reference t ± distance, ± half the two
//! widths with freespace) minus the actor's t. Without any limit the actor jumps onto it; with
//! only a maximum speed it moves sideways at min(max speed, speed) until the error changes
//! sign; with a maximum acceleration a critically damped spring (stiffness 0.4 × the limit)
//! pulls the lateral velocity, its acceleration clipped to the limit and the lateral speed to
//! min(max speed, speed). The actor keeps its lane id (the offset grows past the lane), moves
//! along the road by √(v² − v_lat²)·dt, and heads along its displacement. A non-continuous
//! action ends when the error is below 0.01 m. The entity coordinate system is not supported
//! (warning; the action ends).

use super::ActionRt;
use crate::roads::lane_geometry::lane_center_t;
use crate::roads::move_along_s;
use crate::sim::Sim;
use openscenario::{CoordinateSystem, DynamicConstraints, LateralDisplacement};

const LARGE: f64 = 1e10;
const SMALL: f64 = 1e-10;
const SPRING: f64 = 0.4;
/// Distance error below which a non-continuous action is done, m.
const THRESHOLD: f64 = 0.01;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    Init,
    Rigid,
    Dynamic,
}

#[derive(Debug, Clone)]
pub struct LatDistanceRt {
    /// The action's slot, for its warning.
    slot: usize,
    target: usize,
    /// Signed wanted t of the actor relative to the reference (+ left).
    wanted: f64,
    continuous: bool,
    max_acc: f64,
    max_acc_rate: f64,
    max_speed: f64,
    phase: Phase,
    lat_vel: f64,
    acceleration: f64,
    old: (f64, f64),
}

/// The lateral action's parameters as the model gives them.
pub struct LatDistanceSpec<'s> {
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
        let cs = spec.coordinate_system.unwrap_or(CoordinateSystem::Entity);
        if !matches!(cs, CoordinateSystem::Road | CoordinateSystem::Lane) {
            self.warn_action(slot, "LateralDistanceAction: only the road coordinate system is supported; the action completes at once".into());
            return ActionRt::Done;
        }
        let (Some(a), Some(b)) = (self.entities.get(e), self.entities.get(target)) else { return ActionRt::Done };
        // Left of the reference: larger t (esmini's default for "any" too).
        let side = if spec.displacement == Some(LateralDisplacement::RightToReferencedEntity) { -1.0 } else { 1.0 };
        let mut wanted = side * spec.distance.unwrap_or(0.0).abs();
        if spec.freespace {
            wanted += side * (a.bbox[4] + b.bbox[4]) / 2.0;
        }
        let c = spec.constraints;
        let lim = |v: Option<f64>| v.filter(|x| *x > 0.0).unwrap_or(LARGE);
        ActionRt::LatDistance(Box::new(LatDistanceRt {
            slot,
            target,
            wanted,
            continuous: spec.continuous,
            max_acc: lim(c.and_then(|c| c.max_acceleration)),
            max_acc_rate: lim(c.and_then(|c| c.max_acceleration_rate)),
            max_speed: lim(c.and_then(|c| c.max_speed)),
            phase: Phase::Init,
            lat_vel: 0.0,
            acceleration: 0.0,
            old: (a.x, a.y),
        }))
    }

    /// (actor t, reference t, reference lateral velocity); `None` off the roads.
    fn lat_state(&self, e: usize, r: &LatDistanceRt) -> Option<(f64, f64, f64)> {
        let net = self.net?;
        let a = self.entities.get(e)?.lane?;
        let b_en = self.entities.get(r.target)?;
        let b = b_en.lane?;
        let t_of = |p: &crate::roads::LanePos| net.roads.get(p.road).and_then(|rd| lane_center_t(rd, p.lane_id, p.s)).map(|c| c + p.offset);
        // esmini's lateral velocity of the reference is taken in its own frame (≈ 0 for a
        // vehicle, even during a lane change: it moves along its heading).
        let vel_lat = -b_en.vel.0 * b_en.h.sin() + b_en.vel.1 * b_en.h.cos();
        let (ta, mut tb) = (t_of(&a)?, t_of(&b)?);
        if a.road != b.road {
            // Different roads: compare across the link only when they run the same way.
            tb *= a.dir * b.dir;
        }
        Some((ta, tb, vel_lat))
    }

    pub(super) fn step_lat_distance(&mut self, e: usize, r: &mut LatDistanceRt) -> bool {
        let dt = self.dt;
        let Some(net) = self.net else { return true };
        let Some((ta, tb, vel_lat)) = self.lat_state(e, r) else { return true };
        if self.entities.get(e).and_then(|a| a.lane).map(|l| l.road) != self.entities.get(r.target).and_then(|b| b.lane).map(|l| l.road) {
            // esmini measures the distance across roads through its road-path delta (lane
            // mapping and facing of the found path), which is not reproduced.
            self.warn_action(
                r.slot,
                "LateralDistanceAction: the actor and the reference are on different roads; the lateral distance across the link is approximated (t compared when the roads run the same way)".into(),
            );
        }
        let Some(en) = self.entities.get_mut(e) else { return true };
        let Some(mut lp) = en.lane else { return true };
        let error = tb + r.wanted - ta;
        match r.phase {
            Phase::Init => {
                r.phase = if r.max_speed >= LARGE && r.max_acc >= LARGE { Phase::Rigid } else { Phase::Dynamic };
                r.old = (en.x, en.y);
                return false;
            }
            Phase::Rigid => {
                lp.offset += error;
                en.set_lane_pos(net, lp);
                let done = !r.continuous && error.abs() < THRESHOLD;
                Self::head_along(en, r);
                return done;
            }
            Phase::Dynamic => {}
        }
        let mut done = false;
        let speed_cap = r.max_speed.min(en.speed) - SMALL;
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
        move_along_s(net, &mut lp, long_vel * dt);
        lp.offset += r.lat_vel * dt;
        en.set_lane_pos(net, lp);
        Self::head_along(en, r);
        en.moved_by_action = true;
        done
    }

    fn head_along(en: &mut crate::entities::Entity, r: &mut LatDistanceRt) {
        let (dx, dy) = (en.x - r.old.0, en.y - r.old.1);
        if dx * dx + dy * dy > 0.0 {
            en.h = crate::entities::wrap_2pi(dy.atan2(dx));
        }
        r.old = (en.x, en.y);
    }
}
