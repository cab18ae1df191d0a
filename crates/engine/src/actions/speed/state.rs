//! What a running SpeedAction remembers: its transition and target.

use crate::dynamics::Transition;
use crate::entities::Entity;

#[derive(Debug, Clone)]
pub(crate) enum Target {
    Absolute(f64),
    Relative { entity: usize, value: f64, factor: bool, continuous: bool },
}

impl Target {
    /// The target now: a relative target follows the reference entity's current speed, also
    /// when it is not continuous (esmini's LongSpeedAction::TargetRelative::GetValue).
    pub(super) fn value(&self, entities: &[Entity]) -> f64 {
        match *self {
            Target::Absolute(v) => v,
            Target::Relative { entity, value, factor, .. } => {
                let ref_speed = entities.get(entity).map_or(0.0, |e| e.speed);
                if factor {
                    ref_speed * value
                } else {
                    ref_speed + value
                }
            }
        }
    }

    pub(super) fn is_relative(&self) -> bool {
        matches!(self, Target::Relative { .. })
    }

    pub(super) fn continuous(&self) -> bool {
        matches!(self, Target::Relative { continuous: true, .. })
    }
}

#[derive(Debug, Clone)]
pub(crate) struct SpeedRt {
    pub transition: Transition,
    pub target: Target,
    pub reached: bool,
    /// For a distance's dynamics: the time span Start made of it, which esmini's transition
    /// keeps in place of the distance (SetParamTargetVal) and its next Start reads as the
    /// distance (`Kept::Speed`).
    pub distance_span: Option<f64>,
}

/// What a distance-dimensioned SpeedAction's esmini object keeps for its next execution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SpeedKept {
    /// The transition's parameter target: the time span the last Start computed.
    pub param_target: f64,
}
