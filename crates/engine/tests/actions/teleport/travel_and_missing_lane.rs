//! Two rules found by the differential tester (crates/difftest), each checked against an esmini
//! 3.6.0 run of the scenario built here (the numbers in the asserts are esmini's):
//! - a teleport is no travel: esmini's odometer skips a step whose object has the TELEPORT dirty
//!   bit (ScenarioEngine step), so a TraveledDistanceCondition counts only driving;
//! - a RelativeLanePosition whose lane does not exist keeps the lane and offset the reference was
//!   moved to (Position::SetRelativePosition: SetLanePos fails after CopyLocation).

use crate::common::*;

fn relative_lane(entity: &str, reference: &str, d_lane: i32, ds: f64) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><RelativeLanePosition entityRef="{reference}" dLane="{d_lane}" ds="{ds}" offset="0"/></Position></TeleportAction></PrivateAction></Private>"#
    )
}

/// Ego on lane -2 (the outermost right lane) at s = 100; Target two lanes further right of it,
/// 20 m ahead: there is no such lane.
pub(super) fn missing_lane_scenario() -> String {
    xosc(&format!("{}{}", teleport("Ego", 100.0, -2), relative_lane("Target", "Ego", -1, 20.0)), "", &stop_at(0.5))
}

#[test]
fn a_relative_lane_that_does_not_exist_keeps_the_reference_lane() {
    let run = run(&missing_lane_scenario());
    let t = at(&run, "Target", 0.0);
    // esmini: Target at x = 120, y = -5.25 (lane -2's centre), lane -2
    assert!((t.x - 120.0).abs() < 1e-9 && (t.y + 5.25).abs() < 1e-9, "{t:?}");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
}

/// Ego at 10 m/s on lane -1 from s = 0; at 1 s it is teleported 500 m ahead; an event waits for
/// 15 m of travel. Driving gives 10 m by 1 s, the teleport none, so the event fires after 1.5 s.
pub(super) fn teleport_travel_scenario() -> String {
    let hop = event(
        "Hop",
        "parallel",
        &format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(510.0, -1)),
        &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)),
    );
    let far = r#"<Condition name="d" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><TraveledDistanceCondition value="15"/></EntityCondition></ByEntityCondition></Condition>"#;
    let stop_car = event("Far", "parallel", &speed_action("step", "time", 0.0, 0.0), &trigger(far));
    xosc(
        // one Private per entity: esmini refuses a second one for the same entity
        &format!("{}{}", placed_in_one_private("Ego", 0.0, -1, 10.0), teleport("Target", 300.0, -2)),
        &story("Ego", &format!("{hop}{stop_car}")),
        &stop_at(3.0),
    )
}

#[test]
fn a_teleport_is_no_travel() {
    let run = run(&teleport_travel_scenario());
    let fired = run.trace.events.iter().find(|e| e.element == "FarAction" && e.transition == "start").expect("Far starts");
    // esmini: FarAction starts at 1.51 s (15 m of driving at 10 m/s, seen the step after it is
    // reached); the 500 m jump is not counted
    assert!((fired.time - 1.51).abs() < 1e-6, "{}", fired.time);
}

/// Writes both scenarios beside the fixture road, to run esmini on them by hand:
/// `cargo test -p osc2cr-engine --test tests -- --ignored teleport::travel_and_missing_lane::write_for_esmini`.
#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("missing_lane.xosc"), missing_lane_scenario()).expect("write");
    std::fs::write(fixtures().join("teleport_travel.xosc"), teleport_travel_scenario()).expect("write");
}
