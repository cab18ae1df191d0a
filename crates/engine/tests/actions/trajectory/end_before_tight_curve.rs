//! Where a car goes on from at the end of a trajectory: the position keeps the s esmini's
//! XYZ2TrackPos interpolated between the normals of the lane-0 OSI segment, not the exact
//! projection's. Before a tight curve the straight piece's last vertex lies inside the arc,
//! the normals meet far off, and the two differ by a metre, so the default controller's first
//! move after the trajectory jumps. Found by a helper on s66066_00941 (ref_point).
//!
//! Fixture `trajectory_end_before_tight_curve.xosc` on bend_r5.xodr: "Far" follows a polyline
//! 15 m right of the road from x 30 to 25 and jumps back 1.03 m at 0.51 s (x 23.87); "Ego",
//! placed beside it without a trajectory, drives on evenly. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_trajectory_ends_at_the_s_of_its_osi_segment() {
    assert_fixture_matches_esmini(
        "trajectory_end_before_tight_curve.xosc",
        1.5,
        &[
            ("Far", 0.51, 23.871337, -15.0, std::f64::consts::PI),
            ("Ego", 0.51, 24.830648, -1.5, std::f64::consts::PI),
            ("Far", 1.0, 18.971337, -15.0, std::f64::consts::PI),
        ],
    );
}
