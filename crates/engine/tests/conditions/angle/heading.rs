//! AngleCondition as esmini's TrigByAngle::CheckCondition: the entity's heading in the chosen
//! frame (world by default; road: from the reference line; lane: from the lane's driving
//! direction), wrapped to [−π, π], within the tolerance of the value. Closed form: Target
//! drives on lane 1 of the straight fixture road (along −x, heading π).

use crate::common::*;

fn fires(angle: f64, cs: &str) -> bool {
    let init = format!("{}{}", teleport("Ego", 100.0, -1), teleport("Target", 400.0, 1));
    let cond = format!(
        r#"<Condition name="a" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Target"/></TriggeringEntities><EntityCondition><AngleCondition angle="{angle}" angleTolerance="0.05" angleType="heading"{cs}/></EntityCondition></ByEntityCondition></Condition>"#
    );
    let go = event("Go", "parallel", &speed_action("step", "time", 0.0, 5.0), &trigger(&cond));
    let run = run(&xosc(&init, &story("Ego", &go), &stop_at(0.5)));
    event_time(&run, "GoAction", "start").is_some()
}

#[test]
fn heading_in_world_road_and_lane_frames() {
    use std::f64::consts::PI;
    // world: heading π (−π after wrapping)
    assert!(fires(PI, ""));
    assert!(fires(-PI, r#" coordinateSystem="world""#));
    assert!(!fires(0.0, ""));
    // road: π from the reference line
    assert!(fires(PI, r#" coordinateSystem="road""#));
    // lane: along its lane's driving direction, 0
    assert!(fires(0.0, r#" coordinateSystem="lane""#));
    assert!(!fires(0.5, r#" coordinateSystem="lane""#));
}
