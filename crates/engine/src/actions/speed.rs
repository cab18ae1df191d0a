//! SpeedAction: the speed follows a transition shape from the current speed to an absolute or
//! relative target, over time, distance (converted to time from the mean speed) or at a rate;
//! the peak rate is limited by the vehicle's maximum acceleration / deceleration. A continuous
//! relative target keeps tracking the reference entity and never ends.

use super::ActionRt;
use crate::dynamics::{sign, Transition, SMALL};
use crate::entities::Entity;
use crate::sim::Sim;
use openscenario::{DynamicsDimension, SpeedTarget, SpeedTargetValueType, TransitionDynamics};

#[derive(Debug, Clone)]
pub enum Target {
    Absolute(f64),
    Relative { entity: usize, value: f64, factor: bool, continuous: bool, sampled: Option<f64> },
}

impl Target {
    fn value(&mut self, entities: &[Entity]) -> f64 {
        match self {
            Target::Absolute(v) => *v,
            Target::Relative { entity, value, factor, continuous, sampled } => {
                let ref_speed = match (*continuous, *sampled) {
                    (false, Some(s)) => s,
                    _ => {
                        let s = entities.get(*entity).map_or(0.0, |e| e.speed);
                        *sampled = Some(s);
                        s
                    }
                };
                if *factor {
                    ref_speed * *value
                } else {
                    ref_speed + *value
                }
            }
        }
    }

    fn continuous(&self) -> bool {
        matches!(self, Target::Relative { continuous: true, .. })
    }
}

#[derive(Debug, Clone)]
pub struct SpeedRt {
    pub transition: Transition,
    pub target: Target,
    pub reached: bool,
}

fn abs_limit(v: f64, limit: f64) -> f64 {
    if v.abs() > limit.abs() {
        sign(v) * limit.abs()
    } else {
        v
    }
}

impl<'a> Sim<'a> {
    pub(super) fn start_speed(&mut self, slot: usize, e: usize, dyn_: &TransitionDynamics, target: &SpeedTarget) -> ActionRt {
        let mut target = match target {
            SpeedTarget::Absolute { value } => Target::Absolute(*value),
            SpeedTarget::Relative { entity, value, value_type, continuous } => match self.entity_index(entity) {
                Some(i) => Target::Relative {
                    entity: i,
                    value: *value,
                    factor: *value_type == SpeedTargetValueType::Factor,
                    continuous: *continuous,
                    sampled: None,
                },
                None => {
                    self.warn_action(slot, format!("SpeedAction: unknown reference entity `{entity}`"));
                    return ActionRt::Done;
                }
            },
        };
        let Some(speed) = self.entities.get(e).map(|x| x.speed) else { return ActionRt::Done };
        let mut t = Transition::new(dyn_.shape, dyn_.dimension, dyn_.value);
        t.set_start(speed);
        let v1 = target.value(&self.entities);
        if dyn_.dimension == DynamicsDimension::Distance {
            // The shape is applied over time: the time that covers the distance.
            let (v0, dist) = (speed, t.param_target);
            let span = if (v1 - v0).abs() < SMALL {
                0.0
            } else if v0.abs() > SMALL && v1.abs() > SMALL && sign(v0) != sign(v1) {
                let f = (v0 * v0 / (v0 * v0 + v1 * v1)).abs();
                let d0 = f * dist;
                2.0 * d0 / v0.abs() + 2.0 * (dist - d0) / v1.abs()
            } else {
                2.0 * dist / (v0 + v1).abs()
            };
            t.dimension = DynamicsDimension::Time;
            t.set_param_target(span);
        }
        t.set_target(v1);
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = t.value();
        }
        ActionRt::Speed(SpeedRt { transition: t, target, reached: false })
    }

    /// One step; true when the action is done.
    pub(super) fn step_speed(&mut self, e: usize, s: &mut SpeedRt) -> bool {
        let Some(en) = self.entities.get(e) else { return true };
        let (max_speed, max_acc, max_dec, cur) = (en.max_speed, en.max_acc, en.max_dec, en.speed);
        let tv = s.target.value(&self.entities);
        s.transition.set_target(abs_limit(tv, max_speed));
        let new_speed = if s.reached {
            tv
        } else {
            let t = &mut s.transition;
            if t.target > t.start {
                t.set_max_rate(max_acc);
            } else {
                t.set_max_rate(max_dec);
            }
            t.step(self.dt);
            let v = t.value();
            if t.param > t.param_target - SMALL || (v - t.target).abs() < SMALL || sign(tv - t.start) != sign(tv - cur) {
                s.reached = true;
                tv
            } else {
                v
            }
        };
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = abs_limit(new_speed, max_speed);
        }
        s.reached && !s.target.continuous()
    }
}
