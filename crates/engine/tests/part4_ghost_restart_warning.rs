//! esmini restarts a FollowGhost ghost when an event handed to the ghost starts on a trigger
//! other than simulation time or a ghost-watched condition of the entity itself (its
//! `ReplaceObjectInTrigger` adds an `AddedGhostTeleport`; seen in esmini's
//! driver_lane_bouncing_scenario trace, where time rewinds 2.5 s at 10.25 s). osc2cr does not
//! model the restart and must say so, naming the condition.

mod common;
use common::*;

fn stop(t: f64) -> String {
    format!("<ConditionGroup>{}</ConditionGroup>", sim_time(t, "greaterThan", "none", 0.0))
}

fn ghost_scenario(trigger_condition: &str) -> String {
    let activate = r#"<Private entityRef="Ego"><PrivateAction><ActivateControllerAction longitudinal="true" lateral="true"/></PrivateAction></Private>"#;
    let init = format!("{}{}{}{activate}", teleport("Ego", 50.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0), teleport("Target", 300.0, -1));
    let offset = r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="0.5"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Drift", "overwrite", offset, &trigger(trigger_condition)));
    let text = xosc(&init, &stories, &stop(5.0));
    let c = r#"<ObjectController><Controller name="driver"><Properties><Property name="esminiController" value="FollowGhostController"/><Property name="headstartTime" value="2"/></Properties></Controller></ObjectController></ScenarioObject>"#;
    text.replacen("</ScenarioObject>", c, 1)
}

fn restart_warnings(run: &engine::Run) -> Vec<String> {
    run.warnings.iter().map(|w| w.to_string()).filter(|w| w.contains("started after time 0, where esmini restarts the ghost")).collect()
}

#[test]
fn a_distance_trigger_on_a_ghost_event_is_a_positioned_warning() {
    // Ego (s = 50, 10 m/s, standing still during the 2 s head start) comes within 240 m of
    // s = 300 at 1 s: after time 0, where esmini restarts the ghost.
    let run = run(&ghost_scenario(&near(240.0)));
    let w = restart_warnings(&run);
    assert_eq!(w.len(), 1, "{:?}", run.warnings);
    assert!(w[0].contains("condition `near`") && w[0].contains("event `Drift`"), "{}", w[0]);
    // Positioned at the condition in the scenario text (line:col after the file name).
    assert!(w[0].contains("test.xosc:"), "{}", w[0]);
}

fn near(metres: f64) -> String {
    format!(
        r#"<Condition name="near" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><DistanceCondition value="{metres}" freespace="false" rule="lessThan" relativeDistanceType="longitudinal" coordinateSystem="road"><Position><LanePosition roadId="1" laneId="-1" s="300" offset="0"/></Position></DistanceCondition></EntityCondition></ByEntityCondition></Condition>"#
    )
}

#[test]
fn an_event_that_starts_during_the_head_start_restarts_nothing() {
    // Within 1000 m from the first step (t = −2 s): esmini's teleport does not restart the
    // ghost before time 0.
    let run = run(&ghost_scenario(&near(1000.0)));
    assert!(event_time(&run, "DriftAction", "start").is_some_and(|t| t < 0.0));
    assert!(restart_warnings(&run).is_empty(), "{:?}", run.warnings);
}

#[test]
fn a_simulation_time_trigger_moves_earlier_without_a_restart() {
    let run = run(&ghost_scenario(&sim_time(1.0, "greaterThan", "none", 0.0)));
    assert!(restart_warnings(&run).is_empty(), "{:?}", run.warnings);
}
