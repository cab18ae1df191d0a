//! During a lane change esmini's heading carries the drift of the target lane: LatLaneChangeAction::Step
//! calls SetLanePos on its internal position with the target lane (ForceLaneId), MoveAlongS, then
//! SetHeadingRelativeRoadDirection → EvaluateHPR(H_REL): h = road heading + relative heading +
//! GetHOffset(), where GetHOffset is atan(GetTotalLaneWidthPrim(lane_id_) + laneOffsetPrim(s)) of the
//! internal (target) lane; the later XYZ2TrackPos re-attaches the car to the lane it is in but
//! keeps that heading. The engine took the drift of the lane the car was attached to. Found by
//! crates/difftest (s63063_00689).
//!
//! Fixture `lane_change_target_lane_drift.xosc` on lane_offset_slope.xodr (laneOffset 0.05·s; lane -2 widens by 0.01
//! per metre, so lane -1's centre drifts by 0.05 and lane -2's by 0.045): Car0 drives on lane -2
//! at 10 m/s from s 10; at 1.0 s a LaneChangeAction to lane -1 (linear, 2 s) starts. While the car
//! is still in lane -2 its heading is the lane-change angle plus lane -1's drift (0.218277), not
//! lane -2's (0.2133). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_heading_carries_the_target_lane_drift() {
    assert_fixture_matches_esmini(
        "lane_change_target_lane_drift.xosc",
        2.91,
        &[
            ("Car0", 1.01, 20.100000, -4.095500, 0.044970),
            ("Car0", 1.02, 20.198587, -4.073818, 0.218277),
            ("Car0", 1.3, 22.959017, -3.466727, 0.218277),
            ("Car0", 2.9, 38.732902, 0.002368, 0.218277),
        ],
    );
}
