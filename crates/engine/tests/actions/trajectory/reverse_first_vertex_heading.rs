//! A car reversing onto an untimed polyline whose first vertex gives its heading, though not
//! every vertex does: esmini's FollowTrajectoryAction::Start asks IsHSetExplicitly of the
//! trajectory evaluated at the start, which is the mode of the vertex the first segment starts
//! at (PolyLineBase::EvaluateSegmentByLocalS copies that vertex's pos_mode), so the entity
//! faces as that vertex says and moves by how its heading lies to the path — as with every
//! vertex giving one (`reverse_vertex_headings.rs`). A vertex given as a lane position takes
//! the lane's heading. Found by crates/difftest (s55055_00770, where the engine turned the car
//! by π and warned that partly explicit headings were not modelled).
//!
//! Fixture `trajectory_reverse_first_vertex_heading.xosc` on straight.xodr: Reverser at
//! −3 m/s starts at 0.5 s on a polyline from x 50 (h 0.1) through a lane position at s 40 to
//! x 30 (h 0.1): it faces 0.1, against the path, and runs along it towards x 30. esmini 3.6.0's
//! numbers; the run stops before the middle vertex, where esmini's heading interpolation while
//! reversing is not matched yet.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn reversing_onto_a_polyline_faces_its_first_vertex_heading() {
    let run = assert_fixture_matches_esmini(
        "trajectory_reverse_first_vertex_heading.xosc",
        3.5,
        &[("Reverser", 0.52, 49.97, -1.75, 0.1), ("Reverser", 1.0, 48.53, -1.75, 0.1), ("Reverser", 3.5, 41.03, -1.75, 0.837586)],
    );
    // Where the explicit headings stop (the lane position), esmini's motion is not modelled,
    // and the run says so.
    assert!(run.warnings.iter().any(|w| w.message.contains("explicit vertex headings")), "{:?}", run.warnings);
}
