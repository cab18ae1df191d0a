//! The trace audit before writing: a value that is not finite is an error; a jump no
//! position-setting action explains, and an entity far from the map, are warnings naming the
//! entity, the time and what was running. Traces are built by hand (0.01 s steps).

use crate::common::{sample, straight, trace};
use engine::StoryboardEvent;
use openscenario::{load_str, Content, LoadOptions, Scenario};
use std::path::Path;

/// `Car` with one event whose action `Hop` is a TeleportAction, and `Lane` a LaneChangeAction.
fn scenario() -> Scenario {
    let text = r#"<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork/>
<Entities><ScenarioObject name="Car"><MiscObject name="b" miscObjectCategory="obstacle" mass="1"><BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="1" length="1" height="1"/></BoundingBox><Properties/></MiscObject></ScenarioObject></Entities>
<Storyboard><Init><Actions/></Init>
<Story name="S"><Act name="A"><ManeuverGroup name="G" maximumExecutionCount="1"><Actors selectTriggeringEntities="false"><EntityRef entityRef="Car"/></Actors><Maneuver name="M">
<Event name="E1" priority="parallel"><Action name="Hop"><PrivateAction><TeleportAction><Position><WorldPosition x="50" y="0"/></Position></TeleportAction></PrivateAction></Action>
<StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>
<Event name="E2" priority="parallel"><Action name="Lane"><PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction></Action>
<StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>
</Maneuver></ManeuverGroup></Act></Story></Storyboard></OpenSCENARIO>"#;
    match load_str(Path::new("/virtual/audit.xosc"), text, &LoadOptions::default()).map(|l| l.content) {
        Ok(Content::Scenario(s)) => *s,
        other => panic!("{other:?}"),
    }
}

fn event(time: f64, element: &str, transition: &str) -> StoryboardEvent {
    StoryboardEvent { time, element: element.into(), from: String::new(), transition: transition.into(), to: String::new() }
}

/// 10 m/s along +x, and 40 m further from step 100 (1.00 s) on.
fn jumping(k: usize) -> Option<engine::Sample> {
    let s = straight(0.0, 0.0, 10.0)(k);
    Some(if k >= 100 { sample(s.x + 40.0, s.y, 0.0, 10.0) } else { s })
}

#[test]
fn a_value_that_is_not_finite_is_an_error() {
    let t = trace(10, &["Car"], |_, k| Some(if k == 7 { sample(f64::NAN, 0.0, 0.0, 1.0) } else { sample(0.0, 0.0, 0.0, 0.0) }));
    let err = convert::audit_trace(&t, &scenario(), None).expect_err("NaN is an error");
    assert!(err.contains("`Car`") && err.contains("0.07 s") && err.contains("NaN"), "{err}");
}

#[test]
fn a_jump_nothing_explains_is_said_with_entity_time_and_action() {
    let mut t = trace(200, &["Car"], |_, k| jumping(k));
    // the lane change runs from 0.5 s to the end; no teleport
    t.events.push(event(0.5, "Lane", "start"));
    let w = convert::audit_trace(&t, &scenario(), None).expect("finite");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("`Car` jumps 40.10 m between 0.99 s and 1.00 s"), "{}", w[0]);
    assert!(w[0].contains("`Lane` (LaneChangeAction)"), "{}", w[0]);
}

#[test]
fn a_teleport_explains_its_jump() {
    let mut t = trace(200, &["Car"], |_, k| jumping(k));
    t.events.push(event(1.0, "Hop", "start"));
    t.events.push(event(1.0, "Hop", "end"));
    assert!(convert::audit_trace(&t, &scenario(), None).expect("finite").is_empty());
    // a ghost is not a road user: its restarts are not audited
    let mut t = trace(200, &["Car"], |_, k| jumping(k));
    t.ghosts.push("Car".into());
    assert!(convert::audit_trace(&t, &scenario(), None).expect("finite").is_empty());
}

#[test]
fn speed_explains_motion_and_appearing_is_no_jump() {
    // 60 m/s moves 0.6 m a step: no jump; an entity that appears at step 50 far away: no jump
    let t = trace(100, &["Car"], |_, k| if k < 50 { None } else { Some(straight(5000.0, 0.0, 60.0)(k)) });
    assert!(convert::audit_trace(&t, &scenario(), None).expect("finite").is_empty());
}

#[test]
fn far_outside_the_map_is_said() {
    use commonroad::{Lanelet, LaneletBounds, LaneletId, LaneletNetwork, LaneletType, Point};
    let p = |x: f64, y: f64| Point { x, y, z: None };
    let bounds = LaneletBounds::new(vec![p(0.0, 3.5), p(100.0, 3.5)], vec![p(0.0, 0.0), p(100.0, 0.0)]).expect("bounds");
    let mut map = LaneletNetwork::default();
    map.lanelets.push(Lanelet::new(LaneletId::new(1).expect("id"), bounds, LaneletType::Urban));
    // the map is 100 m long: "far" is 1000 m beyond it; the car ends 1,900 m beyond
    let t = trace(200, &["Car"], |_, k| Some(sample(if k < 150 { 50.0 } else { 2000.0 }, 0.0, 0.0, 0.0)));
    let mut t2 = t.clone();
    t2.events.push(event(1.5, "Hop", "start"));
    let w = convert::audit_trace(&t2, &scenario(), Some(&map)).expect("finite");
    assert_eq!(w.len(), 1, "the teleport explains the jump, not the place: {w:?}");
    assert!(w[0].contains("`Car` is 1900 m outside the map at 1.50 s"), "{}", w[0]);
    // inside the margin: nothing
    let near = trace(10, &["Car"], |_, _| Some(sample(900.0, 0.0, 0.0, 0.0)));
    assert!(convert::audit_trace(&near, &scenario(), Some(&map)).expect("finite").is_empty());
}
