//! LaneOffsetAction with a RelativeTargetLaneOffset, as esmini's LatLaneOffsetAction::Start
//! has it: the target is the reference entity's t moved by the value (leftwards, +t, for a
//! reference driving along s), and Ego's lane offset becomes that t minus its lane centre's t.
//! On the straight fixture road lane −1's centre is y = −1.75 and lane −2's is y = −5.25.

use crate::common::*;

fn relative_offset(entity: &str, value: f64) -> String {
    format!(
        r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><RelativeTargetLaneOffset entityRef="{entity}" value="{value}"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#
    )
}

fn final_y(reference: &str, value: f64) -> f64 {
    let init = format!("{}{}", placed("Ego", 10.0, -1, 10.0), placed("Target", 10.0, -2, 10.0));
    let stories = story("Ego", &event("LO", "overwrite", &relative_offset(reference, value), &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(6.0);
    let run = run(&xosc(&init, &stories, &stop));
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    at(&run, "Ego", 6.0).y
}

#[test]
fn a_negative_value_relative_to_itself_moves_an_entity_on_a_right_lane_to_the_right() {
    // t −1.75 − 1 = −2.75: one metre to the right of its own lane centre (esmini's
    // driver_lane_bouncing_scenario drifts right with value −3 on lane −1).
    assert!(close(final_y("Ego", -1.0), -2.75, 1e-9));
}

#[test]
fn the_target_is_measured_from_the_reference_entity() {
    // Target on lane −2: t −5.25 + 1 = −4.25, i.e. Ego 2.5 m right of its lane centre.
    assert!(close(final_y("Target", 1.0), -4.25, 1e-9));
}
