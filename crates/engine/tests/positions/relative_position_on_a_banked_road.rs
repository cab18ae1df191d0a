//! A relative lane or road position facing relatively on a banked road takes the heading
//! esmini composes twice: Position::EvaluateRelation sets the heading relative to the road
//! (EvaluateHPR composes the road's rotation, its roll and GetPOffset's pitch, with the
//! relative heading), then calls EvaluateHPR again in the position's SET mode, absolute by
//! default (Position::GetModeDefault), which composes the road's rotation with the heading
//! found once more. A LanePosition is composed once. Found by crates/difftest (s31031_00381 on
//! pitch_by_super_elevation.xodr: a RelativeObjectPosition from an entity so placed landed
//! 1.8 m off). Fixture `relative_position_on_a_banked_road.xosc` on `banked.xodr` (roll
//! 0.01·s): Lead on lane −2 at s = 50; Ahead 40 m further by a RelativeLanePosition, Beside
//! 20 m further and 2 m right by a RelativeRoadPosition. Expected values: esmini 3.6.0 on the
//! fixture (headings at the start; moving on, esmini turns them by the relative heading its
//! position keeps, which the engine's lane following does not compose: `attitude.rs`).

use crate::common::*;

#[test]
fn a_relative_position_on_a_banked_road_is_composed_twice() {
    let run = run_fixture_on("relative_position_on_a_banked_road.xosc", "banked.xodr", 2.0);
    let start = [("Lead", 0.0, 50.0, -4.607308, 0.025165), ("Ahead", 0.0, 90.0, -3.263452, 0.066626), ("Beside", 0.0, 70.0, -5.545106, 0.082296)];
    assert_esmini_poses(&run, &start, 1e-5, 1e-5);
    assert_esmini_rows(&run, "Ahead", &[(2.0, 100.0, -2.836587, 5.0)], 1e-5);
    assert_esmini_rows(&run, "Beside", &[(2.0, 80.0, -5.051124, 5.0)], 1e-5);
}
