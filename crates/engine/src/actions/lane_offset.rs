//! LaneOffsetAction: the lateral offset from the lane centre follows the transition shape to an
//! absolute target or to an offset relative to another entity; the span follows from the
//! maximum lateral acceleration. The longitudinal motion stays with the default controller.

pub(crate) mod state;

use state::LaneOffsetRt;

use super::state::ActionRt;
use crate::dynamics::{avoid_zero, sign, Transition};
use crate::roads::lane_geometry::lane_center_t;
use crate::sim::Sim;
use openscenario::{DynamicsDimension, DynamicsShape, LaneOffsetTarget};

/// Lateral acceleration assumed when the action gives none, m/s².
const DEFAULT_MAX_LAT_ACC: f64 = 0.5;

impl<'a> Sim<'a> {
    pub(super) fn start_lane_offset(&mut self, slot: usize, e: usize, shape: DynamicsShape, max_acc: Option<f64>, target: &LaneOffsetTarget) -> ActionRt {
        let (Some(net), Some(lp)) = (self.net, self.entities.get(e).and_then(|x| x.lane)) else {
            self.warn_action(slot, "LaneOffsetAction needs the entity on a road".into());
            return ActionRt::Done;
        };
        let lane_sign = sign(f64::from(lp.lane_id));
        let target_offset = match target {
            LaneOffsetTarget::Absolute { value } => *value,
            LaneOffsetTarget::Relative { entity, value } => {
                let Some(r) = self.action_ref_index(slot, entity).and_then(|i| self.entities[i].lane) else {
                    self.warn_action(slot, format!("LaneOffsetAction: reference entity `{entity}` unknown or off the road"));
                    return ActionRt::Done;
                };
                let Some(road) = net.roads.get(r.road) else { return ActionRt::Done };
                let rt = lane_center_t(road, r.lane_id, r.s).unwrap_or(0.0) + r.offset + value * r.dir;
                let own_c = net.roads.get(lp.road).and_then(|rd| lane_center_t(rd, lp.lane_id, lp.s)).unwrap_or(0.0);
                // esmini's LatLaneOffsetAction::Start: the target is the reference's t moved by
                // the value (leftwards when the reference faces along s), taken as a lane offset
                // (t from the actor's lane centre), like an absolute value.
                rt - own_c
            }
        };
        let mut t = Transition::new(shape, DynamicsDimension::Time, 1.0);
        t.set_target(lane_sign * target_offset);
        t.set_start(lane_sign * lp.offset);
        let acc = max_acc.filter(|a| *a > 0.0).unwrap_or(DEFAULT_MAX_LAT_ACC);
        let span = t.param_by_peak_acc(acc);
        t.set_param_target(span);
        ActionRt::LaneOffset(LaneOffsetRt { transition: t })
    }

    pub(super) fn step_lane_offset(&mut self, e: usize, l: &mut LaneOffsetRt) -> bool {
        let Some(net) = self.net else { return true };
        let Some(en) = self.entities.get_mut(e) else { return true };
        let Some(mut lp) = en.lane else { return true };
        let t = &mut l.transition;
        let v = t.value();
        let lane_sign = sign(f64::from(lp.lane_id));
        let done = t.done(v);
        if done {
            lp.offset = lane_sign * t.target;
            en.yaw_offset = 0.0;
        } else {
            lp.offset = lane_sign * v;
            let angle = (t.derivative() / avoid_zero(en.speed)).atan();
            en.yaw_offset = lp.dir * lane_sign * angle;
        }
        en.set_lane_pos(net, lp);
        t.step(self.dt);
        done
    }
}
