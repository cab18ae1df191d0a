//! Of two cars at the end of a road, an ACC takes the one driven past the end as its lead, not
//! the one stopped there: XYZ2TrackPos gives a point beyond the end the s of the road's last
//! OSI point, `SMALL_NUMBER / 2` short of the end (OpenDrive::SetLaneOSIPoints), while a car
//! stopped by a move along s has the road's length; ControllerACC::Step replaces its lead only
//! by a strictly nearer one. The engine projected the point onto the end, a tie the first car
//! won. Found by a helper on s67067_00786.
//!
//! Fixture `acc_prefers_car_past_road_end.xosc` on difftest_straight.xodr (2000 m): Ego's ACC
//! (override) behind Lead, which stops at the end at 2.5 s, and Far, a FollowGhost car that
//! runs off the end. From 2.5 s esmini's Ego follows Far, faster: at 3 s x 1977.818 (5.8 cm
//! behind where following Lead put it). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_acc_follows_the_car_past_the_end() {
    assert_fixture_matches_esmini("acc_prefers_car_past_road_end.xosc", 3.5, &[("Ego", 3.0, 1977.817998, -1.75, 0.0)]);
}
