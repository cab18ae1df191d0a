//! AngleCondition on the heading in the trajectory frame, as esmini 3.6.0's
//! TrigByAngle::CheckCondition has it: the entity's heading minus the direction of the
//! segment of the followed trajectory it is on (RMTrajectory::GetHTrue), so it measures how
//! far a polyline's corner blending has turned the entity off (or not yet onto) its segment.
//! Checked by running esmini on this scenario: event times and the final pose are its own.
//!
//! Straight fixture road; Ego at 5 m/s follows (10, −1.75) → (30, −1.75) → (50, 8.25) from
//! t = 0.5 (position mode: the heading turns over ±2 m around the corner at x = 30).
//! `Slow` (3 m/s) waits for +0.1 ± 0.05 rad — reached before the corner, still on the first
//! segment; `Stop` waits for −0.1 ± 0.05 — reached past the corner, the heading still short of
//! the second segment's.

use crate::common::*;

fn world(x: f64, y: f64) -> String {
    format!(r#"<Position><WorldPosition x="{x}" y="{y}" z="0"/></Position>"#)
}

fn angle_trigger(angle: f64) -> String {
    format!(
        r#"<StartTrigger><ConditionGroup><Condition name="a" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><AngleCondition angle="{angle}" angleTolerance="0.05" angleType="heading" coordinateSystem="trajectory"/></EntityCondition></ByEntityCondition></Condition></ConditionGroup></StartTrigger>"#
    )
}

#[test]
fn the_heading_is_measured_from_the_current_segment_of_the_trajectory() {
    let shape =
        format!("<Polyline><Vertex>{}</Vertex><Vertex>{}</Vertex><Vertex>{}</Vertex></Polyline>", world(10.0, -1.75), world(30.0, -1.75), world(50.0, 8.25));
    let follow = format!(
        r#"<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="T" closed="false"><ParameterDeclarations/><Shape>{shape}</Shape></Trajectory></TrajectoryRef><TimeReference><None/></TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#
    );
    let init = format!(r#"{}{}"#, teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 5.0));
    let events = [
        event("Follow", "parallel", &follow, &trigger(&sim_time(0.5, "greaterOrEqual", "none", 0.0))),
        event("Slow", "parallel", &speed_action("step", "time", 0.0, 3.0), &angle_trigger(0.1)),
        event("Stop", "parallel", &speed_action("step", "time", 0.0, 0.0), &angle_trigger(-0.1)),
    ]
    .concat();
    let stop = stop_at(10.0);
    let run = run(&xosc(&init, &story("Ego", &events), &stop));
    assert!(!run.warnings.iter().any(|w| w.message.contains("AngleCondition")), "{:?}", run.warnings);
    // s = 5 (t − 0.5): the blend starts at s = 18 (t = 4.1); 0.05 rad of the 0.4636 rad turn
    // is reached 0.43 m later, in the step to t = 4.19.
    assert!(event_time(&run, "Slow", "start").is_some_and(|t| close(t, 4.19, 1e-9)), "{:?}", run.trace.events);
    assert!(event_time(&run, "Stop", "start").is_some_and(|t| close(t, 4.95, 1e-9)), "{:?}", run.trace.events);
    // Where esmini stops it (its trace, 4 decimals).
    let e = at(&run, "Ego", 9.0);
    assert!(close(e.x, 30.6529, 1e-4) && close(e.y, -1.4235, 1e-4) && close(e.speed, 0.0, 1e-12), "{e:?}");
}
