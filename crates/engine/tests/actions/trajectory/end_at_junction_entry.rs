//! A trajectory that ends exactly where a road meets its junction: esmini places the follower
//! with Position::SetInertiaPos, and XYZ2TrackPos lets a junction arm directly connected to the
//! current road that contains the point as closely replace it, the least bending arm at its
//! start, the later in the file at a tie. The default controller then drives on along that arm,
//! not the one it would enter itself.
//!
//! Fixture `trajectory_end_at_junction_entry.xosc` on `fork_straight_and_easing.xodr`: both arms
//! have curvature 0 where they start (a straight road 10, then road 11, a spiral easing into a
//! right bend). Exact's polyline ends at the road's end and Exact goes on along road 11;
//! Short's ends 1 m before and Short goes straight on. Before, the engine kept Exact on road 1
//! and took it straight on (18 m from esmini at 8.5 s). The numbers are esmini 3.6.0's run.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_trajectory_ending_at_a_junction_entry_leaves_its_entity_on_the_arm_esmini_attaches() {
    assert_fixture_matches_esmini(
        "trajectory_end_at_junction_entry.xosc",
        9.0,
        &[("Exact", 6.0, 109.857436, -2.95678, 5.904705), ("Exact", 8.0, 124.91416, -15.995553, 5.533185), ("Short", 8.0, 100.0, -1.75, 0.0)],
    );
}
