//! Speed and relative speed conditions with a `direction` measure velocities in an entity's own
//! frame (esmini's TrigBySpeed / TrigByRelativeSpeed::CheckCondition: the triggering entity's
//! velocity turned into the reference entity's axes, less the reference's own). The corpus
//! scenario direction_dimension_trig is exact with it; here in closed form: Ego drives +x at
//! 10 m/s, Target drives −x at 10 m/s on the other side of the road. Their speeds are equal
//! (relative speed 0), but in Ego's frame Target moves at −10 m/s: longitudinally −20 m/s.

use crate::common::*;

fn scenario(direction: &str) -> String {
    let init = r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" offset="0" s="100"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>
<Private entityRef="Target"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="1" offset="0" s="500"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#;
    let cond = format!(
        r#"<Condition name="rel" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Target"/></TriggeringEntities><EntityCondition><RelativeSpeedCondition entityRef="Ego" value="-15" rule="lessThan"{direction}/></EntityCondition></ByEntityCondition></Condition>"#
    );
    let stop = event("Stop", "parallel", &speed_action("step", "time", 0.0, 0.0), &trigger(&cond));
    xosc(init, &story("Ego", &stop), &stop_at(1.0))
}

#[test]
fn a_longitudinal_relative_speed_is_measured_in_the_reference_frame() {
    let directed = run(&scenario(r#" direction="longitudinal""#));
    // −20 < −15 from the first evaluation: Ego stops at once
    assert!(event_time(&directed, "StopAction", "start").is_some_and(|t| t < 0.02), "{:?}", directed.trace.events);
    // without a direction it is the difference of the speeds, 0, never below −15
    let plain = run(&scenario(""));
    assert!(event_time(&plain, "StopAction", "start").is_none());
}
