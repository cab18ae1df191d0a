//! Each condition, edge and delay on purpose-built scenarios; trigger times computed by hand.
//! Ego starts at x = 10 on lane -1 driving 10 m/s, so x(t) = 10 + 10 t; the storyboard at time
//! t sees the state recorded at t.

use crate::common::*;

/// Time at which event "E" starts when triggered by `condition` (XML of one Condition).
fn fire_time(condition: &str, target_s: f64) -> Option<f64> {
    let init = format!("{}{}{}", teleport("Ego", 10.0, -1), teleport("Target", target_s, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let ev = event("E", "overwrite", &speed_action("step", "time", 0.0, 10.0), &trigger(condition));
    let run = run(&xosc(&init, &story("Ego", &ev), &stop_at(15.0)));
    event_time(&run, "E", "start")
}

fn by_entity(inner: &str, edge: &str) -> String {
    format!(
        r#"<Condition name="c" delay="0" conditionEdge="{edge}"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition>{inner}</EntityCondition></ByEntityCondition></Condition>"#
    )
}

fn assert_time(got: Option<f64>, want: f64) {
    let g = got.unwrap_or(-1.0);
    assert!(close(g, want, 1e-6), "fired at {g}, expected {want}");
}

#[test]
fn simulation_time_edges_and_delay() {
    assert_time(fire_time(&sim_time(1.0, "greaterThan", "none", 0.0), 500.0), 1.01);
    assert_time(fire_time(&sim_time(1.0, "greaterOrEqual", "none", 0.0), 500.0), 1.0);
    // Rising: false at 1.00, true at 1.01.
    assert_time(fire_time(&sim_time(1.0, "greaterThan", "rising", 0.0), 500.0), 1.01);
    // Falling: t < 1 holds until 0.99 and fails at 1.00.
    assert_time(fire_time(&sim_time(1.0, "lessThan", "falling", 0.0), 500.0), 1.0);
    // Delay 2 s after the condition holds at 1.01.
    assert_time(fire_time(&sim_time(1.0, "greaterThan", "none", 2.0), 500.0), 3.01);
}

#[test]
fn storyboard_element_state_follows_transitions() {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let after_first = r#"<Condition name="s" delay="0" conditionEdge="none"><ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="First" state="endTransition"/></ByValueCondition></Condition>"#;
    let events = format!(
        "{}{}",
        event("First", "parallel", &speed_action("linear", "time", 1.0, 20.0), &trigger(&sim_time(2.0, "greaterThan", "none", 0.0))),
        event("Second", "parallel", &speed_action("step", "time", 0.0, 5.0), &trigger(after_first))
    );
    let run = run(&xosc(&init, &story("Ego", &events), &stop_at(6.0)));
    // First: starts 2.01, ends after 1 s of steps at 3.00; Second starts in the next evaluation.
    let first_end = event_time(&run, "First", "end").unwrap_or(-1.0);
    assert!(close(first_end, 3.0, 1e-6), "{first_end}");
    let second = event_time(&run, "Second", "start").unwrap_or(-1.0);
    assert!(close(second, 3.01, 1e-6), "{second}");
}

#[test]
fn reach_position_and_traveled_distance() {
    // |x - 50| < 1.05 first at x = 49.0 (t = 3.90; 48.9 at 3.89 is outside).
    let reach =
        by_entity(r#"<ReachPositionCondition tolerance="1.05"><Position><WorldPosition x="50" y="-1.75"/></Position></ReachPositionCondition>"#, "none");
    assert_time(fire_time(&reach, 500.0), 3.90);
    // 30 m travelled at t = 3.00 (the odometer sums 0.1 m steps: allow one step of rounding).
    let trav = by_entity(r#"<TraveledDistanceCondition value="30"/>"#, "none");
    let t = fire_time(&trav, 500.0).unwrap_or(-1.0);
    assert!((3.0 - 1e-9..=3.01 + 1e-9).contains(&t), "{t}");
}

#[test]
fn speed_and_standstill() {
    // Ego drives 10 m/s from the first step: speed > 5 already at 0.00 after Init.
    assert_time(fire_time(&by_entity(r#"<SpeedCondition value="5" rule="greaterThan"/>"#, "none"), 500.0), 0.0);
    // Target stands still from t = 0, noted at 0.01 s (a stamp of 0 reads as "not standing"):
    // StandStill 2 s holds once strictly longer, at 2.01 as in esmini 3.6.0 (standstill_clock.rs).
    let cond = r#"<Condition name="c" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Target"/></TriggeringEntities><EntityCondition><StandStillCondition duration="2"/></EntityCondition></ByEntityCondition></Condition>"#;
    assert_time(fire_time(cond, 500.0), 2.01);
}

#[test]
fn relative_distance_headway_ttc_collision() {
    // Target stands at x = 110 on the same lane. Reference points: 100 - 10 t apart.
    let rd = by_entity(
        r#"<RelativeDistanceCondition entityRef="Target" relativeDistanceType="longitudinal" value="20" freespace="false" rule="lessThan"/>"#,
        "none",
    );
    assert_time(fire_time(&rd, 110.0), 8.01);
    // Headway = distance / own speed < 5 s: 100 - 10 t < 50, t > 5.
    let hw = by_entity(
        r#"<TimeHeadwayCondition entityRef="Target" value="5" freespace="false" rule="lessThan" coordinateSystem="entity" relativeDistanceType="longitudinal"/>"#,
        "none",
    );
    assert_time(fire_time(&hw, 110.0), 5.01);
    // TTC with freespace: gap = 100 - 4.5 - 10 t (box lengths 4.5, same offsets), < 2 s at 10 m/s: t > 7.55.
    let ttc = by_entity(
        r#"<TimeToCollisionCondition value="2" freespace="true" rule="lessThan" coordinateSystem="entity" relativeDistanceType="longitudinal"><TimeToCollisionConditionTarget><EntityRef entityRef="Target"/></TimeToCollisionConditionTarget></TimeToCollisionCondition>"#,
        "none",
    );
    assert_time(fire_time(&ttc, 110.0), 7.56);
    // Boxes touch when 100 - 10 t <= 4.5: t = 9.55.
    let col = by_entity(r#"<CollisionCondition><EntityRef entityRef="Target"/></CollisionCondition>"#, "none");
    let t = fire_time(&col, 110.0).unwrap_or(-1.0);
    assert!((9.55 - 1e-9..=9.56 + 1e-9).contains(&t), "{t}");
    // Road coordinates give the same longitudinal distance on a straight road.
    let road = by_entity(
        r#"<RelativeDistanceCondition entityRef="Target" relativeDistanceType="longitudinal" coordinateSystem="road" value="20" freespace="false" rule="lessThan"/>"#,
        "none",
    );
    assert_time(fire_time(&road, 110.0), 8.01);
}

#[test]
fn distance_to_a_position() {
    // Euclidean distance from (10 + 10 t, -1.75) to (100, -1.75) below 30: t > 6.
    let d = by_entity(
        r#"<DistanceCondition value="30" freespace="false" rule="lessThan"><Position><WorldPosition x="100" y="-1.75"/></Position></DistanceCondition>"#,
        "none",
    );
    assert_time(fire_time(&d, 500.0), 6.01);
}

#[test]
fn end_of_road_and_offroad() {
    // Road ends at x = 1000; Ego reaches it at t = 99: use a start close to the end.
    let init = format!("{}{}", teleport("Ego", 980.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let cond = by_entity(r#"<EndOfRoadCondition duration="1"/>"#, "none");
    let ev = event("E", "overwrite", &speed_action("step", "time", 0.0, 1.0), &trigger(&cond));
    let run = run(&xosc(&init, &story("Ego", &ev), &stop_at(8.0)));
    // At the end at 2.00 (clamped there), + 1 s.
    assert_time(event_time(&run, "E", "start"), 3.0);
    assert!(close(at(&run, "Ego", 5.0).x, 1000.0, 1e-6));
}

#[test]
fn all_rule_needs_every_entity() {
    let init = format!("{}{}{}", teleport("Ego", 10.0, -1), teleport("Target", 10.0, -2), init_speed("Ego", "step", "time", 0.0, 10.0));
    let cond = r#"<Condition name="c" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="all"><EntityRef entityRef="Ego"/><EntityRef entityRef="Target"/></TriggeringEntities><EntityCondition><SpeedCondition value="5" rule="greaterThan"/></EntityCondition></ByEntityCondition></Condition>"#;
    let events = event("E", "overwrite", &speed_action("step", "time", 0.0, 10.0), &trigger(cond));
    // Target never moves: the event never starts; with "any" it would start at once.
    let run = run(&xosc(&init, &story("Ego", &events), &stop_at(3.0)));
    assert!(event_time(&run, "E", "start").is_none());
}

#[test]
fn execution_count_and_priorities() {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let repeated = r#"<Event name="R" priority="parallel" maximumExecutionCount="3"><Action name="RA"><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Action>"#.to_string()
        + &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))
        + "</Event>";
    let run1 = run(&xosc(&init, &story("Ego", &repeated), &stop_at(3.0)));
    let starts = run1.trace.events.iter().filter(|e| e.element == "R" && e.transition == "start").count();
    assert_eq!(starts, 3);
    // Override: a second event ends the running first one in the same maneuver.
    let events = format!(
        "{}{}",
        event("Slow", "overwrite", &speed_action("linear", "time", 10.0, 0.0), &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))),
        event("Fast", "overwrite", &speed_action("step", "time", 0.0, 20.0), &trigger(&sim_time(2.0, "greaterThan", "none", 0.0)))
    );
    let run2 = run(&xosc(&init, &story("Ego", &events), &stop_at(4.0)));
    assert_time(event_time(&run2, "Slow", "end"), 2.01);
    assert!(close(at(&run2, "Ego", 3.0).speed, 20.0, 1e-9));
    // Skip: a skip event does not start while another runs.
    let events = format!(
        "{}{}",
        event("Slow", "overwrite", &speed_action("linear", "time", 10.0, 0.0), &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))),
        event("Skipper", "skip", &speed_action("step", "time", 0.0, 20.0), &trigger(&sim_time(2.0, "greaterThan", "none", 0.0)))
    );
    let run3 = run(&xosc(&init, &story("Ego", &events), &stop_at(4.0)));
    assert!(event_time(&run3, "Skipper", "start").is_none());
}
