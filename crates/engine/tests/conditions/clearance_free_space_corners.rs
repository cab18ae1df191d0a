//! RelativeClearanceCondition with freeSpace: esmini's Object::FreeSpaceDistanceObjectRoadLane
//! takes the lane difference between the two front right corners, so Ego's clearance to the
//! right opens when its front right corner crosses into the next lane, before its centre does
//! (fixture `clearance_free_space_corners.xosc`, esmini 3.6.0: 1.92 s; by the centre: never).

use crate::common::*;

#[test]
fn free_space_clearance_counts_lanes_by_the_front_right_corners() {
    let run = run_straight_fixture("clearance_free_space_corners.xosc", 6.0);
    let t = event_time(&run, "ByCorners", "start").expect("clearance by the corners opened");
    assert!((1.91..=1.93).contains(&t), "{t}");
    assert_eq!(event_time(&run, "ByCentre", "start"), None);
}
