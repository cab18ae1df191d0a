//! SpeedAction: the speed follows a transition shape from the current speed to an absolute or
//! relative target, over time, distance (converted to time from the mean speed) or at a rate.
//! The shape is stretched once at the start so its peak rate stays within the vehicle's maximum
//! acceleration / deceleration, and every step is limited to them again. A relative target reads
//! the reference entity's speed every step (continuous or not); a continuous one never ends.
//! All of it follows esmini's LongSpeedAction::Start / Step.

pub(crate) mod state;

use state::{SpeedRt, Target};

use super::state::ActionRt;
use crate::dynamics::{abs_limit, sign, Transition};
use crate::sim::Sim;
use openscenario::{DynamicsDimension, DynamicsShape, SpeedTarget, SpeedTargetValueType, TransitionDynamics};

use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;

/// The shape's value; an empty span (time or distance under SMALL_NUMBER) is a step
/// (esmini's TransitionDynamics::Evaluate).
fn evaluate(t: &Transition) -> f64 {
    if t.shape == DynamicsShape::Step || (t.dimension != DynamicsDimension::Rate && t.param_target < SMALL_NUMBER) {
        t.target
    } else {
        t.value()
    }
}

impl<'a> Sim<'a> {
    /// esmini's LongSpeedAction::Start.
    pub(super) fn start_speed(&mut self, slot: usize, e: usize, dyn_: &TransitionDynamics, target: &SpeedTarget) -> ActionRt {
        if self.longitudinal_overridden(e) {
            // esmini's LongSpeedAction::Start: a controller in override mode drives the
            // entity's speed; the action ends at once and changes nothing.
            return ActionRt::EndedAtStart;
        }
        let target = match target {
            SpeedTarget::Absolute { value } => Target::Absolute(*value),
            SpeedTarget::Relative { entity, value, value_type, continuous } => match self.action_ref_index(slot, entity) {
                Some(i) => Target::Relative { entity: i, value: *value, factor: *value_type == SpeedTargetValueType::Factor, continuous: *continuous },
                None => {
                    self.warn_action(slot, format!("SpeedAction: unknown reference entity `{entity}`"));
                    return ActionRt::Done;
                }
            },
        };
        let Some((speed, max_speed, max_acc, max_dec)) = self.entities.get(e).map(|x| (x.speed, x.max_speed, x.max_acc, x.max_dec)) else {
            return ActionRt::Done;
        };
        // esmini's ScenarioReader::ParseTransitionDynamics reads a step's value as 0 whatever
        // the file says: a step with a time or distance still ends in its first step.
        let value = if dyn_.shape == DynamicsShape::Step { 0.0 } else { dyn_.value };
        let mut t = Transition::new(dyn_.shape, dyn_.dimension, value);
        if dyn_.dimension != DynamicsDimension::Rate {
            // esmini keeps the span as given: zero means "at once" (see `evaluate`).
            t.param_target = value;
        }
        t.set_start(speed);
        let v1 = target.value(&self.entities);
        let mut distance_span = None;
        if dyn_.dimension == DynamicsDimension::Distance {
            // The shape runs over time: the time that covers the distance. esmini's transition
            // keeps that time in place of the distance (SetParamTargetVal), and the action
            // executed again reads it as its distance.
            let dist = match self.actions.get(slot).and_then(|s| s.kept_for(e)) {
                Some(super::state::Kept::Speed(k)) => k.param_target,
                _ => value,
            };
            let v0 = speed;
            let span = if (v1 - v0).abs() < SMALL_NUMBER {
                0.0
            } else if v0.abs() > SMALL_NUMBER && v1.abs() > SMALL_NUMBER && sign(v0) != sign(v1) {
                // The speed changes sign: two parts, split where it passes zero.
                let f = (v0 * v0 / (v0 * v0 + v1 * v1)).abs();
                let d0 = f * dist;
                2.0 * d0 / v0.abs() + 2.0 * (dist - d0) / v1.abs()
            } else {
                2.0 * dist / (v0 + v1).abs()
            };
            t.dimension = DynamicsDimension::Time;
            t.param_target = span;
            distance_span = Some(span);
        }
        t.set_target(abs_limit(v1, max_speed));
        // The peak rate is checked once, against the limit of the direction of change.
        t.set_max_rate(if t.target > t.start { max_acc } else { max_dec });
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = evaluate(&t);
        }
        ActionRt::Speed(SpeedRt { transition: t, target, reached: false, distance_span })
    }

    /// One step (esmini's LongSpeedAction::Step); true when the action is done.
    pub(super) fn step_speed(&mut self, e: usize, s: &mut SpeedRt) -> bool {
        if self.longitudinal_overridden(e) {
            // esmini's LongSpeedAction::Step: ends once a controller overrides the speed.
            return true;
        }
        let Some(en) = self.entities.get(e) else { return true };
        let (max_speed, max_acc, max_dec, cur) = (en.max_speed, en.max_acc, en.max_dec, en.speed);
        let dt = self.dt;
        let tv = s.target.value(&self.entities);
        let t = &mut s.transition;
        if s.target.is_relative() {
            t.set_target(abs_limit(tv, max_speed));
        }
        let mut new_speed = if t.param_target > 0.0 && t.param > t.param_target - SMALL_NUMBER {
            // After the shape: approach the target within the acceleration limits.
            let acc = if dt > SMALL_NUMBER { (tv - cur) / dt } else { 0.0 };
            abs_limit(cur + acc.clamp(-max_dec, max_acc) * dt, max_speed)
        } else {
            t.step(dt);
            let v = evaluate(t);
            let acc_required = if dt > SMALL_NUMBER { (v - cur) / dt } else { 0.0 };
            if acc_required > max_acc + SMALL_NUMBER || acc_required < -(max_dec + SMALL_NUMBER) {
                // Too big a step: take what the limits allow and move the shape back by the
                // part of the step not taken.
                let limited = abs_limit(cur + acc_required.clamp(-max_dec, max_acc) * dt, max_speed);
                let step_approx = (limited - cur) / acc_required;
                t.step(-(dt - step_approx));
                limited
            } else {
                v
            }
        };
        if t.param > t.param_target - SMALL_NUMBER && (new_speed - t.target).abs() < SMALL_NUMBER {
            s.reached = true;
            new_speed = abs_limit(tv, max_speed);
        }
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = new_speed;
        }
        s.reached && !s.target.continuous()
    }
}
