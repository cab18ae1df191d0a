//! A freespace distance from an entity's box to a point in road or lane coordinates is
//! esmini's Object::FreeSpaceDistancePointRoadLane: the corners' deltas to the point, the one
//! smallest in magnitude, zero only where it and the largest differ in sign (fixture
//! `freespace_point_corners.xosc`; esmini 3.6.0 logs dist 0.40, 2.32 and 96.12 m at 0 s and
//! starts LatOneSide, LatTurned and LongTurned then; the entity's half extents gave 0, 2.5 and
//! 96.25 m).

use crate::common::*;

#[test]
fn a_turned_box_is_measured_from_its_corners() {
    let run = run_straight_fixture("freespace_point_corners.xosc", 1.0);
    for name in ["LatOneSide", "LatTurned", "LongTurned"] {
        assert_eq!(event_time(&run, name, "start"), Some(0.0), "{name}");
    }
}
