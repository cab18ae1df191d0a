//! esmini's Position::GetDrivingDirection, bit for bit: the road heading turned by π with
//! GetAngleSum (which wraps into [0, 2π)) for a lane left of the reference line, and once more
//! under left-hand traffic. Road paths (RoadPath::Calculate) turn a distance negative when the
//! heading a position holds differs from it by more than π/2 (GetHRelativeDrivingDirection, an
//! angle difference in [−π, π]); for an entity facing exactly against its lane the difference is
//! ±π by rounding, and these bits decide which.

use crate::angles::{angle_difference, wrap_2pi};
use opendrive::TrafficRule;
use std::f64::consts::{FRAC_PI_2, PI};

/// The driving direction of lane `lane_id` on a road of traffic `rule` whose heading is `road_h`.
pub(crate) fn driving_direction(rule: TrafficRule, lane_id: i32, road_h: f64) -> f64 {
    let mut h = road_h;
    if lane_id > 0 {
        h = wrap_2pi(h + PI);
    }
    if rule == TrafficRule::LeftHand {
        h = wrap_2pi(h + PI);
    }
    h
}

/// Whether a position holding heading `held_h` faces against that driving direction
/// (GetHRelativeDrivingDirection past π/2).
pub(crate) fn faces_against(rule: TrafficRule, lane_id: i32, road_h: f64, held_h: f64) -> bool {
    angle_difference(held_h, driving_direction(rule, lane_id, road_h)) > FRAC_PI_2
}
