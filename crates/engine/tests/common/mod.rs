//! Shared helpers for the engine's scenario tests: a scenario on the straight fixture road
//! (1000 m along +x; lanes 1, -1, -2 each 3.5 m wide, so lane -1's centre is y = -1.75) with
//! two cars, Ego and Target (bounding box centre 1.5 m ahead of the reference point, 4.5 m x 2 m).

#![allow(dead_code)]

pub(crate) mod oracle;

use engine::{Run, Settings};
use std::path::Path;

pub(crate) fn fixtures() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures")
}

fn car(name: &str) -> String {
    car_with(name, "")
}

/// A car as in every scenario here, followed by `controller` (an ObjectController, or nothing).
pub(crate) fn car_with(name: &str, controller: &str) -> String {
    format!(
        r#"<ScenarioObject name="{name}"><Vehicle name="car" vehicleCategory="car">
  <ParameterDeclarations/>
  <Performance maxSpeed="70" maxAcceleration="200" maxDeceleration="200"/>
  <BoundingBox><Center x="1.5" y="0" z="0.9"/><Dimensions width="2.0" length="4.5" height="1.8"/></BoundingBox>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="3.1" positionZ="0.3"/>
  <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/></Axles>
  <Properties/></Vehicle>{controller}</ScenarioObject>"#
    )
}

/// A scenario: `init` inside <Actions>, `stories` after </Init>, `stop` the storyboard StopTrigger content.
pub(crate) fn xosc(init: &str, stories: &str, stop: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="test" author="osc2cr"/>
<ParameterDeclarations><ParameterDeclaration name="X" parameterType="double" value="0"/></ParameterDeclarations>
<CatalogLocations/>
<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>
<Entities>{}{}</Entities>
<Storyboard>
<Init><Actions>{init}</Actions></Init>
{stories}
<StopTrigger>{stop}</StopTrigger>
</Storyboard>
</OpenSCENARIO>"#,
        car("Ego"),
        car("Target")
    )
}

pub(crate) fn lane_pos(s: f64, lane: i32) -> String {
    format!(r#"<Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position>"#)
}

pub(crate) fn teleport(entity: &str, s: f64, lane: i32) -> String {
    format!(r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction></Private>"#, lane_pos(s, lane))
}

pub(crate) fn speed_action(shape: &str, dim: &str, value: f64, target: f64) -> String {
    format!(
        r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="{shape}" dynamicsDimension="{dim}" value="{value}"/><SpeedActionTarget><AbsoluteTargetSpeed value="{target}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#
    )
}

pub(crate) fn init_speed(entity: &str, shape: &str, dim: &str, value: f64, target: f64) -> String {
    format!(r#"<Private entityRef="{entity}">{}</Private>"#, speed_action(shape, dim, value, target))
}

/// `entity` put on lane `lane` of the fixture road at `s`, at `speed` from the start (a step).
pub(crate) fn placed(entity: &str, s: f64, lane: i32, speed: f64) -> String {
    format!("{}{}", teleport(entity, s, lane), init_speed(entity, "step", "time", 0.0, speed))
}

/// As [`placed`], in one `Private` element (esmini refuses a second one for the same entity
/// where a test puts it beside its other Init actions).
pub(crate) fn placed_in_one_private(entity: &str, s: f64, lane: i32, speed: f64) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>{}</Private>"#,
        lane_pos(s, lane),
        speed_action("step", "time", 0.0, speed)
    )
}

/// The stop trigger's condition group: simulated time past `t`.
pub(crate) fn stop_at(t: f64) -> String {
    format!("<ConditionGroup>{}</ConditionGroup>", sim_time(t, "greaterThan", "none", 0.0))
}

pub(crate) fn sim_time(value: f64, rule: &str, edge: &str, delay: f64) -> String {
    format!(
        r#"<Condition name="t" delay="{delay}" conditionEdge="{edge}"><ByValueCondition><SimulationTimeCondition value="{value}" rule="{rule}"/></ByValueCondition></Condition>"#
    )
}

pub(crate) fn trigger(conditions: &str) -> String {
    format!("<StartTrigger><ConditionGroup>{conditions}</ConditionGroup></StartTrigger>")
}

/// A story with one act (started at once) whose maneuver group has `actor` and the given events.
pub(crate) fn story(actor: &str, events: &str) -> String {
    format!(
        r#"<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors><Maneuver name="M">{events}</Maneuver></ManeuverGroup>{}</Act></Story>"#,
        trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))
    )
}

