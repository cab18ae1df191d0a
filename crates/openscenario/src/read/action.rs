//! Actions: the Action wrapper and private actions.

use super::entity::read_object_controller;
use super::global_action::read_global_action;
use super::position::{lane_id, read_position, read_position_kind};
use super::trajectory::{read_route_ref, read_trajectory_ref};
use super::Reader;
use crate::attr::Cx;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

/// An `Action` element (storyboard event action).
pub(crate) fn read_action(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Action, Error> {
    let name = cx.opt_text(e, "name")?.unwrap_or_default();
    let c = cx.choice(e, "PrivateAction, GlobalAction or UserDefinedAction")?;
    Ok(Action { name, kind: read_action_kind(r, cx, c)?, origin: cx.loc(c.pos) })
}

/// A PrivateAction / GlobalAction / UserDefinedAction element.
pub(crate) fn read_action_kind(r: &mut Reader, cx: &Cx, c: &Elem) -> Result<ActionKind, Error> {
    match c.name.as_str() {
        "PrivateAction" => read_private_action(r, cx, c),
        "GlobalAction" => read_global_action(r, cx, c),
        "UserDefinedAction" => {
            let cc = c.child("CustomCommandAction");
            if let Some(cc) = cc {
                r.warn(cx.loc(cc.pos), "CustomCommandAction: its text content is not interpreted (only its type is kept)");
            }
            Ok(ActionKind::CustomCommand { command_type: cc.map(|cc| cx.opt_text(cc, "type")).transpose()?.flatten().unwrap_or_default() })
        }
        _ => Err(cx.unexpected(c, "Action", "PrivateAction, GlobalAction, UserDefinedAction")),
    }
}

fn unsupported(r: &mut Reader, cx: &Cx, e: &Elem, parent: &str) -> ActionKind {
    r.unsupported(cx, e, parent);
    ActionKind::Unsupported { element: e.name.clone() }
}

pub(crate) fn read_private_action(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<ActionKind, Error> {
    let e = cx.choice(wrapper, "a private action")?;
    let a = match e.name.as_str() {
        "LongitudinalAction" => {
            let c = cx.choice(e, "SpeedAction, LongitudinalDistanceAction or SpeedProfileAction")?;
            match c.name.as_str() {
                "SpeedAction" => speed_action(cx, c)?,
                "LongitudinalDistanceAction" => PrivateAction::LongitudinalDistance {
                    entity: cx.reference(c, "entityRef")?,
                    distance: cx.opt_f64(c, "distance")?,
                    time_gap: cx.opt_f64(c, "timeGap")?,
                    freespace: cx.bool_or(c, "freespace", false)?,
                    continuous: cx.bool_or(c, "continuous", false)?,
                    coordinate_system: cx.opt_enum(c, "coordinateSystem")?,
                    displacement: cx.opt_enum(c, "displacement")?,
                    constraints: constraints(cx, c)?,
                },
                "SpeedProfileAction" => PrivateAction::SpeedProfile {
                    entity: cx.opt_reference(c, "entityRef")?,
                    following_mode: cx.opt_enum(c, "followingMode")?.unwrap_or(FollowingMode::Follow),
                    constraints: constraints(cx, c)?,
                    entries: c
                        .children_named("SpeedProfileEntry")
                        .map(|s| Ok(SpeedProfileEntry { speed: cx.f64(s, "speed")?, time: cx.opt_f64(s, "time")? }))
                        .collect::<Result<_, Error>>()?,
                },
                _ => return Ok(unsupported(r, cx, c, "LongitudinalAction")),
            }
        }
        "LateralAction" => {
            let c = cx.choice(e, "LaneChangeAction, LaneOffsetAction or LateralDistanceAction")?;
            match c.name.as_str() {
                "LaneChangeAction" => lane_change(cx, c)?,
                "LaneOffsetAction" => {
                    let d = cx.child(c, "LaneOffsetActionDynamics")?;
                    let t = cx.choice(cx.child(c, "LaneOffsetTarget")?, "RelativeTargetLaneOffset or AbsoluteTargetLaneOffset")?;
                    let target = match t.name.as_str() {
                        "RelativeTargetLaneOffset" => LaneOffsetTarget::Relative { entity: cx.reference(t, "entityRef")?, value: cx.f64(t, "value")? },
                        "AbsoluteTargetLaneOffset" => LaneOffsetTarget::Absolute { value: cx.f64(t, "value")? },
                        _ => return Err(cx.unexpected(t, "LaneOffsetTarget", "RelativeTargetLaneOffset, AbsoluteTargetLaneOffset")),
                    };
                    PrivateAction::LaneOffset {
                        continuous: cx.bool_or(c, "continuous", false)?,
                        shape: cx.enum_(d, "dynamicsShape")?,
                        max_lateral_acc: cx.opt_f64(d, "maxLateralAcc")?,
                        target,
                    }
                }
                "LateralDistanceAction" => PrivateAction::LateralDistance {
                    entity: cx.reference(c, "entityRef")?,
                    distance: cx.opt_f64(c, "distance")?,
                    freespace: cx.bool_or(c, "freespace", false)?,
                    continuous: cx.bool_or(c, "continuous", false)?,
                    coordinate_system: cx.opt_enum(c, "coordinateSystem")?,
                    displacement: cx.opt_enum(c, "displacement")?,
                    constraints: constraints(cx, c)?,
                },
                _ => return Ok(unsupported(r, cx, c, "LateralAction")),
            }
        }
        "VisibilityAction" => PrivateAction::Visibility {
            graphics: cx.bool_or(e, "graphics", true)?,
            sensors: cx.bool_or(e, "sensors", true)?,
            traffic: cx.bool_or(e, "traffic", true)?,
            sensor_refs: match e.child("SensorReferenceSet") {
                Some(s) => s.children_named("SensorReference").map(|x| cx.text(x, "name")).collect::<Result<_, _>>()?,
                None => Vec::new(),
            },
        },
        "SynchronizeAction" => synchronize(r, cx, e)?,
        "ActivateControllerAction" => activate_controller(cx, e)?,
        "ControllerAction" => {
            if e.children().len() > 1 {
                for extra in e.children().iter().skip(1) {
                    extra.announce();
                    r.warn(cx.loc(extra.pos), format!("<{}> after the first ControllerAction child is ignored", extra.name));
                }
            }
            let c = cx.choice(e, "AssignControllerAction, OverrideControllerValueAction or ActivateControllerAction")?;
            match c.name.as_str() {
                "ActivateControllerAction" => activate_controller(cx, c)?,
                "AssignControllerAction" => PrivateAction::AssignController {
                    controller: read_object_controller(r, cx, c)?,
                    object_controller_name: match c.child("ObjectController") {
                        Some(w) => cx.opt_text(w, "name")?,
                        None => None,
                    },
                    activate_lateral: cx.opt_bool(c, "activateLateral")?,
                    activate_longitudinal: cx.opt_bool(c, "activateLongitudinal")?,
                    activate_lighting: cx.opt_bool(c, "activateLighting")?,
                    activate_animation: cx.opt_bool(c, "activateAnimation")?,
                },
                "OverrideControllerValueAction" => PrivateAction::OverrideControllerValue(
                    c.children()
                        .iter()
                        .map(|v| {
                            let value = match cx.opt_f64(v, "value")? {
                                Some(x) => Some(x),
                                None => match cx.opt_f64(v, "number")? {
                                    Some(x) => Some(x),
                                    // 1.2: BrakePercent/BrakeForce `value`, ManualGear `number`,
                                    // AutomaticGear `gear` (a letter: no number to keep)
                                    None => match v.first_child() {
                                        Some(g) if g.name == "ManualGear" => cx.opt_f64(g, "number")?,
                                        Some(g) if g.name == "AutomaticGear" => cx.opt_text(g, "gear")?.and(None),
                                        Some(g) => cx.opt_f64(g, "value")?,
                                        None => None,
                                    },
                                },
                            };
                            Ok(OverrideValue { kind: v.name.clone(), active: cx.bool_or(v, "active", false)?, value, max_rate: cx.opt_f64(v, "maxRate")? })
                        })
                        .collect::<Result<_, Error>>()?,
                ),
                _ => return Ok(unsupported(r, cx, c, "ControllerAction")),
            }
        }
        "TeleportAction" => PrivateAction::Teleport(read_position(r, cx, cx.child(e, "Position")?)?),
        "RoutingAction" => {
            let c = cx.choice(e, "AssignRouteAction, FollowTrajectoryAction, AcquirePositionAction or RandomRouteAction")?;
            match c.name.as_str() {
                "AssignRouteAction" => {
                    // 1.3 wraps the route in RouteRef; earlier versions hold Route / CatalogReference directly.
                    let route = match c.child("RouteRef") {
                        Some(rr) => read_route_ref(r, cx, rr)?,
                        None => read_route_ref(r, cx, c)?,
                    };
                    PrivateAction::AssignRoute(route)
                }
                "FollowTrajectoryAction" => follow_trajectory(r, cx, c)?,
                "AcquirePositionAction" => PrivateAction::AcquirePosition(read_position(r, cx, cx.child(c, "Position")?)?),
                "RandomRouteAction" => PrivateAction::RandomRoute,
                _ => return Ok(unsupported(r, cx, c, "RoutingAction")),
            }
        }
        "AppearanceAction" => {
            let c = cx.choice(e, "LightStateAction or AnimationAction")?;
            match c.name.as_str() {
                "LightStateAction" => light_state(cx, c)?,
                "AnimationAction" => {
                    r.warn(cx.loc(c.pos), "AnimationAction: only the animation type, loop, duration and state are kept");
                    let ty = c.child("AnimationType").and_then(|t| t.first_child());
                    PrivateAction::Animation {
                        animation_type: ty.map(|t| t.name.clone()).unwrap_or_default(),
                        loop_: cx.opt_bool(c, "loop")?,
                        duration: cx.opt_f64(c, "animationDuration")?,
                        state: c.child("AnimationState").map(|s| cx.f64(s, "state")).transpose()?,
                    }
                }
                _ => return Ok(unsupported(r, cx, c, "AppearanceAction")),
            }
        }
        "TrailerAction" => {
            let c = cx.choice(e, "ConnectTrailerAction or DisconnectTrailerAction")?;
            match c.name.as_str() {
                "ConnectTrailerAction" => PrivateAction::ConnectTrailer { trailer: cx.reference(c, "trailerRef")? },
                "DisconnectTrailerAction" => PrivateAction::DisconnectTrailer,
                _ => return Ok(unsupported(r, cx, c, "TrailerAction")),
            }
        }
        _ => return Ok(unsupported(r, cx, e, "PrivateAction")),
    };
    Ok(ActionKind::Private(a))
}

pub(crate) fn transition_dynamics(cx: &Cx, e: &Elem) -> Result<TransitionDynamics, Error> {
    Ok(TransitionDynamics {
        shape: cx.enum_(e, "dynamicsShape")?,
        dimension: cx.enum_(e, "dynamicsDimension")?,
        value: cx.f64(e, "value")?,
        following_mode: cx.opt_enum(e, "followingMode")?,
    })
}

fn constraints(cx: &Cx, e: &Elem) -> Result<Option<DynamicConstraints>, Error> {
    e.child("DynamicConstraints")
        .map(|d| {
            Ok(DynamicConstraints {
                max_acceleration: cx.opt_f64(d, "maxAcceleration")?,
                max_deceleration: cx.opt_f64(d, "maxDeceleration")?,
                max_speed: cx.opt_f64(d, "maxSpeed")?,
                max_acceleration_rate: cx.opt_f64(d, "maxAccelerationRate")?,
                max_deceleration_rate: cx.opt_f64(d, "maxDecelerationRate")?,
            })
        })
        .transpose()
}

fn speed_action(cx: &Cx, c: &Elem) -> Result<PrivateAction, Error> {
    let dynamics = transition_dynamics(cx, cx.child(c, "SpeedActionDynamics")?)?;
    let t = cx.choice(cx.child(c, "SpeedActionTarget")?, "RelativeTargetSpeed or AbsoluteTargetSpeed")?;
    let target = match t.name.as_str() {
        "AbsoluteTargetSpeed" => SpeedTarget::Absolute { value: cx.f64(t, "value")? },
        "RelativeTargetSpeed" => SpeedTarget::Relative {
            entity: cx.reference(t, "entityRef")?,
            value: cx.f64(t, "value")?,
            value_type: cx.enum_(t, "speedTargetValueType")?,
            continuous: cx.bool_or(t, "continuous", false)?,
        },
        _ => return Err(cx.unexpected(t, "SpeedActionTarget", "RelativeTargetSpeed, AbsoluteTargetSpeed")),
    };
    Ok(PrivateAction::Speed { dynamics, target })
}

fn lane_change(cx: &Cx, c: &Elem) -> Result<PrivateAction, Error> {
    let dynamics = transition_dynamics(cx, cx.child(c, "LaneChangeActionDynamics")?)?;
    let t = cx.choice(cx.child(c, "LaneChangeTarget")?, "RelativeTargetLane or AbsoluteTargetLane")?;
    let target = match t.name.as_str() {
        "RelativeTargetLane" => LaneChangeTarget::Relative { entity: cx.reference(t, "entityRef")?, value: lane_id(cx, t, "value")? },
        "AbsoluteTargetLane" => LaneChangeTarget::Absolute { lane_id: lane_id(cx, t, "value")? },
        _ => return Err(cx.unexpected(t, "LaneChangeTarget", "RelativeTargetLane, AbsoluteTargetLane")),
    };
    Ok(PrivateAction::LaneChange { dynamics, target, target_lane_offset: cx.opt_f64(c, "targetLaneOffset")? })
}

fn activate_controller(cx: &Cx, e: &Elem) -> Result<PrivateAction, Error> {
    Ok(PrivateAction::ActivateController {
        lateral: cx.opt_bool(e, "lateral")?,
        longitudinal: cx.opt_bool(e, "longitudinal")?,
        lighting: cx.opt_bool(e, "lighting")?,
        animation: cx.opt_bool(e, "animation")?,
        controller_ref: cx.opt_reference(e, "controllerRef")?,
        object_controller_ref: cx.opt_reference(e, "objectControllerRef")?,
    })
}

fn steady_state(cx: &Cx, e: &Elem) -> Result<Option<SteadyState>, Error> {
    // 1.1+ wraps it in <SteadyState>; esmini's earlier extension puts it directly inside.
    let direct = e.children().iter().find(|c| c.name == "TargetDistanceSteadyState" || c.name == "TargetTimeSteadyState");
    let Some(s) = e.child("SteadyState").and_then(|s| s.first_child()).or(direct) else { return Ok(None) };
    Ok(match s.name.as_str() {
        "TargetDistanceSteadyState" => Some(SteadyState::Distance(cx.f64(s, "distance")?)),
        "TargetTimeSteadyState" => Some(SteadyState::Time(cx.f64(s, "time")?)),
        _ => return Err(cx.unexpected(s, "SteadyState", "TargetDistanceSteadyState, TargetTimeSteadyState")),
    })
}

fn synchronize(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<PrivateAction, Error> {
    let final_speed = match e.child("FinalSpeed").and_then(|f| f.first_child()) {
        None => None,
        Some(f) if f.name == "AbsoluteSpeed" => Some(FinalSpeed::Absolute { value: cx.f64(f, "value")?, steady_state: steady_state(cx, f)? }),
        Some(f) if f.name == "RelativeSpeedToMaster" => Some(FinalSpeed::RelativeToMaster {
            value: cx.f64(f, "value")?,
            value_type: cx.enum_(f, "speedTargetValueType")?,
            steady_state: steady_state(cx, f)?,
        }),
        Some(f) => return Err(cx.unexpected(f, "FinalSpeed", "AbsoluteSpeed, RelativeSpeedToMaster")),
    };
    // TargetPositionMaster / TargetPosition are of type Position: their child is the position.
    let tpm = cx.child(e, "TargetPositionMaster")?;
    let tp = cx.child(e, "TargetPosition")?;
    Ok(PrivateAction::Synchronize {
        master: cx.reference(e, "masterEntityRef")?,
        target_position_master: read_position_kind(r, cx, cx.choice(tpm, "a position")?)?,
        target_position: read_position_kind(r, cx, cx.choice(tp, "a position")?)?,
        final_speed,
        target_tolerance_master: cx.opt_f64(e, "targetToleranceMaster")?,
        target_tolerance: cx.opt_f64(e, "targetTolerance")?,
    })
}

fn follow_trajectory(r: &mut Reader, cx: &Cx, c: &Elem) -> Result<PrivateAction, Error> {
    let trajectory = match c.child("TrajectoryRef") {
        Some(tr) => read_trajectory_ref(r, cx, tr)?,
        // 1.0 form: Trajectory or CatalogReference directly inside the action.
        None => {
            let inner = c.children().iter().find(|x| x.name == "Trajectory" || x.name == "CatalogReference").ok_or_else(|| {
                cx.err(crate::error::ErrorKind::Structure, c.pos, "FollowTrajectoryAction needs a TrajectoryRef, Trajectory or CatalogReference")
            })?;
            match inner.name.as_str() {
                "Trajectory" => super::trajectory::read_trajectory(r, cx, inner, &[])?,
                _ => r.catalog_entry(cx, inner, &[crate::catalog::CatalogKind::Trajectory], super::trajectory::read_trajectory)?,
            }
        }
    };
    let time_reference = match c.child("TimeReference").and_then(|t| t.first_child()) {
        Some(t) if t.name == "Timing" => {
            TimeReference::Timing { domain: cx.enum_(t, "domainAbsoluteRelative")?, scale: cx.f64_or(t, "scale", 1.0)?, offset: cx.f64_or(t, "offset", 0.0)? }
        }
        _ => TimeReference::None,
    };
    let following_mode = match c.child("TrajectoryFollowingMode") {
        Some(m) => cx.enum_(m, "followingMode")?,
        None => FollowingMode::Position,
    };
    Ok(PrivateAction::FollowTrajectory { trajectory, time_reference, following_mode, initial_distance_offset: cx.opt_f64(c, "initialDistanceOffset")? })
}

fn light_state(cx: &Cx, c: &Elem) -> Result<PrivateAction, Error> {
    let lt = cx.choice(cx.child(c, "LightType")?, "VehicleLight or UserDefinedLight")?;
    let light_type = match lt.name.as_str() {
        "VehicleLight" => LightType::Vehicle(cx.text(lt, "vehicleLightType")?),
        "UserDefinedLight" => LightType::UserDefined(cx.text(lt, "userDefinedLightType")?),
        _ => return Err(cx.unexpected(lt, "LightType", "VehicleLight, UserDefinedLight")),
    };
    let s = cx.child(c, "LightState")?;
    let color = s.child("Color");
    let rgb = match color.and_then(|col| col.child("ColorRgb")) {
        Some(rgb) => Some((cx.f64(rgb, "red")?, cx.f64(rgb, "green")?, cx.f64(rgb, "blue")?)),
        None => None,
    };
    Ok(PrivateAction::LightState {
        light_type,
        state: LightState {
            mode: cx.enum_(s, "mode")?,
            luminous_intensity: cx.opt_f64(s, "luminousIntensity")?,
            flashing_on_duration: cx.opt_f64(s, "flashingOnDuration")?,
            flashing_off_duration: cx.opt_f64(s, "flashingOffDuration")?,
            color_type: color.map(|col| cx.opt_text(col, "colorType")).transpose()?.flatten(),
            rgb,
        },
        transition_time: cx.opt_f64(c, "transitionTime")?,
    })
}
