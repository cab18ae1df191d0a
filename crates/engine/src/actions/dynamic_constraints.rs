//! The limits of a DynamicConstraints element as esmini's ScenarioReader::parseDynamicConstraints
//! reads them, for the actions that plan their own motion (SpeedProfileAction,
//! LongitudinalDistanceAction with the actor's performance; LateralDistanceAction without).

use openscenario::DynamicConstraints;

/// esmini's LARGE_NUMBER: no limit.
pub(crate) const UNLIMITED: f64 = 1e10;
/// esmini's SMALL_NUMBER: a limit under it is taken as not meant.
const SMALL: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;

/// The limits a planner keeps to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Limits {
    pub speed: f64,
    pub acc: f64,
    pub dec: f64,
    pub acc_rate: f64,
    pub dec_rate: f64,
}

/// The performance a limit falls back to and is cut to: the actor's (speed, acceleration,
/// deceleration), or none (`UNLIMITED`) when esmini passes no entity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Performance {
    pub speed: f64,
    pub acc: f64,
    pub dec: f64,
}

impl Performance {
    pub(crate) const NONE: Performance = Performance { speed: UNLIMITED, acc: UNLIMITED, dec: UNLIMITED };
}

/// Without a DynamicConstraints element every limit is unbounded (DynamicConstraints'
/// constructor). With one, a missing attribute is the performance value, a value under
/// SMALL_NUMBER becomes the smaller of esmini's default (maxSpeed 250 km/h, maxAcceleration 5,
/// maxDeceleration 10, the rates none) and the performance, and a value above the performance
/// is cut to it.
pub(crate) fn limits(constraints: Option<&DynamicConstraints>, performance: Performance) -> Limits {
    let Some(c) = constraints else {
        return Limits { speed: UNLIMITED, acc: UNLIMITED, dec: UNLIMITED, acc_rate: UNLIMITED, dec_rate: UNLIMITED };
    };
    let pick = |value: Option<f64>, default: f64, performance: f64| match value {
        None => performance,
        Some(v) if v < SMALL => default.min(performance),
        Some(v) => v.min(performance),
    };
    Limits {
        speed: pick(c.max_speed, 250.0 / 3.6, performance.speed.min(UNLIMITED)),
        acc: pick(c.max_acceleration, 5.0, performance.acc.min(UNLIMITED)),
        dec: pick(c.max_deceleration, 10.0, performance.dec.min(UNLIMITED)),
        acc_rate: pick(c.max_acceleration_rate, UNLIMITED, UNLIMITED),
        dec_rate: pick(c.max_deceleration_rate, UNLIMITED, UNLIMITED),
    }
}
