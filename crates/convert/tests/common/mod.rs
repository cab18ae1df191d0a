//! Builders for synthetic entities and traces (tests only).
#![allow(dead_code)]

use engine::{EntityTrace, Sample, Trace};
use openscenario::{
    Axle, Axles, BoundingBox, Entity, EntityObject, Location, MiscObject, MiscObjectCategory, Pedestrian, PedestrianCategory, Performance, Properties, Vec3,
    Vehicle, VehicleCategory,
};
use std::path::Path;

pub(crate) fn bbox(cx: f64, cy: f64, length: f64, width: f64) -> BoundingBox {
    BoundingBox { center: Vec3 { x: cx, y: cy, z: 0.75 }, width, length, height: 1.5 }
}

fn origin() -> Location {
    Location::file_only(Path::new("synthetic.xosc"))
}

pub(crate) fn vehicle(name: &str, category: VehicleCategory, bb: BoundingBox) -> Entity {
    let axle = Axle { max_steering: 0.5, wheel_diameter: 0.6, track_width: 1.6, position_x: 0.0, position_z: 0.3 };
    entity(
        name,
        EntityObject::Vehicle(Vehicle {
            name: name.into(),
            category,
            role: None,
            mass: None,
            model3d: None,
            parameters: Vec::new(),
            bounding_box: bb,
            performance: Performance {
                max_speed: 70.0,
                max_acceleration: 10.0,
                max_deceleration: 10.0,
                max_acceleration_rate: None,
                max_deceleration_rate: None,
            },
            axles: Axles { front: Some(axle), rear: axle, additional: Vec::new() },
            properties: Properties::default(),
            trailer_hitch: None,
            trailer_coupler: None,
            trailer: None,
        }),
    )
}

pub(crate) fn car(name: &str) -> Entity {
    vehicle(name, VehicleCategory::Car, bbox(1.4, 0.0, 4.5, 2.0))
}

/// An entity without controllers, at the synthetic origin.
fn entity(name: &str, object: EntityObject) -> Entity {
    Entity { name: name.into(), object, controllers: Vec::new(), origin: origin() }
}

pub(crate) fn pedestrian(name: &str, category: PedestrianCategory, bb: BoundingBox) -> Entity {
    let pedestrian = Pedestrian {
        name: name.into(),
        category,
        role: None,
        mass: 80.0,
        model3d: None,
        parameters: Vec::new(),
        bounding_box: bb,
        properties: Properties::default(),
    };
    entity(name, EntityObject::Pedestrian(pedestrian))
}

pub(crate) fn misc(name: &str, category: MiscObjectCategory, bb: BoundingBox) -> Entity {
    let misc =
        MiscObject { name: name.into(), category, mass: 100.0, model3d: None, parameters: Vec::new(), bounding_box: bb, properties: Properties::default() };
    entity(name, EntityObject::MiscObject(misc))
}

pub(crate) fn sample(x: f64, y: f64, h: f64, speed: f64) -> Sample {
    Sample { x, y, z: 0.0, h, speed, acceleration: 0.0, yaw_rate: 0.0, road: None, visible: true }
}

/// A trace of `len` steps of 0.01 s; `f(k)` gives each entity's sample at step k.
pub(crate) fn trace(len: usize, names: &[&str], f: impl Fn(usize, usize) -> Option<Sample>) -> Trace {
    Trace {
        start: 0.0,
        step: 0.01,
        len,
        entities: names.iter().enumerate().map(|(i, n)| EntityTrace { name: n.to_string(), samples: (0..len).map(|k| f(i, k)).collect() }).collect(),
        ghosts: Vec::new(),
        events: Vec::new(),
        signal_states: Vec::new(),
        replays: Vec::new(),
    }
}

/// Straight motion along +x at `v` m/s from `x0`, heading 0.
pub(crate) fn straight(x0: f64, y: f64, v: f64) -> impl Fn(usize) -> Sample {
    move |k| sample(x0 + v * k as f64 * 0.01, y, 0.0, v)
}

/// A `<Vehicle>` for scenarios written in tests: 4.5 × 2 m, box centre 1.5 m ahead of the rear
/// axle.
pub(crate) const CAR: &str = r#"<Vehicle name="car" vehicleCategory="car"><ParameterDeclarations/>
<Performance maxSpeed="70" maxAcceleration="200" maxDeceleration="200"/>
<BoundingBox><Center x="1.5" y="0" z="0.9"/><Dimensions width="2.0" length="4.5" height="1.8"/></BoundingBox>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="3.1" positionZ="0.3"/>
<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/></Axles>
<Properties/></Vehicle>"#;

/// A fresh temporary directory for one test's files.
pub(crate) fn fresh_dir(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("osc2cr-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Converts `dir/<name>.xosc` with the default options, removes `dir`, and returns what the
/// conversion reports and the model it built (panics, with the failure, if it failed).
pub(crate) fn convert_and_clean(dir: &Path, name: &str) -> (convert::Conversion, convert::Model) {
    let path = dir.join(format!("{name}.xosc"));
    let request = convert::Request::named(&path, name).keeping_model();
    let (conversion, model) = convert::convert(&request, &convert::ConvertOptions::default());
    let _ = std::fs::remove_dir_all(dir);
    assert!(conversion.result.is_ok(), "{:?}", conversion.result.err());
    (conversion, model.expect("model kept"))
}

/// A vehicle on lane `lane` of road 1 at `s`, driving at `speed` from the start (an Init
/// `Private`: teleport and a step speed change).
pub(crate) fn place(entity: &str, s: f64, lane: i32, speed: f64) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction>
<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#
    )
}

/// An event named `event` whose one action `action` does `body` (a `GlobalAction`'s content)
/// once the simulation time reaches `t`.
pub(crate) fn global_event_at(event: &str, action: &str, t: f64, body: &str) -> String {
    format!(
        r#"<Event name="{event}" priority="parallel"><Action name="{action}"><GlobalAction>{body}</GlobalAction></Action>
<StartTrigger><ConditionGroup><Condition name="t" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>"#
    )
}

/// An OpenSCENARIO 1.1 scenario on the road file `xodr`: the ScenarioObjects `entities`, the
/// Init actions `init`, one maneuver acted by Ego holding `events` (started at 0 s), and the
/// stop once the simulation time is `rule` (`greaterThan`, `greaterOrEqual`) `stop`.
pub(crate) fn one_maneuver_scenario(description: &str, xodr: &str, entities: &str, init: &str, events: &str, rule: &str, stop: f64) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="{description}" author="osc2cr"/>
<ParameterDeclarations/>
<CatalogLocations/>
<RoadNetwork><LogicFile filepath="{xodr}"/></RoadNetwork>
<Entities>{entities}</Entities>
<Storyboard>
<Init><Actions>{init}</Actions></Init>
<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false"><EntityRef entityRef="Ego"/></Actors>
<Maneuver name="M">{events}</Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{stop}" rule="{rule}"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard>
</OpenSCENARIO>"#
    )
}
