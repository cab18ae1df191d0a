//! The ALKS_R157SM_Controller's RSS and FSM models (ControllerALKS_R157SM::RSS and ::FSM:
//! CheckSafety, CheckCritical, ReactCritical, MinDist), and what every model shares: esmini steps
//! the controller in frame 0 too (dt 0, no velocities measured yet, so the model cruises and
//! keeps that deceleration through its reaction time) and after the default controller has moved
//! the others (ScenarioEngine::step). Fixture `alks_r157_rss_fsm.xosc` (straight road, an RSS
//! follower 25 m behind a slower lead, an FSM follower 25 m behind another, far apart); expected
//! rows: esmini 3.6.0 on the same fixture (osc2cr drove both as the ReferenceDriver, 7.7 m and
//! 5.8 m off). Fixture `alks_r157_against_s.xosc`: an FSM car driving against the road's s with
//! a slower car in the lane to its right; the lateral gap and the lane step are measured in the
//! road's frame (Position::Delta: `tB - tA`, `laneB - laneA`), not the ego's, so the neighbour's
//! negative gap makes it a cut-in the model brakes for (esmini logs "Detected object: Beside
//! Scenario: CutIn"). Fixture `alks_r157_curve.xosc` (curve_r50.xodr): an FSM follower on the
//! arc, its gap measured corner by corner in road coordinates (Object::
//! FreeSpaceDistanceObjectRoadLane). Fixture `alks_r157_after_head_start.xosc`: the lead has a
//! FollowGhost head start of 2 s, during which esmini measures the ghost's motion only
//! (ScenarioEngine::prepareGroundTruth), so at the first step after it the RSS model sees both
//! cars moving and turns critical at once, holding its speed through the reaction time.

use crate::common::*;

#[test]
fn the_rss_and_fsm_models_brake_for_a_slower_lead_as_esmini() {
    let run = run_fixture("alks_r157_rss_fsm.xosc", "straight.xodr");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_poses(
        &run,
        &[
            ("RssEgo", 1.00, 75.942999, -1.75, 0.0),
            ("FsmEgo", 1.00, 422.980000, -1.75, 0.0),
            ("RssEgo", 2.50, 102.630135, -1.75, 0.0),
            ("FsmEgo", 2.50, 449.950000, -1.75, 0.0),
            ("RssEgo", 4.00, 122.465209, -1.75, 0.0),
            ("FsmEgo", 4.00, 469.183021, -1.75, 0.0),
            ("RssEgo", 6.50, 159.165535, -1.75, 0.0),
            ("FsmEgo", 6.50, 501.143443, -1.75, 0.0),
        ],
        0.01,
        1e-6,
    );
    // the FSM brakes at br_min (4 m/s²) after its 0.75 s reaction time, from 25 to the lead's 15 m/s
    assert!(close(at(&run, "FsmEgo", 2.5).speed, 15.0, 1e-6));
}

#[test]
fn an_alks_r157_driving_against_s_measures_the_lateral_gap_in_the_road_frame() {
    let run = run_fixture("alks_r157_against_s.xosc", "straight.xodr");
    assert_esmini_poses(
        &run,
        &[
            ("FsmEgo", 1.00, 882.054782, -1.75, std::f64::consts::PI),
            ("FsmEgo", 2.00, 868.759782, -1.75, std::f64::consts::PI),
            ("FsmEgo", 4.00, 843.634182, -1.75, std::f64::consts::PI),
        ],
        0.01,
        1e-5,
    );
}

#[test]
fn an_alks_r157_on_a_curve_measures_the_gap_corner_by_corner_on_the_road() {
    let run = run_fixture("alks_r157_curve.xosc", "curve_r50.xodr");
    assert_esmini_poses(
        &run,
        &[
            ("FsmEgo", 1.00, 52.978479, -1.664215, 0.057587),
            ("FsmEgo", 2.50, 78.305952, 6.677539, 0.578746),
            ("FsmEgo", 4.00, 91.893353, 19.618929, 0.943357),
            ("FsmEgo", 5.50, 99.793430, 35.904725, 1.294938),
        ],
        0.01,
        1e-4,
    );
}

#[test]
fn an_alks_r157_right_after_a_ghost_head_start_sees_the_others_moving() {
    let run = run_fixture("alks_r157_after_head_start.xosc", "straight.xodr");
    assert_esmini_poses(
        &run,
        &[("RssEgo", 0.50, 64.0, -1.75, 0.0), ("RssEgo", 1.00, 77.962999, -1.75, 0.0), ("RssEgo", 3.00, 117.681541, -1.75, 0.0)],
        0.02,
        1e-6,
    );
    // the reaction time (0.75 s) passes at the speed it had: nothing braked before it
    assert!(close(at(&run, "RssEgo", 0.5).speed, 28.0, 1e-9));
}
