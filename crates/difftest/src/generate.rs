//! The grammar: a scenario is a map, one to three cars placed by Init positions of every kind,
//! and a story of one to three events, each one action (speed, lane change, lane offset,
//! teleport) with its dynamics, started by a condition (simulation time, traveled distance,
//! speed, relative distance) with an edge, a delay and a priority; a car may be driven by
//! esmini's ACC controller (override or additive mode). Every random choice comes
//! from a ChaCha8 generator seeded with the seed and set to the scenario's index as its stream,
//! so scenario `i` of a seed is always the same bytes, whatever else is generated.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::roads::{MapChoice, Spot, LANE_WIDTH};

/// One generated scenario: its text and the features it exercises.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    pub name: String,
    pub xosc: String,
    /// e.g. `action:SpeedAction`, `dynamics:SpeedAction/cubic/time`, `condition:SpeedCondition`.
    pub features: BTreeSet<String>,
}

const CAR: &str = r#"<Vehicle name="car" vehicleCategory="car"><ParameterDeclarations/>
<Performance maxSpeed="69.444" maxAcceleration="10" maxDeceleration="10"/>
<BoundingBox><Center x="1.4" y="0.0" z="0.75"/><Dimensions width="2.0" length="5.04" height="1.5"/></BoundingBox>
<Axles><FrontAxle maxSteering="0.5236" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>
<RearAxle maxSteering="0.5236" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles>
<Properties/></Vehicle>"#;

struct Gen<'a> {
    rng: ChaCha8Rng,
    features: BTreeSet<String>,
    map: &'a MapChoice,
    spot: &'a Spot,
}