pub(crate) fn event(name: &str, priority: &str, action: &str, start: &str) -> String {
    format!(r#"<Event name="{name}" priority="{priority}"><Action name="{name}Action">{action}</Action>{start}</Event>"#)
}

pub(crate) fn run_with(text: &str, settings: &Settings) -> Run {
    run_on(text, "straight.xodr", settings)
}

/// Test scenario `text` (read as `fixtures/test.xosc`) as a model.
pub(crate) fn scenario_of(text: &str) -> openscenario::Scenario {
    let loaded = openscenario::load_str(&fixtures().join("test.xosc"), text, &Default::default()).expect("test scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("not a scenario") };
    *scenario
}

/// Fixture road `xodr` (in `fixtures/`).
pub(crate) fn fixture_road(xodr: &str) -> opendrive::RoadNetwork {
    opendrive::load(fixtures().join(xodr)).expect("fixture road loads").network
}

/// Test scenario `text` run on fixture road `xodr`.
pub(crate) fn run_on(text: &str, xodr: &str, settings: &Settings) -> Run {
    engine::simulate(&scenario_of(text), Some(&fixture_road(xodr)), settings).expect("simulate")
}

/// Run the fixture scenario `name` (in `fixtures/`) on the straight fixture road, 0.01 s steps.
pub(crate) fn run_straight_fixture(name: &str, max_time: f64) -> Run {
    run_fixture_on(name, "straight.xodr", max_time)
}

/// Run the fixture scenario `name` on the fixture road network `map`, 0.01 s steps.
pub(crate) fn run_fixture_on(name: &str, map: &str, max_time: f64) -> Run {
    let loaded = openscenario::load(&fixtures().join(name), &Default::default()).expect("fixture scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("not a scenario") };
    let net = opendrive::load(fixtures().join(map)).expect("fixture road loads").network;
    engine::simulate(&scenario, Some(&net), &Settings { step: 0.01, max_time }).expect("simulate")
}

/// Assert that `run` puts each (entity, time, x, y, heading) row of an esmini log (6 decimals)
/// within `tol` m and `tol_h` rad.
pub(crate) fn assert_esmini_poses(run: &Run, rows: &[(&str, f64, f64, f64, f64)], tol: f64, tol_h: f64) {
    use std::f64::consts::PI;
    for &(name, t, x, y, h) in rows {
        let s = at(run, name, t);
        let dh = (s.h - h + PI).rem_euclid(2.0 * PI) - PI;
        assert!(close(s.x, x, tol) && close(s.y, y, tol) && dh.abs() < tol_h, "{name} at {t}: ({}, {}, {}) against esmini ({x}, {y}, {h})", s.x, s.y, s.h);
    }
}

/// Assert that `run` puts `entity` at each (time, x, y, speed) row of an esmini log within `tol`.
pub(crate) fn assert_esmini_rows(run: &Run, entity: &str, rows: &[(f64, f64, f64, f64)], tol: f64) {
    for &(t, x, y, v) in rows {
        let e = at(run, entity, t);
        assert!(close(e.x, x, tol) && close(e.y, y, tol) && close(e.speed, v, tol), "{entity} at {t}: {e:?}, esmini ({x}, {y}, {v})");
    }
}

/// Assert that `run` gives each (entity, time, x, speed) row of an esmini log within `tol`.
pub(crate) fn assert_esmini_x_speed(run: &Run, rows: &[(&str, f64, f64, f64)], tol: f64) {
    for &(name, t, x, v) in rows {
        let s = at(run, name, t);
        assert!(close(s.x, x, tol) && close(s.speed, v, tol), "{name} at {t}: x {} speed {} against esmini {x} {v}", s.x, s.speed);
    }
}

pub(crate) fn run(text: &str) -> Run {
    run_with(text, &Settings { step: 0.01, max_time: 20.0 })
}

/// The run of fixture scenario `xosc` on fixture road `xodr` (0.01 s steps, at most 20 s).
pub(crate) fn run_fixture(xosc: &str, xodr: &str) -> Run {
    let loaded = openscenario::load(&fixtures().join(xosc), &Default::default()).expect("fixture scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("not a scenario") };
    let net = opendrive::load(fixtures().join(xodr)).expect("fixture road loads").network;
    engine::simulate(&scenario, Some(&net), &Settings { step: 0.01, max_time: 20.0 }).expect("simulate")
}

/// Sample of `entity` at time `t` (a run with a ghost's head start begins before 0).
pub(crate) fn at(run: &Run, entity: &str, t: f64) -> engine::Sample {
    let e = run.trace.entities.iter().find(|e| e.name == entity).expect("entity in trace");
    let k = ((t - run.trace.start) / run.trace.step).round() as usize;
    e.samples.get(k).copied().flatten().expect("sample exists")
}

/// Time of the first transition `transition` of element `element`.
pub(crate) fn event_time(run: &Run, element: &str, transition: &str) -> Option<f64> {
    run.trace.events.iter().find(|e| e.element == element && e.transition == transition).map(|e| e.time)
}

pub(crate) fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Init of an Ego at s = 50 on lane −1 driving 10 m/s whose controllers are activated (the
/// FollowGhost tests), followed by `others`.
pub(crate) fn ghost_ego_init(others: &str) -> String {
    let activate = r#"<Private entityRef="Ego"><PrivateAction><ActivateControllerAction longitudinal="true" lateral="true"/></PrivateAction></Private>"#;
    format!("{}{}{others}{activate}", teleport("Ego", 50.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0))
}

/// `text` with a FollowGhostController of head start `headstart` s on its first entity (Ego).
pub(crate) fn with_follow_ghost(text: &str, headstart: f64) -> String {
    let c = format!(
        r#"<ObjectController><Controller name="driver"><Properties><Property name="esminiController" value="FollowGhostController"/><Property name="headstartTime" value="{headstart}"/></Properties></Controller></ObjectController></ScenarioObject>"#
    );
    text.replacen("</ScenarioObject>", &c, 1)
}
