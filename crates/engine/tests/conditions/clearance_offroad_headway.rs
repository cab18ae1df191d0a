//! RelativeClearanceCondition, storyboard element references qualified by their parents
//! ("Event::Action"), and OffroadCondition next to lanes of type `none`, on the straight fixture
//! road (along +x; lanes 1, −1, −2 of 3.5 m; lane −1 centre y = −1.75, lane −2 centre y = −5.25).

use crate::common::*;
use engine::{Run, Settings};

fn clearance(from: i32, to: i32) -> String {
    format!(
        r#"<Condition name="clear" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><RelativeClearanceCondition distanceForward="20" distanceBackward="10" freeSpace="false" oppositeLanes="false"><RelativeLaneRange from="{from}" to="{to}"/></RelativeClearanceCondition></EntityCondition></ByEntityCondition></Condition>"#
    )
}

fn lane_offset(value: f64) -> String {
    format!(
        r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics dynamicsShape="step" maxLateralAcc="1"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="{value}"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#
    )
}

#[test]
fn relative_clearance_waits_until_the_neighbour_lane_window_is_empty() {
    // Ego on lane −2 at s = 185, 10 m/s; Target stands on lane −1 (Ego's lane + 1) at s = 200,
    // 15 m ahead: inside [−10, 20]. It leaves the window when Ego passes s = 210, at t = 2.5 s.
    let init = format!("{}{}{}", teleport("Ego", 185.0, -2), init_speed("Ego", "step", "time", 0.0, 10.0), teleport("Target", 200.0, -1));
    let stories = story("Ego", &event("Pass", "overwrite", &lane_offset(0.0), &trigger(&clearance(1, 1))));
    let run = run(&xosc(&init, &stories, &stop_at(5.0)));
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let t = event_time(&run, "Pass", "start").expect("clearance became true");
    assert!((2.5..=2.53).contains(&t), "{t}");
}

#[test]
fn relative_clearance_needs_the_lane_to_exist() {
    // Lane −3 (Ego's lane − 1) does not exist: the area is empty but is no clearance.
    let init = format!("{}{}", teleport("Ego", 100.0, -2), teleport("Target", 500.0, -1));
    let stories = story("Ego", &event("Never", "overwrite", &lane_offset(0.0), &trigger(&clearance(-1, -1))));
    let run = run(&xosc(&init, &stories, &stop_at(1.0)));
    assert_eq!(event_time(&run, "Never", "start"), None);
}

#[test]
fn qualified_element_reference_picks_the_action_of_the_named_event() {
    // Two events each hold an action named "Act". The stop trigger waits for "Late::Act" to
    // end (a step lane offset ends at once when it starts at 2 s): the run stops at 2 s, not at
    // the end of "Early::Act" at 0 s.
    let ev = |name: &str, t: f64| {
        format!(
            r#"<Event name="{name}" priority="parallel"><Action name="Act">{}</Action>{}</Event>"#,
            lane_offset(0.5),
            trigger(&sim_time(t, "greaterOrEqual", "none", 0.0))
        )
    };
    let stories = story("Ego", &format!("{}{}", ev("Early", 0.0), ev("Late", 2.0)));
    let stop = r#"<ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition><StoryboardElementStateCondition storyboardElementType="action" storyboardElementRef="Late::Act" state="endTransition"/></ByValueCondition></Condition></ConditionGroup>"#;
    let run = run(&xosc(&teleport("Ego", 10.0, -1), &stories, stop));
    let end = event_time(&run, "storyBoard", "stop").expect("stopped");
    assert!((2.0..=2.05).contains(&end), "{end}");
}

fn run_on_verge(text: &str) -> Run {
    run_on(text, "straight_verge.xodr", &Settings { step: 0.01, max_time: 5.0 })
}

fn offroad_event(duration: f64) -> String {
    let cond = format!(
        r#"<Condition name="off" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><OffroadCondition duration="{duration}"/></EntityCondition></ByEntityCondition></Condition>"#
    );
    story("Ego", &event("Off", "overwrite", &lane_offset(0.0), &trigger(&cond)))
}

#[test]
fn a_lane_of_type_none_is_off_the_road() {
    // straight_verge.xodr adds lane −3 of type none (6 m) outside lane −2: road edge at t = −7.
    // Ego stands 3 m right of lane −2's centre (t = −8.25, inside the verge): off road from the
    // start, so a 0.5 s OffroadCondition holds at 0.5 s.
    let init = r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-2" offset="-3" s="10"/></Position></TeleportAction></PrivateAction></Private>"#;
    let run = run_on_verge(&xosc(init, &offroad_event(0.5), &stop_at(2.0)));
    let t = event_time(&run, "Off", "start").expect("went off road");
    assert!((0.5..=0.52).contains(&t), "{t}");
}

#[test]
fn inside_the_outermost_real_lane_is_on_the_road() {
    // 1.5 m right of lane −2's centre: t = −6.75, inside lane −2 (edge −7): never off road.
    let init = r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-2" offset="-1.5" s="10"/></Position></TeleportAction></PrivateAction></Private>"#;
    let run = run_on_verge(&xosc(init, &offroad_event(0.5), &stop_at(2.0)));
    assert_eq!(event_time(&run, "Off", "start"), None);
}

fn headway_run(target_s: f64) -> Run {
    let init = format!("{}{}", placed("Ego", 100.0, -1, 10.0), placed("Target", target_s, -2, 10.0));
    let cond = |rule: &str, value: f64| {
        format!(
            r#"<Condition name="hw" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><TimeHeadwayCondition entityRef="Target" value="{value}" freespace="false" alongRoute="false" rule="{rule}"/></EntityCondition></ByEntityCondition></Condition>"#
        )
    };
    let events = format!(
        "{}{}",
        event("Above", "parallel", &lane_offset(0.0), &trigger(&cond("greaterThan", 0.3))),
        event("Below", "parallel", &lane_offset(0.0), &trigger(&cond("lessThan", 0.4)))
    );
    run(&xosc(&init, &story("Ego", &events), &stop_at(1.0)))
}

#[test]
fn time_headway_measures_euclidean_distance_by_default() {
    // Without relativeDistanceType/coordinateSystem esmini measures the euclidean distance,
    // signed by the longitudinal part in the entity's frame. Target drives 1 m ahead in the lane
    // to the right (3.5 m), both at 10 m/s: headway √(1 + 3.5²) / 10 = 0.364 s (a longitudinal
    // distance would give 0.1 s).
    let run = headway_run(101.0);
    assert!(event_time(&run, "Above", "start").is_some_and(|t| t <= 0.02), "{:?}", run.trace.events);
    assert!(event_time(&run, "Below", "start").is_some_and(|t| t <= 0.02));
}

#[test]
fn time_headway_to_an_entity_exactly_beside_is_undefined() {
    // 0 m ahead counts as behind (the sign of a zero longitudinal part is negative): no headway.
    let run = headway_run(100.0);
    assert_eq!(event_time(&run, "Above", "start"), None);
    assert_eq!(event_time(&run, "Below", "start"), None);
}