impl Gen<'_> {
    fn pick<'b, T>(&mut self, items: &'b [T]) -> &'b T {
        &items[self.rng.gen_range(0..items.len())]
    }
    fn num(&mut self, lo: f64, hi: f64) -> f64 {
        // two decimals: the file says exactly what both simulators read
        (self.rng.gen_range(lo..hi) * 100.0).round() / 100.0
    }
    fn feature(&mut self, f: impl Into<String>) {
        self.features.insert(f.into());
    }

    fn lane_position(&mut self, lane: i32, s: f64) -> String {
        format!(r#"<LanePosition roadId="{}" laneId="{lane}" offset="0" s="{s}"/>"#, self.spot.road)
    }

    /// The first entity's position: lane, road or (on the straight map) world.
    fn absolute_position(&mut self) -> String {
        let lane = *self.pick(&self.spot.lanes.clone());
        let s = self.num(self.spot.s_min, self.spot.s_max);
        let kinds: &[&str] = if self.map.straight { &["LanePosition", "RoadPosition", "WorldPosition"] } else { &["LanePosition", "RoadPosition"] };
        let kind = *self.pick(kinds);
        self.feature(format!("init:{kind}"));
        match kind {
            "RoadPosition" => {
                let t = -(f64::from(-lane) - 0.5) * LANE_WIDTH;
                format!(r#"<RoadPosition roadId="{}" s="{s}" t="{t}"/>"#, self.spot.road)
            }
            "WorldPosition" => {
                let y = -(f64::from(-lane) - 0.5) * LANE_WIDTH;
                format!(r#"<WorldPosition x="{s}" y="{y}" z="0" h="0"/>"#)
            }
            _ => self.lane_position(lane, s),
        }
    }

    /// A later entity's position: absolute, or relative to an entity already placed.
    fn position(&mut self, placed: &[String]) -> String {
        if placed.is_empty() || self.rng.gen_bool(0.3) {
            return self.absolute_position();
        }
        let reference = self.pick(placed).clone();
        let kind = *self.pick(&["RelativeLanePosition", "RelativeObjectPosition", "RelativeRoadPosition"]);
        self.feature(format!("init:{kind}"));
        let ds = self.num(-40.0, 40.0);
        match kind {
            "RelativeLanePosition" => {
                let d_lane = *self.pick(&[-1, 0, 0, 1]);
                format!(r#"<RelativeLanePosition entityRef="{reference}" dLane="{d_lane}" ds="{ds}" offset="0"/>"#)
            }
            "RelativeObjectPosition" => {
                let dy = *self.pick(&[-LANE_WIDTH, 0.0, LANE_WIDTH]);
                format!(r#"<RelativeObjectPosition entityRef="{reference}" dx="{ds}" dy="{dy}"/>"#)
            }
            _ => {
                let dt = *self.pick(&[-LANE_WIDTH, 0.0, LANE_WIDTH]);
                format!(r#"<RelativeRoadPosition entityRef="{reference}" ds="{ds}" dt="{dt}"/>"#)
            }
        }
    }

    fn dynamics(&mut self, element: &str, action: &str, allow_rate: bool) -> String {
        let shape = *self.pick(&["linear", "cubic", "sinusoidal", "step"]);
        let dims: &[&str] = if allow_rate { &["time", "distance", "rate"] } else { &["time", "distance"] };
        let dim = *self.pick(dims);
        let value = match (shape, dim) {
            ("step", _) => 0.0,
            (_, "time") => self.num(0.5, 5.0),
            (_, "distance") => self.num(10.0, 80.0),
            _ => self.num(1.0, 4.0),
        };
        self.feature(format!("dynamics:{action}/{shape}/{dim}"));
        format!(r#"<{element} dynamicsShape="{shape}" value="{value}" dynamicsDimension="{dim}"/>"#)
    }

    fn action(&mut self, actor: &str, others: &[String]) -> String {
        let kind = *self.pick(&["SpeedAction", "SpeedAction", "LaneChangeAction", "LaneChangeAction", "LaneOffsetAction", "TeleportAction"]);
        self.feature(format!("action:{kind}"));
        match kind {
            "SpeedAction" => {
                let dynamics = self.dynamics("SpeedActionDynamics", kind, true);
                let target = if others.is_empty() || self.rng.gen_bool(0.6) {
                    format!(r#"<AbsoluteTargetSpeed value="{}"/>"#, self.num(0.0, 35.0))
                } else {
                    let other = self.pick(others).clone();
                    let (kind, value) = if self.rng.gen_bool(0.5) { ("delta", self.num(-5.0, 5.0)) } else { ("factor", self.num(0.5, 1.5)) };
                    let continuous = self.rng.gen_bool(0.5);
                    self.feature(format!("speed-target:relative/{kind}/continuous={continuous}"));
                    format!(r#"<RelativeTargetSpeed entityRef="{other}" value="{value}" speedTargetValueType="{kind}" continuous="{continuous}"/>"#)
                };
                format!("<PrivateAction><LongitudinalAction><SpeedAction>{dynamics}<SpeedActionTarget>{target}</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>")
            }
            "LaneChangeAction" => {
                let dynamics = self.dynamics("LaneChangeActionDynamics", kind, false);
                let target = if self.rng.gen_bool(0.5) {
                    self.feature("lane-change-target:relative");
                    format!(r#"<RelativeTargetLane entityRef="{actor}" value="{}"/>"#, self.pick(&[-1, 1]))
                } else {
                    self.feature("lane-change-target:absolute");
                    format!(r#"<AbsoluteTargetLane value="{}"/>"#, self.pick(&self.spot.lanes.clone()))
                };
                format!("<PrivateAction><LateralAction><LaneChangeAction>{dynamics}<LaneChangeTarget>{target}</LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>")
            }
            "LaneOffsetAction" => {
                let shape = *self.pick(&["linear", "cubic", "sinusoidal", "step"]);
                self.feature(format!("dynamics:LaneOffsetAction/{shape}"));
                let acc = self.num(0.5, 3.0);
                let value = self.num(-1.2, 1.2);
                format!(
                    r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="{acc}" dynamicsShape="{shape}"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="{value}"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#
                )
            }
            _ => {
                let lane = *self.pick(&self.spot.lanes.clone());
                let s = self.num(self.spot.s_min, self.spot.s_max + 100.0);
                let position = self.lane_position(lane, s);
                format!("<PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction>")
            }
        }
    }

    fn condition(&mut self, actor: &str, entities: &[String]) -> String {
        let kind =
            *self.pick(&["SimulationTimeCondition", "SimulationTimeCondition", "TraveledDistanceCondition", "SpeedCondition", "RelativeDistanceCondition"]);
        let kind = if kind == "RelativeDistanceCondition" && entities.len() < 2 { "SimulationTimeCondition" } else { kind };
        self.feature(format!("condition:{kind}"));
        let edge = *self.pick(&["none", "none", "rising", "risingOrFalling"]);
        if edge != "none" {
            self.feature(format!("edge:{edge}"));
        }
        let delay = *self.pick(&[0.0, 0.0, 0.5, 1.3]);
        if delay > 0.0 {
            self.feature("condition-delay");
        }
        let body = match kind {
            "SimulationTimeCondition" => {
                let rule = *self.pick(&["greaterThan", "greaterOrEqual"]);
                format!(r#"<ByValueCondition><SimulationTimeCondition value="{}" rule="{rule}"/></ByValueCondition>"#, self.num(0.0, 6.0))
            }
            _ => {
                let entity = if kind == "TraveledDistanceCondition" { actor.to_string() } else { self.pick(entities).clone() };
                let condition = match kind {
                    "TraveledDistanceCondition" => format!(r#"<TraveledDistanceCondition value="{}"/>"#, self.num(5.0, 120.0)),
                    "SpeedCondition" => {
                        let rule = *self.pick(&["greaterThan", "lessThan"]);
                        format!(r#"<SpeedCondition value="{}" rule="{rule}"/>"#, self.num(2.0, 30.0))
                    }
                    _ => {
                        let others: Vec<String> = entities.iter().filter(|e| **e != entity).cloned().collect();
                        let other = self.pick(&others).clone();
                        let kind = *self.pick(&["longitudinal", "euclidianDistance", "lateral"]);
                        let freespace = self.rng.gen_bool(0.5);
                        let rule = *self.pick(&["greaterThan", "lessThan"]);
                        self.feature(format!("relative-distance:{kind}/freespace={freespace}"));
                        format!(
                            r#"<RelativeDistanceCondition entityRef="{other}" relativeDistanceType="{kind}" value="{}" freespace="{freespace}" rule="{rule}" coordinateSystem="entity"/>"#,
                            self.num(2.0, 60.0)
                        )
                    }
                };
                format!(
                    r#"<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="{entity}"/></TriggeringEntities><EntityCondition>{condition}</EntityCondition></ByEntityCondition>"#
                )
            }
        };
        format!(r#"<Condition name="c" delay="{delay}" conditionEdge="{edge}">{body}</Condition>"#)
    }
}

/// Scenario `index` of `seed` on one of `maps` (referred to by `map.name` from the folder the
/// scenario is written to).
pub fn generate(seed: u64, index: u64, maps: &[MapChoice]) -> Generated {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    let map = &maps[rng.gen_range(0..maps.len())];
    let spot = &map.spots[rng.gen_range(0..map.spots.len())];
    let mut g = Gen { rng, features: BTreeSet::new(), map, spot };
    g.feature(format!(
        "map:{}",
        if map.straight {
            "builtin-straight"
        } else if map.name == "curve.xodr" {
            "builtin-curve"
        } else {
            "folder"
        }
    ));

    let n = g.rng.gen_range(1..=3);
    let names: Vec<String> = (0..n).map(|i| format!("Car{i}")).collect();
    if n > 1 {
        g.feature(format!("entities:{n}"));
    }
    let mut init = String::new();
    let mut placed = Vec::new();
    let mut controllers = Vec::new();
    for name in &names {
        let position = g.position(&placed);
        let speed = g.num(0.0, 30.0);
        // a driver model: esmini's ACC controller, in override or additive mode, activated in Init
        let acc = g.rng.gen_bool(0.2);
        let (controller, activate) = if acc {
            let mode = *g.pick(&["override", "additive"]);
            g.feature(format!("controller:ACCController/{mode}"));
            let gap = g.num(0.5, 2.0);
            let set_speed = g.num(10.0, 30.0);
            (
                format!(
                    r#"<ObjectController><Controller name="ACC{name}"><Properties><Property name="esminiController" value="ACCController"/><Property name="timeGap" value="{gap}"/><Property name="mode" value="{mode}"/><Property name="setSpeed" value="{set_speed}"/></Properties></Controller></ObjectController>"#
                ),
                r#"<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="false"/></ControllerAction></PrivateAction>"#
                    .to_string(),
            )
        } else {
            (String::new(), String::new())
        };
        controllers.push(controller);
        let _ = writeln!(
            init,
            r#"<Private entityRef="{name}"><PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>{activate}</Private>"#
        );
        placed.push(name.clone());
    }

    let events = g.rng.gen_range(1..=3);
    let mut groups = String::new();
    for e in 0..events {
        let actor = g.pick(&names).clone();
        let others: Vec<String> = names.iter().filter(|n| **n != actor).cloned().collect();
        let action = g.action(&actor, &others);
        let condition = g.condition(&actor, &names);
        let priority = *g.pick(&["parallel", "parallel", "override"]);
        if priority != "parallel" {
            g.feature(format!("priority:{priority}"));
        }
        let _ = write!(
            groups,
            r#"<ManeuverGroup maximumExecutionCount="1" name="G{e}"><Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors>
<Maneuver name="M{e}"><Event name="E{e}" priority="{priority}" maximumExecutionCount="1"><Action name="A{e}">{action}</Action>
<StartTrigger><ConditionGroup>{condition}</ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>
"#
        );
    }
    let stop = g.num(6.0, 15.0);
    let entities: String = names.iter().zip(&controllers).map(|(n, c)| format!(r#"<ScenarioObject name="{n}">{CAR}{c}</ScenarioObject>"#)).collect();
    let name = format!("s{seed}_{index:05}");
    let xosc = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2026-01-01T00:00:00" description="difftest seed {seed} scenario {index}" author="osc2cr difftest"/>
<ParameterDeclarations/>
<CatalogLocations/>
<RoadNetwork><LogicFile filepath="{map}"/></RoadNetwork>
<Entities>{entities}</Entities>
<Storyboard>
<Init><Actions>
{init}</Actions></Init>
<Story name="S"><Act name="Act">
{groups}<StartTrigger><ConditionGroup><Condition name="start" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>
</Act></Story>
<StopTrigger><ConditionGroup><Condition name="stop" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{stop}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard>
</OpenSCENARIO>
"#,
        map = map.name
    );
    Generated { name, xosc, features: g.features }
}
