//! Two rules from esmini's source, each checked against an esmini 3.6.0 run of the scenario
//! built here (`write_for_esmini` writes them; the asserted numbers are esmini's):
//! - a TeleportAction holds the lateral and the longitudinal domain (DOMAIN_MASK_LAT_AND_LONG),
//!   so starting one ends a running lane change of the entity (Event::Start ends conflicting
//!   actions) — the entity stays where it was put instead of being pulled back;
//! - a RelativeRoadPosition without an orientation faces along the road's +s, whichever side of
//!   the road it lands on (Position::SetRelativePosition: SetHeadingRelative(dh = 0)).

use crate::common::*;

/// Ego at 10 m/s on lane -1 from s = 50: a 4 s lane change to lane -2 from 1 s, a teleport to
/// lane -1 at s = 300 at 2 s.
fn teleport_during_lane_change() -> String {
    let change = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="linear" value="4" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let hop = format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(300.0, -1));
    let events = format!(
        "{}{}",
        event("Change", "parallel", change, &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0))),
        event("Hop", "parallel", &hop, &trigger(&sim_time(2.0, "greaterOrEqual", "none", 0.0)))
    );
    xosc(&format!("{}{}", placed_in_one_private("Ego", 50.0, -1, 10.0), teleport("Target", 600.0, -2)), &story("Ego", &events), &stop_at(4.0))
}

/// Ego at 10 m/s on lane -1 at s = 100; Target 20 m ahead on the other side of the road (lane 1,
/// whose traffic drives against s), placed by a RelativeRoadPosition, at 5 m/s.
fn relative_road_across() -> String {
    let target = format!(
        r#"<Private entityRef="Target"><PrivateAction><TeleportAction><Position><RelativeRoadPosition entityRef="Ego" ds="20" dt="3.5"/></Position></TeleportAction></PrivateAction>{}</Private>"#,
        speed_action("step", "time", 0.0, 5.0)
    );
    xosc(&format!("{}{}", placed_in_one_private("Ego", 100.0, -1, 10.0), target), "", &stop_at(2.0))
}

#[test]
fn a_teleport_ends_a_running_lane_change() {
    let run = run(&teleport_during_lane_change());
    let s = at(&run, "Ego", 3.0);
    // esmini: x = 309.9, y = -1.75 at 3 s: put on lane -1 at s = 300 at 2.01 s (the step after
    // the trigger), then 0.99 s of driving at 10 m/s; without the rule the lane change pulls it back
    assert!((s.x - 309.9).abs() < 1e-3 && (s.y + 1.75).abs() < 1e-3, "{s:?}");
}

#[test]
fn a_relative_road_position_faces_along_the_road() {
    let run = run(&relative_road_across());
    let t0 = at(&run, "Target", 0.0);
    let t2 = at(&run, "Target", 2.0);
    // esmini: heading 0, x from 120 to 130 (5 m/s along +s), y = 1.75
    assert!(t0.h.abs() < 1e-9 && (t0.x - 120.0).abs() < 1e-3 && (t0.y - 1.75).abs() < 1e-3, "{t0:?}");
    assert!((t2.x - 130.0).abs() < 1e-3, "{t2:?}");
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("teleport_during_lane_change.xosc"), teleport_during_lane_change()).expect("write");
    std::fs::write(fixtures().join("relative_road_across.xosc"), relative_road_across()).expect("write");
}
