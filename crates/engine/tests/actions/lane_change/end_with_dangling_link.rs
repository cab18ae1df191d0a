//! A lane change that reaches the end of a road goes on there when that end has a link element,
//! even one to a road the map lacks: without a route, LatLaneChangeAction::Step re-attaches the
//! position (XYZ2TrackPos) before it tests POS_STATUS_END_OF_ROAD, and the re-attachment's
//! Position::SetLongitudinalTrackPos sets that status only at an end without a link. Where the
//! end has no link the change ends there (`too_fast_and_road_end.rs`). Checked against esmini
//! 3.6.0 runs of the scenario built here on `fixtures/dangling_successor.xodr` (the straight
//! fixture road with a successor link to a missing road 2) and on `straight.xodr`
//! (`write_for_esmini`; the asserted numbers are esmini's).

use crate::common::*;
use engine::Settings;

/// Ego at 10 m/s on lane -1 from s = 990 of the 1,000 m road; at 0.5 s a 2 s linear lane
/// change to lane -2 (the road's end is reached at 1 s).
fn change_into_road_end() -> String {
    let change = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="linear" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let events = event("Change", "parallel", change, &trigger(&sim_time(0.5, "greaterOrEqual", "none", 0.0)));
    xosc(&format!("{}{}", placed_in_one_private("Ego", 990.0, -1, 10.0), teleport("Target", 100.0, -2)), &story("Ego", &events), &stop_at(3.0))
}

#[test]
fn a_lane_change_goes_on_at_a_road_end_with_a_link() {
    let run = run_on(&change_into_road_end(), "dangling_successor.xodr", &Settings { step: 0.01, max_time: 3.0 });
    // esmini: at the road's end (x = 1000) from 1.5 s, still at 10 m/s, sideways to y = -4.375 at
    // 2 s and -5.25 at 2.5 s (the change ends at 2.49 s); stopped from 2.6 s
    for (t, y, v) in [(1.5, -3.5, 10.0), (2.0, -4.375, 10.0), (2.5, -5.25, 10.0), (3.0, -5.25, 0.0)] {
        let s = at(&run, "Ego", t);
        assert!((s.x - 1000.0).abs() < 1e-6 && (s.y - y).abs() < 1e-3 && (s.speed - v).abs() < 1e-9, "{t}: {s:?}");
    }
}

#[test]
fn a_lane_change_ends_at_a_road_end_without_a_link() {
    let run = run(&change_into_road_end());
    // esmini: the change ends at 1.0 s at the road's end; y = -2.6425 and speed 0 from 1.5 s
    for t in [1.5, 2.5] {
        let s = at(&run, "Ego", t);
        assert!((s.x - 1000.0).abs() < 1e-6 && (s.y + 2.6425).abs() < 1e-3 && s.speed.abs() < 1e-9, "{t}: {s:?}");
    }
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("change_into_road_end.xosc"), change_into_road_end()).expect("write");
}
