//! Time headway and time to collision where they are not defined (esmini's
//! TrigByTimeHeadway / TrigByTimeToCollision): the entity counts as false without deciding the
//! rule `all`; and a euclidean distance is signed by the entity's own frame in the lane
//! coordinate system too (Position::getRelativeDistance), so a point behind has no TTC
//! (fixture `undefined_headway_ttc.xosc`; esmini 3.6.0: HeadwayAll and TtcAheadLane at 2.01 s,
//! TtcBehindLane never).

use crate::common::*;

#[test]
fn an_undefined_headway_leaves_the_rule_all_to_the_next_entity() {
    let run = run_straight_fixture("undefined_headway_ttc.xosc", 6.0);
    let t = event_time(&run, "HeadwayAll", "start").expect("headway of Ego decided");
    assert!((2.0..=2.02).contains(&t), "{t}");
}

#[test]
fn a_point_behind_has_no_time_to_collision_in_the_lane_frame() {
    let run = run_straight_fixture("undefined_headway_ttc.xosc", 6.0);
    assert_eq!(event_time(&run, "TtcBehindLane", "start"), None);
    let t = event_time(&run, "TtcAheadLane", "start").expect("ttc to the point ahead");
    assert!((2.0..=2.02).contains(&t), "{t}");
}
