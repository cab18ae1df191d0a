//! Cars reversing onto untimed polylines whose every vertex gives its heading: esmini 3.6's
//! FollowTrajectoryAction::Start faces the entity as the vertices say (IsHSetExplicitly, no turn
//! by π) and takes the sign of its motion from how that heading lies to the path
//! (initialHeadingSign_); Move goes sign(speed) × that sign along the path. Headings pointing
//! forward: the car backs off the start, where PolyLineBase::Evaluate keeps the s below zero
//! (no distance left over), the action ends at once and the car reverses on along the road.
//! Headings pointing back: the car runs forward along the path facing backwards.
//!
//! Fixture `trajectory_reverse_vertex_headings.xosc` on straight.xodr: two cars at −5 m/s
//! whose polylines (60 → 100 m) start at 1 s. The numbers are esmini 3.6.0's run; where esmini
//! runs here the whole run is compared.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn reversing_onto_vertex_headings_moves_by_how_they_lie_to_the_path() {
    let run = assert_fixture_matches_esmini(
        "trajectory_reverse_vertex_headings.xosc",
        20.0,
        &[
            // Put on the start, then reversing along the road, facing forward.
            ("Along", 1.03, 59.95, -1.75, 0.0),
            ("Along", 4.0, 45.1, -1.75, 0.0),
            // Along the path, facing back as the vertices say.
            ("Against", 4.0, 74.95, -5.25, 3.12),
            ("Against", 8.0, 94.810649, -7.286464, 3.060757),
        ],
    );
    assert!(run.warnings.iter().all(|w| !w.message.contains("explicit vertex headings")), "{:?}", run.warnings);
}
