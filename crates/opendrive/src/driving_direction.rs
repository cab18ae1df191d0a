//! Which way traffic flows in a lane, from the lane side and the road's traffic rule.

use crate::model::road::TrafficRule;

/// Whether traffic in lane `lane_id` drives along +s.
///
/// Right-hand traffic drives on the right: right lanes (negative ids) go with s, left lanes
/// against it. Left-hand traffic is the mirror image. The centre lane (0) counts as +s.
pub fn drives_along_s(rule: TrafficRule, lane_id: i32) -> bool {
    match rule {
        TrafficRule::RightHand => lane_id <= 0,
        TrafficRule::LeftHand => lane_id >= 0,
    }
}

/// Driving heading of a lane given the reference-line heading at the same s.
pub fn driving_heading(rule: TrafficRule, lane_id: i32, reference_heading: f64) -> f64 {
    if drives_along_s(rule, lane_id) {
        reference_heading
    } else {
        reference_heading + std::f64::consts::PI
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn right_and_left_hand_traffic_mirror() {
        assert!(drives_along_s(TrafficRule::RightHand, -1));
        assert!(!drives_along_s(TrafficRule::RightHand, 2));
        assert!(drives_along_s(TrafficRule::LeftHand, 1));
        assert!(!drives_along_s(TrafficRule::LeftHand, -3));
        let h = driving_heading(TrafficRule::RightHand, 1, 0.25);
        assert!((h - (0.25 + std::f64::consts::PI)).abs() < 1e-15);
    }
}
