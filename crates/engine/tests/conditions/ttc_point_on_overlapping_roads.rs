//! A TimeToCollisionCondition to a point where several roads lie equally near (fixture
//! `ttc_point_on_overlapping_connectors.xosc` on `crossing.xodr`: the centre of the crossing,
//! on the reference line of the four straight connecting roads). Without freespace esmini's
//! Position::Distance maps the point by a fresh Position, with no current road: XYZ2TrackPos
//! keeps the first of the equally near roads (101, joined to Ego's road 3), and the lateral
//! distance along the road path is 5.25 m, a time to collision of 0.525 s at 10 m/s. esmini
//! 3.6.0 starts TtcUnderOne (< 1 s) at 0 s and never TtcOverOne (> 1 s). Mapped from Ego's
//! road the point went to road 110, joined to nothing of Ego's: not measured (LARGE_NUMBER).

use crate::common::*;

#[test]
fn a_point_on_overlapping_roads_goes_to_the_first_as_a_fresh_position_maps_it() {
    let run = run_fixture_on("ttc_point_on_overlapping_connectors.xosc", "crossing.xodr", 1.0);
    assert_eq!(event_time(&run, "TtcUnderOne", "start"), Some(0.0));
    assert_eq!(event_time(&run, "TtcOverOne", "start"), None);
}
