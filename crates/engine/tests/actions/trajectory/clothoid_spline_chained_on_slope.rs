//! A ClothoidSpline segment without a start of its own begins where the previous one ends, as
//! esmini places that end: ClothoidSplineShape::Freeze starts it from the previous segment's
//! `posEnd_`, set by SetInertiaPos(x, y, h), whose heading EvaluateHPR composes with the road's
//! pitch and roll there. On a sloped or banked road that is not the spiral's own end heading
//! (a few milliradians here), and the rest of the spline turns with it. Found by a helper on
//! s59059_00414 (straight_500_superelevation_elevation_curve).
//!
//! Fixture `clothoid_spline_chained_on_banked_slope.xosc` on sloped_banked.xodr (slope 0.1,
//! superelevation 0.4): Car0 at 6 m/s follows a 20 m segment from its lane position and a 30 m
//! segment chained to it; esmini 3.6.0's numbers. With the spiral's end heading the second
//! segment started 2 mrad off and the car ended 0.14 m away.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_chained_segment_starts_at_the_previous_end_as_placed_on_the_road() {
    assert_fixture_matches_esmini(
        "clothoid_spline_chained_on_banked_slope.xosc",
        8.0,
        &[("Car0", 3.0, 65.003148, -1.333824, 0.051786), ("Car0", 6.0, 82.859884, 0.847687, 0.15536), ("Car0", 8.0, 94.70837, 2.744931, 0.125746)],
    );
}

/// The chained segment's start is placed where the first segment ends, in the map's own
/// coordinates: on a map whose header offsets and turns them, resolving that end again as a
/// scenario's world position moved it by the offset a second time (s33033_00154 on offset.xodr,
/// found when the rule above was first written that way). Fixture
/// `trajectory_position_chained_clothoid_on_offset_map.xosc` on straight_offset.xodr: Car0
/// placed 32.5 m along the spline (on the chained segment), 0.5 m to its left.
#[test]
fn on_an_offset_map_the_chained_segment_starts_where_the_first_ends() {
    assert_fixture_matches_esmini("trajectory_position_chained_clothoid_on_offset_map.xosc", 0.5, &[("Car0", 0.0, 6.265352, 31.489203, 1.597833)]);
}
