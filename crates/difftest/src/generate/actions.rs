//! Private actions: speed (absolute, relative, negative targets: reversing), speed profiles,
//! longitudinal and lateral distance keeping, lane changes and lane offsets, synchronization,
//! teleports, routes, trajectories, acquiring a position, visibility, lights and trailers,
//! each with its dynamics and constraints. (Controller actions are in `controllers`.)

use super::positions::Scope;
use super::{Area, EntityKind, Gen};

impl Gen<'_> {
    fn dynamics(&mut self, element: &str, action: &str, allow_rate: bool) -> String {
        let shape = self.pick(&["linear", "cubic", "sinusoidal", "step"]);
        let dims: &[&str] = if allow_rate { &["time", "distance", "rate"] } else { &["time", "distance"] };
        let dim = self.pick(dims);
        let value = match (shape, dim) {
            ("step", _) => 0.0,
            (_, "time") => self.num(0.5, 5.0),
            (_, "distance") => self.num(10.0, 80.0),
            _ => self.num(1.0, 4.0),
        };
        self.feature(format!("dynamics:{action}/{shape}/{dim}"));
        format!(r#"<{element} dynamicsShape="{shape}" value="{value}" dynamicsDimension="{dim}"/>"#)
    }

    fn constraints(&mut self, prefix: &str) -> String {
        if !self.chance(0.6) {
            return String::new();
        }
        self.feature(format!("{prefix}/dynamic-constraints"));
        let rates = if self.chance(0.3) {
            let rates = format!(r#" maxAccelerationRate="{}" maxDecelerationRate="{}""#, self.num(1.0, 10.0), self.num(1.0, 10.0));
            if self.since(2) {
                rates
            } else {
                String::new()
            }
        } else {
            String::new()
        };
        format!(
            r#"<DynamicConstraints maxAcceleration="{}" maxDeceleration="{}" maxSpeed="{}"{rates}/>"#,
            self.num(1.0, 6.0),
            self.num(2.0, 9.0),
            self.num(10.0, 40.0)
        )
    }

    /// An absolute speed target: mostly forward, sometimes backwards (reversing).
    pub(crate) fn speed_value(&mut self) -> f64 {
        if self.rich(Area::Longitudinal) && self.chance(0.12) {
            self.feature("speed:negative");
            self.num(-8.0, -0.5)
        } else {
            self.num(0.0, 35.0)
        }
    }

    pub(crate) fn speed_action(&mut self, others: &[String]) -> String {
        let dynamics = self.dynamics("SpeedActionDynamics", "SpeedAction", true);
        let target = if others.is_empty() || self.chance(0.6) {
            format!(r#"<AbsoluteTargetSpeed value="{}"/>"#, self.speed_value())
        } else {
            let other = others[self.pick_index(others.len())].clone();
            let (kind, value) = if self.chance(0.5) { ("delta", self.num(-5.0, 5.0)) } else { ("factor", self.num(0.5, 1.5)) };
            let continuous = self.chance(0.5);
            self.feature(format!("speed-target:relative/{kind}/continuous={continuous}"));
            format!(r#"<RelativeTargetSpeed entityRef="{other}" value="{value}" speedTargetValueType="{kind}" continuous="{continuous}"/>"#)
        };
        format!("<PrivateAction><LongitudinalAction><SpeedAction>{dynamics}<SpeedActionTarget>{target}</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>")
    }

    fn speed_profile_action(&mut self) -> String {
        let mode = self.pick(&["position", "follow"]);
        self.feature(format!("speed-profile:following-mode/{mode}"));
        let constraints = self.constraints("speed-profile");
        let timed = self.chance(0.6);
        self.feature(format!("speed-profile:{}", if timed { "timed" } else { "untimed" }));
        let n = 1 + self.pick_index(4);
        let entries: String = (0..n)
            .map(|_| {
                let speed = self.num(0.0, 30.0);
                if timed {
                    format!(r#"<SpeedProfileEntry speed="{speed}" time="{}"/>"#, self.num(0.5, 5.0))
                } else {
                    format!(r#"<SpeedProfileEntry speed="{speed}"/>"#)
                }
            })
            .collect();
        format!(
            r#"<PrivateAction><LongitudinalAction><SpeedProfileAction followingMode="{mode}">{constraints}{entries}</SpeedProfileAction></LongitudinalAction></PrivateAction>"#
        )
    }

    fn long_distance_action(&mut self, others: &[String]) -> String {
        let other = others[self.pick_index(others.len())].clone();
        let gap = if self.chance(0.5) {
            self.feature("long-distance:distance");
            format!(r#"distance="{}""#, self.num(5.0, 50.0))
        } else {
            self.feature("long-distance:timeGap");
            format!(r#"timeGap="{}""#, self.num(0.5, 3.0))
        };
        let freespace = self.chance(0.5);
        let continuous = self.chance(0.6);
        let cs = self.pick(&["entity", "road", "lane"]);
        let displacement = self.pick(&["trailingReferencedEntity", "leadingReferencedEntity", "any"]);
        let (cs, displacement) = if self.since(1) {
            self.feature(format!("long-distance:{cs}/{displacement}/freespace={freespace}/continuous={continuous}"));
            (format!(r#" coordinateSystem="{cs}""#), format!(r#" displacement="{displacement}""#))
        } else {
            // 1.0 has neither: the entity system, and the distance's sign says the side
            self.feature(format!("long-distance:1.0/freespace={freespace}/continuous={continuous}"));
            (String::new(), String::new())
        };
        let constraints = self.constraints("long-distance");
        format!(
            r#"<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="{other}" {gap} freespace="{freespace}" continuous="{continuous}"{cs}{displacement}>{constraints}</LongitudinalDistanceAction></LongitudinalAction></PrivateAction>"#
        )
    }

    fn lane_change_action(&mut self, actor: &str) -> String {
        let dynamics = self.dynamics("LaneChangeActionDynamics", "LaneChangeAction", false);
        let target = if self.chance(0.5) {
            self.feature("lane-change-target:relative");
            let reference = if self.chance(0.8) { actor.to_string() } else { self.names()[self.pick_index(self.entities.len())].clone() };
            // esmini's target: the reference's lane + value, counted in its direction of travel
            // (LatLaneChangeAction::Start); a value that leads to an existing lane of that way
            let p = self.place_of(&reference);
            let lanes = super::lanes::lanes_at(&self.map.net, p.road, p.s);
            let fits = |v: i32| {
                let t = p.lane + if p.forward { v } else { -v };
                let t = if t == 0 || t.signum() != p.lane.signum() { (t - p.lane).signum() * (t.abs() + 1) } else { t };
                lanes.iter().any(|(l, f)| *l == t && *f == p.forward)
            };
            let values: Vec<i32> = [-1, 1].into_iter().filter(|v| fits(*v)).collect();
            let value = if values.is_empty() { self.pick(&[-1, 1]) } else { values[self.pick_index(values.len())] };
            format!(r#"<RelativeTargetLane entityRef="{reference}" value="{value}"/>"#)
        } else {
            self.feature("lane-change-target:absolute");
            let p = self.place_of(actor);
            let lanes: Vec<i32> = super::lanes::lanes_at(&self.map.net, p.road, p.s).into_iter().filter(|(_, f)| *f == p.forward).map(|(l, _)| l).collect();
            let lane = if lanes.is_empty() { p.lane } else { lanes[self.pick_index(lanes.len())] };
            format!(r#"<AbsoluteTargetLane value="{lane}"/>"#)
        };
        let offset = if self.rich(Area::Lateral) && self.chance(0.25) {
            self.feature("lane-change:target-lane-offset");
            format!(r#" targetLaneOffset="{}""#, self.num(-0.8, 0.8))
        } else {
            String::new()
        };
        format!("<PrivateAction><LateralAction><LaneChangeAction{offset}>{dynamics}<LaneChangeTarget>{target}</LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>")
    }

    fn lane_offset_action(&mut self, others: &[String]) -> String {
        let shape = self.pick(&["linear", "cubic", "sinusoidal", "step"]);
        self.feature(format!("dynamics:LaneOffsetAction/{shape}"));
        let acc = self.num(0.5, 3.0);
        let rich = self.rich(Area::Lateral);
        let continuous = rich && self.chance(0.3);
        let target = if rich && !others.is_empty() && self.chance(0.3) {
            self.feature("lane-offset-target:relative");
            format!(r#"<RelativeTargetLaneOffset entityRef="{}" value="{}"/>"#, others[self.pick_index(others.len())], self.num(-1.2, 1.2))
        } else {
            format!(r#"<AbsoluteTargetLaneOffset value="{}"/>"#, self.num(-1.2, 1.2))
        };
        format!(
            r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="{continuous}"><LaneOffsetActionDynamics maxLateralAcc="{acc}" dynamicsShape="{shape}"/><LaneOffsetTarget>{target}</LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#
        )
    }

    fn lat_distance_action(&mut self, others: &[String]) -> String {
        let other = others[self.pick_index(others.len())].clone();
        let freespace = self.chance(0.5);
        let continuous = self.chance(0.5);
        let cs = self.pick(&["road", "lane", "road", "entity"]);
        // esmini reads no displacement "any" (it quits); leaving the attribute out means any
        let displacement = self.pick(&["any", "leftToReferencedEntity", "rightToReferencedEntity"]);
        let (cs, displacement) = if self.since(1) {
            self.feature(format!("lat-distance:{cs}/{displacement}/freespace={freespace}/continuous={continuous}"));
            let displacement = if displacement == "any" { String::new() } else { format!(r#" displacement="{displacement}""#) };
            (format!(r#" coordinateSystem="{cs}""#), displacement)
        } else {
            // 1.0 has neither: the entity system, either side
            self.feature(format!("lat-distance:1.0/freespace={freespace}/continuous={continuous}"));
            (String::new(), String::new())
        };
        let constraints = self.constraints("lat-distance");
        format!(
            r#"<PrivateAction><LateralAction><LateralDistanceAction entityRef="{other}" distance="{}" freespace="{freespace}" continuous="{continuous}"{cs}{displacement}>{constraints}</LateralDistanceAction></LateralAction></PrivateAction>"#,
            self.num(0.5, 6.0)
        )
    }

    fn synchronize_action(&mut self, actor: &str, others: &[String]) -> String {
        let master = others[self.pick_index(others.len())].clone();
        let master_place = self.place_ahead(&master, 60.0, 250.0);
        let master_position = self.place_position(&master_place, "synchronize:", Scope::Plain, false);
        let place = self.place_ahead(actor, 40.0, 200.0);
        let position = self.place_position(&place, "synchronize:", Scope::Plain, false);
        let final_speed = match self.pick_index(3) {
            0 => String::new(),
            1 => {
                self.feature("synchronize:final-speed/absolute");
                let steady = self.steady_state();
                format!(r#"<FinalSpeed><AbsoluteSpeed value="{}">{steady}</AbsoluteSpeed></FinalSpeed>"#, self.num(2.0, 25.0))
            }
            _ => {
                let kind = self.pick(&["delta", "factor"]);
                self.feature(format!("synchronize:final-speed/relative-{kind}"));
                let value = if kind == "delta" { self.num(-3.0, 3.0) } else { self.num(0.7, 1.3) };
                let steady = self.steady_state();
                format!(r#"<FinalSpeed><RelativeSpeedToMaster value="{value}" speedTargetValueType="{kind}">{steady}</RelativeSpeedToMaster></FinalSpeed>"#)
            }
        };
        let tolerances = if self.chance(0.3) {
            let tolerances = format!(r#" targetToleranceMaster="{}" targetTolerance="{}""#, self.num(0.5, 3.0), self.num(0.5, 3.0));
            if self.since(1) {
                tolerances
            } else {
                String::new()
            }
        } else {
            String::new()
        };
        format!(
            r#"<PrivateAction><SynchronizeAction masterEntityRef="{master}"{tolerances}><TargetPositionMaster>{master_position}</TargetPositionMaster><TargetPosition>{position}</TargetPosition>{final_speed}</SynchronizeAction></PrivateAction>"#
        )
    }

    fn steady_state(&mut self) -> String {
        match self.pick_index(3) {
            0 => String::new(),
            1 => {
                self.feature("synchronize:steady-state/distance");
                format!(r#"<TargetDistanceSteadyState distance="{}"/>"#, self.num(5.0, 40.0))
            }
            _ => {
                self.feature("synchronize:steady-state/time");
                format!(r#"<TargetTimeSteadyState time="{}"/>"#, self.num(0.5, 4.0))
            }
        }
    }

    fn acquire_position_action(&mut self, actor: &str) -> String {
        let place = self.place_ahead(actor, 50.0, 300.0);
        let position = self.place_position(&place, "acquire:", Scope::Plain, false);
        format!("<PrivateAction><RoutingAction><AcquirePositionAction><Position>{position}</Position></AcquirePositionAction></RoutingAction></PrivateAction>")
    }

    fn teleport_action(&mut self, actor: &str) -> String {
        let position = self.target_position(actor, Scope::Any);
        format!("<PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction>")
    }

    fn visibility_action(&mut self) -> String {
        let (g, t, s) = (self.chance(0.5), self.chance(0.5), self.chance(0.5));
        self.feature(format!("visibility:graphics={g}"));
        format!(r#"<PrivateAction><VisibilityAction graphics="{g}" traffic="{t}" sensors="{s}"/></PrivateAction>"#)
    }

    fn light_state_action(&mut self) -> String {
        let light = self.pick(&["brakeLights", "indicatorLeft", "lowBeam", "warningLights"]);
        let mode = self.pick(&["on", "off", "flashing"]);
        format!(
            r#"<PrivateAction><AppearanceAction><LightStateAction transitionTime="{}"><LightType><VehicleLight vehicleLightType="{light}"/></LightType><LightState mode="{mode}"/></LightStateAction></AppearanceAction></PrivateAction>"#,
            self.num(0.0, 1.0)
        )
    }

    /// One private action for `actor`, and the feature name of its kind. `t_start`: about
    /// when it starts (for absolute trajectory times).
    pub(crate) fn private_action(&mut self, actor: &str, t_start: f64) -> String {
        let others: Vec<String> = self.mobile_names().into_iter().filter(|n| n != actor).collect();
        let kind = self.entity(actor).map_or(EntityKind::Car, |e| e.kind);
        let has_trailer = self.entities.iter().any(|e| e.kind == EntityKind::Trailer);
        let vehicle = matches!(kind, EntityKind::Car | EntityKind::Truck | EntityKind::Bicycle);
        let mut kinds: Vec<&str> = match kind {
            EntityKind::Pedestrian => vec!["SpeedAction", "SpeedAction", "TeleportAction", "LaneOffsetAction"],
            EntityKind::Misc | EntityKind::Trailer => vec!["TeleportAction"],
            _ => vec!["SpeedAction", "SpeedAction", "LaneChangeAction", "LaneChangeAction", "LaneOffsetAction", "TeleportAction"],
        };
        if self.rich(Area::Longitudinal) && vehicle {
            kinds.extend(["SpeedProfileAction", "SpeedProfileAction", "SpeedAction"]);
            if !others.is_empty() {
                kinds.extend(["LongitudinalDistanceAction", "LongitudinalDistanceAction", "SynchronizeAction", "SynchronizeAction"]);
            }
        }
        if self.rich(Area::Lateral) && vehicle {
            kinds.extend(["LaneChangeAction", "LaneOffsetAction"]);
            if !others.is_empty() {
                kinds.extend(["LateralDistanceAction", "LateralDistanceAction", "LateralDistanceAction"]);
            }
        }
        if self.rich(Area::Routes) && kind != EntityKind::Misc && kind != EntityKind::Trailer {
            kinds.extend(["AssignRouteAction", "AssignRouteAction", "AcquirePositionAction", "AcquirePositionAction"]);
        }
        if self.rich(Area::Trajectories) && kind != EntityKind::Misc && kind != EntityKind::Trailer {
            kinds.extend(["FollowTrajectoryAction"; 6]);
        }
        if self.rich(Area::RoadUsers) {
            kinds.extend(["VisibilityAction", "LightStateAction"]);
            if has_trailer && kind == EntityKind::Car {
                kinds.extend(["ConnectTrailerAction", "DisconnectTrailerAction"]);
            }
        }
        let k = self.pick(&kinds);
        self.feature(format!("action:{k}"));
        match k {
            "SpeedAction" => self.speed_action(&others),
            "SpeedProfileAction" => self.speed_profile_action(),
            "LongitudinalDistanceAction" => self.long_distance_action(&others),
            "LaneChangeAction" => self.lane_change_action(actor),
            "LaneOffsetAction" => self.lane_offset_action(&others),
            "LateralDistanceAction" => self.lat_distance_action(&others),
            "SynchronizeAction" => self.synchronize_action(actor, &others),
            "AssignRouteAction" => self.assign_route_action(actor),
            "FollowTrajectoryAction" => self.follow_trajectory_action(actor, t_start),
            "AcquirePositionAction" => self.acquire_position_action(actor),
            "VisibilityAction" => self.visibility_action(),
            "LightStateAction" => self.light_state_action(),
            "ConnectTrailerAction" => {
                let trailer = self.entities.iter().find(|e| e.kind == EntityKind::Trailer).map(|e| e.name.clone()).unwrap_or_default();
                format!(r#"<PrivateAction><TrailerAction><ConnectTrailerAction trailerRef="{trailer}"/></TrailerAction></PrivateAction>"#)
            }
            "DisconnectTrailerAction" => "<PrivateAction><TrailerAction><DisconnectTrailerAction/></TrailerAction></PrivateAction>".into(),
            _ => self.teleport_action(actor),
        }
    }
}
