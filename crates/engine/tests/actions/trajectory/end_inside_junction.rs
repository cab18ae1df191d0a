//! A trajectory that ends inside a junction, on a point where a turning and a straight
//! connecting road overlap: the entity goes on along the straight one. Each step the
//! trajectory places the entity by its world point (Position::XYZ2TrackPos from the road it
//! was on), and once the point is off that road, a road directly connected to it from its lane
//! that contains the point replaces any other containing it, the one bending least at its
//! contact point among them (`roads::junction_entry::entry_connector`); the nearest lane centre
//! alone took the turning road the polyline's last vertex names. Found by crates/difftest
//! (s32032_00660 on the generated crossing, s31031_00647 on its T junction, and four more).
//!
//! Fixture `trajectory_end_inside_junction.xosc` on crossing.xodr: Follower drives west on
//! lane 1 of road 1 at 10 m/s along a polyline that ends at s 6 of lane −1 of connecting road
//! 100 (the right turn), 6 m into the junction; it then keeps straight on (y 2.5665, the
//! straight connecting road 101) instead of turning right. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn after_a_trajectory_ending_in_a_junction_the_entity_goes_straight_on() {
    assert_fixture_matches_esmini(
        "trajectory_end_inside_junction.xosc",
        6.0,
        &[
            ("Follower", 2.59, 14.163076, 2.566508, 3.109567),
            ("Follower", 4.0, 0.063076, 2.566508, 3.109567),
            ("Follower", 6.0, -19.936924, 2.566508, 3.109567),
        ],
    );
}
