//! Conditions and triggers: the value conditions (simulation time, parameter, variable,
//! storyboard element state, traffic signal and its controller) and the entity conditions
//! (traveled distance, speed, relative speed, acceleration, stand still, time headway, time to
//! collision, reach position, distance and relative distance of every kind and coordinate
//! system, relative clearance, angle, end of road, off road, collision), with an edge, a delay,
//! a triggering-entities rule, and condition groups (AND) under a trigger (OR).

use super::global_actions::PHASES;
use super::positions::Scope;
use super::{Area, EntityKind, Gen};

const RULES: [&str; 6] = ["greaterThan", "lessThan", "greaterOrEqual", "lessOrEqual", "equalTo", "notEqualTo"];

impl Gen<'_> {
    fn rule(&mut self) -> &'static str {
        let rule = self.pick(&["greaterThan", "lessThan", "greaterThan", "lessThan", "greaterOrEqual", "lessOrEqual"]);
        self.rule_word(rule)
    }

    /// The measuring options of a distance: a coordinate system and a distance type that
    /// esmini handles (in the world frame only the euclidean distance: esmini's
    /// `Object::FreeSpaceDistance…`/`Position::Distance` have no lateral or longitudinal
    /// world distance and log "Unhandled case").
    fn distance_options(&mut self, feature: &str) -> String {
        let cs = self.pick(&["entity", "entity", "road", "lane", "world"]);
        let freespace = self.chance(0.5);
        let t = if cs == "world" { "euclidianDistance" } else { self.pick(&["longitudinal", "lateral", "euclidianDistance"]) };
        if self.rev_minor == 0 {
            // 1.0 has neither attribute: `alongRoute` says road coordinates (esmini reads it as
            // the road system with the euclidean distance, ScenarioReader's parseOSCCondition)
            let along = cs == "road" || cs == "lane";
            self.feature(format!("{feature}/alongRoute={along}/freespace={freespace}"));
            return format!(r#" freespace="{freespace}" alongRoute="{along}""#);
        }
        let cs = self.coordinate_system_word(cs);
        self.feature(format!("{feature}/{cs}/freespace={freespace}"));
        self.feature(format!("{feature}/{t}"));
        format!(r#" freespace="{freespace}" coordinateSystem="{cs}" relativeDistanceType="{t}""#)
    }

    fn direction(&mut self, feature: &str) -> String {
        if !self.chance(0.25) {
            return String::new();
        }
        let d = self.pick(&["longitudinal", "lateral", "vertical"]);
        if !self.since(2) {
            return String::new();
        }
        self.feature(format!("{feature}/direction={d}"));
        format!(r#" direction="{d}""#)
    }

    fn value_condition(&mut self, kind: &str) -> String {
        let body = match kind {
            "ParameterCondition" => {
                let (p, kind) = self.parameter(false);
                let rule = self.pick(&RULES);
                let rule = self.rule_word(rule);
                let value = self.value_of(kind);
                format!(r#"<ParameterCondition parameterRef="{p}" value="{value}" rule="{rule}"/>"#)
            }
            "VariableCondition" => {
                let (v, kind) = self.variable(false);
                let rule = self.pick(&RULES);
                let rule = self.rule_word(rule);
                let value = self.value_of(kind);
                format!(r#"<VariableCondition variableRef="{v}" value="{value}" rule="{rule}"/>"#)
            }
            "StoryboardElementStateCondition" => {
                let i = self.pick_index(self.elements.len());
                let (kind, name) = self.elements[i].clone();
                let state =
                    self.pick(&["startTransition", "endTransition", "completeState", "runningState", "standbyState", "stopTransition", "skipTransition"]);
                if kind == "action" {
                    self.action_state_refs.push((name.clone(), state.to_string()));
                } else {
                    self.feature(format!("storyboard-state:{kind}/{state}"));
                }
                format!(r#"<StoryboardElementStateCondition storyboardElementType="{kind}" storyboardElementRef="{name}" state="{state}"/>"#)
            }
            "TrafficSignalCondition" => {
                self.uses_signals = true;
                let s = self.map.signals[self.pick_index(self.map.signals.len())].clone();
                let states = s.states();
                format!(r#"<TrafficSignalCondition name="{}" state="{}"/>"#, s.id, states[self.pick_index(states.len())])
            }
            "TrafficSignalControllerCondition" => {
                self.uses_signals = true;
                format!(r#"<TrafficSignalControllerCondition trafficSignalControllerRef="Lights" phase="{}"/>"#, self.pick(&PHASES).0)
            }
            _ => {
                let rule = self.pick(&["greaterThan", "greaterOrEqual"]);
                let rule = self.rule_word(rule);
                format!(r#"<SimulationTimeCondition value="{}" rule="{rule}"/>"#, self.num(0.0, 6.0))
            }
        };
        format!("<ByValueCondition>{body}</ByValueCondition>")
    }

    fn entity_condition(&mut self, kind: &str, actor: &str) -> String {
        // never a trailer: esmini 3.6.0 crashes measuring a free-space distance to one
        let names: Vec<String> = self.entities.iter().filter(|e| e.kind != EntityKind::Trailer).map(|e| e.name.clone()).collect();
        let mobile = self.mobile_names();
        let triggering =
            if kind == "TraveledDistanceCondition" || mobile.is_empty() { actor.to_string() } else { mobile[self.pick_index(mobile.len())].clone() };
        let others: Vec<String> = names.iter().filter(|n| **n != triggering).cloned().collect();
        let other = if others.is_empty() { triggering.clone() } else { others[self.pick_index(others.len())].clone() };
        let condition = match kind {
            "TraveledDistanceCondition" => format!(r#"<TraveledDistanceCondition value="{}"/>"#, self.num(5.0, 120.0)),
            "SpeedCondition" => {
                let (rule, dir) = (self.pick(&["greaterThan", "lessThan"]), self.direction("speed"));
                format!(r#"<SpeedCondition value="{}" rule="{rule}"{dir}/>"#, self.num(2.0, 30.0))
            }
            "RelativeSpeedCondition" => {
                let (rule, dir) = (self.rule(), self.direction("relative-speed"));
                format!(r#"<RelativeSpeedCondition entityRef="{other}" value="{}" rule="{rule}"{dir}/>"#, self.num(-8.0, 8.0))
            }
            "AccelerationCondition" => {
                let (rule, dir) = (self.rule(), self.direction("acceleration"));
                format!(r#"<AccelerationCondition value="{}" rule="{rule}"{dir}/>"#, self.num(-4.0, 4.0))
            }
            "StandStillCondition" => format!(r#"<StandStillCondition duration="{}"/>"#, self.num(0.0, 2.0)),
            "EndOfRoadCondition" => format!(r#"<EndOfRoadCondition duration="{}"/>"#, self.num(0.0, 1.0)),
            "OffroadCondition" => format!(r#"<OffroadCondition duration="{}"/>"#, self.num(0.0, 1.0)),
            "CollisionCondition" => {
                if self.chance(0.6) {
                    self.feature("collision:entity");
                    format!(r#"<CollisionCondition><EntityRef entityRef="{other}"/></CollisionCondition>"#)
                } else {
                    let t = self.pick(&["vehicle", "pedestrian", "miscellaneous"]);
                    self.feature(format!("collision:by-type/{t}"));
                    format!(r#"<CollisionCondition><ByType type="{t}"/></CollisionCondition>"#)
                }
            }
            "TimeHeadwayCondition" => {
                let (rule, opts) = (self.rule(), self.distance_options("time-headway"));
                format!(r#"<TimeHeadwayCondition entityRef="{other}" value="{}" rule="{rule}"{opts}/>"#, self.num(0.3, 4.0))
            }
            "TimeToCollisionCondition" => {
                let (rule, opts) = (self.rule(), self.distance_options("ttc"));
                let target = if self.chance(0.6) {
                    self.feature("ttc:target/entity");
                    format!(r#"<EntityRef entityRef="{other}"/>"#)
                } else {
                    self.feature("ttc:target/position");
                    format!("<Position>{}</Position>", self.target_position(&triggering, Scope::Plain))
                };
                format!(
                    r#"<TimeToCollisionCondition value="{}" rule="{rule}"{opts}><TimeToCollisionConditionTarget>{target}</TimeToCollisionConditionTarget></TimeToCollisionCondition>"#,
                    self.num(0.5, 8.0)
                )
            }
            "ReachPositionCondition" => {
                let place = self.place_ahead(&triggering, 10.0, 120.0);
                let position = self.place_position(&place, "reach:", Scope::Plain, false);
                format!(r#"<ReachPositionCondition tolerance="{}"><Position>{position}</Position></ReachPositionCondition>"#, self.num(1.0, 8.0))
            }
            "DistanceCondition" => {
                let (rule, opts) = (self.rule(), self.distance_options("distance"));
                let position = self.target_position(&triggering, Scope::Plain);
                format!(r#"<DistanceCondition value="{}" rule="{rule}"{opts}><Position>{position}</Position></DistanceCondition>"#, self.num(2.0, 80.0))
            }
            "RelativeClearanceCondition" => {
                let (from, to) = (self.pick(&[-2, -1, 0]), self.pick(&[0, 1, 2]));
                let refs = if self.chance(0.5) { format!(r#"<EntityRef entityRef="{other}"/>"#) } else { String::new() };
                format!(
                    r#"<RelativeClearanceCondition oppositeLanes="{}" distanceBackward="{}" distanceForward="{}" freeSpace="{}"><RelativeLaneRange from="{from}" to="{to}"/>{refs}</RelativeClearanceCondition>"#,
                    self.chance(0.3),
                    self.num(0.0, 30.0),
                    self.num(5.0, 60.0),
                    self.chance(0.5)
                )
            }
            "AngleCondition" => {
                let angle_type = self.pick(&["heading", "heading", "pitch", "roll"]);
                let cs = self.pick(&["road", "lane", "world"]);
                self.feature(format!("angle:{angle_type}/{cs}"));
                format!(
                    r#"<AngleCondition angleType="{angle_type}" angle="{}" angleTolerance="{}" coordinateSystem="{cs}"/>"#,
                    self.num(-0.5, 0.5),
                    self.num(0.01, 0.3)
                )
            }
            _ => {
                // RelativeDistanceCondition (the feature names kept from the first grammar)
                let t = self.pick(&["longitudinal", "euclidianDistance", "lateral"]);
                let freespace = self.chance(0.5);
                let rule = self.pick(&["greaterThan", "lessThan"]);
                let cs = if !self.rich(Area::Conditions) {
                    "entity"
                } else if t == "euclidianDistance" {
                    self.pick(&["entity", "road", "lane", "world"])
                } else {
                    self.pick(&["entity", "road", "lane"])
                };
                let cs = self.coordinate_system_word(cs);
                self.feature(format!("relative-distance:{t}/freespace={freespace}"));
                let cs = if self.since(1) {
                    self.feature(format!("relative-distance:coordinate-system/{cs}"));
                    format!(r#" coordinateSystem="{cs}""#)
                } else {
                    // 1.0 has none: the entity system
                    self.feature("relative-distance:coordinate-system/1.0");
                    String::new()
                };
                let t = self.distance_type_word(t);
                format!(
                    r#"<RelativeDistanceCondition entityRef="{other}" relativeDistanceType="{t}" value="{}" freespace="{freespace}" rule="{rule}"{cs}/>"#,
                    self.num(2.0, 60.0)
                )
            }
        };
        let (rule, extra) = if self.rich(Area::Conditions) && self.chance(0.15) && names.len() > 1 {
            let second = names.iter().find(|n| **n != triggering).cloned().unwrap_or_default();
            let r = self.pick(&["any", "all"]);
            self.feature(format!("triggering-entities:{r}"));
            (r, format!(r#"<EntityRef entityRef="{second}"/>"#))
        } else {
            ("any", String::new())
        };
        format!(
            r#"<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="{rule}"><EntityRef entityRef="{triggering}"/>{extra}</TriggeringEntities><EntityCondition>{condition}</EntityCondition></ByEntityCondition>"#
        )
    }

    /// One condition of an event of `actor`.
    pub(crate) fn condition(&mut self, actor: &str) -> String {
        let several = self.entities.len() > 1;
        let mut kinds = vec!["SimulationTimeCondition", "SimulationTimeCondition", "TraveledDistanceCondition", "SpeedCondition"];
        if several {
            kinds.push("RelativeDistanceCondition");
        }
        if self.rich(Area::Conditions) {
            kinds.extend([
                "ReachPositionCondition",
                "DistanceCondition",
                "DistanceCondition",
                "AccelerationCondition",
                "StandStillCondition",
                "EndOfRoadCondition",
                "OffroadCondition",
                "AngleCondition",
            ]);
            if several {
                kinds.extend([
                    "RelativeDistanceCondition",
                    "TimeHeadwayCondition",
                    "TimeToCollisionCondition",
                    "RelativeSpeedCondition",
                    "CollisionCondition",
                    "RelativeClearanceCondition",
                ]);
            }
            if !self.elements.is_empty() {
                kinds.extend(["StoryboardElementStateCondition", "StoryboardElementStateCondition"]);
            }
        }
        if self.rich(Area::Globals) {
            kinds.extend(["ParameterCondition", "VariableCondition"]);
            if !self.map.signals.is_empty() {
                kinds.extend(["TrafficSignalCondition", "TrafficSignalControllerCondition"]);
            }
        }
        let kind = self.pick(&kinds);
        self.feature(format!("condition:{kind}"));
        let edge = if self.rich(Area::Conditions) {
            self.pick(&["none", "none", "rising", "risingOrFalling", "falling"])
        } else {
            self.pick(&["none", "none", "rising", "risingOrFalling"])
        };
        if edge != "none" {
            self.feature(format!("edge:{edge}"));
        }
        let delay = self.pick(&[0.0, 0.0, 0.5, 1.3]);
        if delay > 0.0 {
            self.feature("condition-delay");
        }
        let by_value = matches!(
            kind,
            "SimulationTimeCondition"
                | "ParameterCondition"
                | "VariableCondition"
                | "StoryboardElementStateCondition"
                | "TrafficSignalCondition"
                | "TrafficSignalControllerCondition"
        );
        let body = if by_value { self.value_condition(kind) } else { self.entity_condition(kind, actor) };
        format!(r#"<Condition name="c" delay="{delay}" conditionEdge="{edge}">{body}</Condition>"#)
    }

    /// A start trigger: mostly one condition, sometimes two in a group (AND) or two groups (OR).
    pub(crate) fn trigger(&mut self, element: &str, actor: &str) -> String {
        if let Some(c) = self.forced_condition.take() {
            return format!("<{element}><ConditionGroup>{c}</ConditionGroup></{element}>");
        }
        let first = self.condition(actor);
        let combine = if self.rich(Area::Conditions) { self.pick_index(6) } else { 2 };
        let groups = match combine {
            0 => {
                self.feature("trigger:and");
                let second = self.condition(actor);
                format!("<ConditionGroup>{first}{second}</ConditionGroup>")
            }
            1 => {
                self.feature("trigger:or");
                let second = self.condition(actor);
                format!("<ConditionGroup>{first}</ConditionGroup><ConditionGroup>{second}</ConditionGroup>")
            }
            _ => format!("<ConditionGroup>{first}</ConditionGroup>"),
        };
        format!("<{element}>{groups}</{element}>")
    }
}
