//! AngleCondition on pitch and roll, as esmini 3.6.0 evaluates them (TrigByAngle) — event
//! times checked by running esmini on these scenarios. On a road an entity rolls with the
//! superelevation and pitches with the elevation, both turned around when it faces against
//! s; following a polyline whose vertices give heights, it pitches with the path (corners
//! blended over ±2 m as the heading).

use crate::common::*;

fn angle_trigger(entity: &str, angle: f64, tolerance: f64, kind: &str, frame: &str) -> String {
    format!(
        r#"<StartTrigger><ConditionGroup><Condition name="a" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="{entity}"/></TriggeringEntities><EntityCondition><AngleCondition angle="{angle}" angleTolerance="{tolerance}" angleType="{kind}" coordinateSystem="{frame}"/></EntityCondition></ByEntityCondition></Condition></ConditionGroup></StartTrigger>"#
    )
}

fn with_speed(entity: &str, s: f64, lane: i32, speed: f64) -> String {
    teleport(entity, s, lane).replace("</Private>", &format!("{}</Private>", speed_action("step", "time", 0.0, speed)))
}

#[test]
fn roll_follows_the_superelevation_and_turns_with_the_facing() {
    // fixtures/banked.xodr: superelevation 0.01·s rad. Ego on lane −1 (facing +s) from s = 10
    // at 10 m/s; Target on lane 1 (facing −s) from s = 60 at 7 m/s, its roll −0.01·s.
    let init = format!("{}{}", with_speed("Ego", 10.0, -1, 10.0), with_speed("Target", 60.0, 1, 7.0));
    let events = [
        // relative to the road the roll is 0 at once
        event("EgoRollRoad", "parallel", &speed_action("step", "time", 0.0, 10.0), &angle_trigger("Ego", 0.0, 0.001, "roll", "road")),
        // −0.425 ± 0.05: the Target's roll reaches −0.475 at s = 47.5, t ≈ 1.786
        event("TargetRoll", "parallel", &speed_action("step", "time", 0.0, 5.0), &angle_trigger("Target", -0.425, 0.05, "roll", "world")),
        // 0.35 ± 0.02: Ego reaches s = 33 (roll 0.33) 1.02 s after slowing to 5 m/s at s = 27.9
        event("EgoRoll", "parallel", &speed_action("step", "time", 0.0, 1.0), &angle_trigger("Ego", 0.35, 0.02, "roll", "world")),
    ]
    .concat();
    let text = xosc(&init, &story("Ego", &events), &stop_at(5.0)).replace("straight.xodr", "banked.xodr");
    let run = run_on(&text, "banked.xodr", &engine::Settings { step: 0.01, max_time: 10.0 });
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for (name, t) in [("EgoRollRoad", 0.0), ("TargetRoll", 1.79), ("EgoRoll", 2.81)] {
        assert!(event_time(&run, name, "start").is_some_and(|s| close(s, t, 1e-9)), "{name}: {:?}", run.trace.events);
    }
    // esmini's Ego at 4.5 s (its trace, 4 decimals)
    assert!(close(at(&run, "Ego", 4.5).x, 34.69, 1e-4), "{:?}", at(&run, "Ego", 4.5));
}

#[test]
fn an_elevated_trajectory_pitches_the_entity_off_the_road() {
    // Straight flat road; Ego at 5 m/s follows (10, −1.75, 0) → (20, −1.75, 1) → (30, −1.75, 5):
    // pitch −atan(0.1) on the first segment, −atan(0.4) on the second, blended over ±2 m
    // around s = 10. In the world frame −0.1 ± 0.01 holds from the start (slowing it to
    // 4 m/s); in the lane frame (the road is flat) −0.3 ± 0.05 first holds 0.14 m past the
    // corner, reached in the step to t = 2.54 (s = 10.16).
    let w = |x: f64, z: f64| format!(r#"<Position><WorldPosition x="{x}" y="-1.75" z="{z}"/></Position>"#);
    let shape = format!("<Polyline><Vertex>{}</Vertex><Vertex>{}</Vertex><Vertex>{}</Vertex></Polyline>", w(10.0, 0.0), w(20.0, 1.0), w(30.0, 5.0));
    let follow = format!(
        r#"<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="T" closed="false"><ParameterDeclarations/><Shape>{shape}</Shape></Trajectory></TrajectoryRef><TimeReference><None/></TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#
    );
    let init = with_speed("Ego", 10.0, -1, 5.0).replace("</Private>", &format!("{follow}</Private>"));
    let events = [
        event("Pitch", "parallel", &speed_action("step", "time", 0.0, 0.0), &angle_trigger("Ego", -0.3, 0.05, "pitch", "lane")),
        event("PitchWorld", "parallel", &speed_action("step", "time", 0.0, 4.0), &angle_trigger("Ego", -0.1, 0.01, "pitch", "world")),
    ]
    .concat();
    let run = run(&xosc(&init, &story("Ego", &events), &stop_at(6.0)));
    assert!(event_time(&run, "PitchWorld", "start").is_some_and(|s| close(s, 0.0, 1e-9)), "{:?}", run.trace.events);
    assert!(event_time(&run, "Pitch", "start").is_some_and(|s| close(s, 2.54, 1e-9)), "{:?}", run.trace.events);
}
