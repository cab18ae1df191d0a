//! The dynamic file (`CommonRoadDynamic`): the static and dynamic obstacles with their states
//! and trajectories, and the traffic-light cycles (in 2024 a light's cycle is dynamic; its
//! position and colours are in the map). Environment obstacles are in the map (commonroad-io
//! reads them from there); static signs too, so no `TrafficSignValue` is written (commonroad-io
//! would decode one with the ZAM table whatever the country, and let it replace the map's).
//!
//! States carry the fields the 2020a readers give them, so both formats read back alike: an
//! initial state has every field of commonroad-io's `InitialState` (the 2020a readers fill the
//! missing ones with 0, and the 2024 reader stops filling at the first missing one); trajectory
//! states have exactly the 2020a file's fields.

use super::error::{finite, fits_u32};
use super::messages::{commonroad_common as pb, commonroad_dynamic as dynamic};
use super::values::{enum_value, exact, shape, state, time_exact, StateFields};
use crate::obstacle::{DynamicObstacle, State, StaticObstacle};
use crate::scenario::Scenario;
use crate::traffic::TrafficLight;
use crate::Error;

pub(super) fn dynamic_message(scenario: &Scenario, meta: pb::ScenarioMetaInformation) -> Result<dynamic::CommonRoadDynamic, Error> {
    Ok(dynamic::CommonRoadDynamic {
        dynamic_meta_information: meta,
        environment: dynamic::Environment::default(),
        traffic_light_cycle: scenario.network.traffic_lights.iter().map(light_cycle).collect::<Result<_, _>>()?,
        traffic_sign_value: Vec::new(),
        static_obstacles: scenario.static_obstacles.iter().map(static_obstacle).collect::<Result<_, _>>()?,
        dynamic_obstacles: scenario.dynamic_obstacles.iter().map(dynamic_obstacle).collect::<Result<_, _>>()?,
        phantom_obstacles: Vec::new(),
    })
}

fn light_cycle(t: &TrafficLight) -> Result<dynamic::TrafficLightCycle, Error> {
    use pb::traffic_light_state_enum::TrafficLightState;
    let ctx = || format!("trafficLight {} cycle", t.id);
    Ok(dynamic::TrafficLightCycle {
        traffic_light_id: fits_u32(ctx, t.id.get())?,
        cycle_elements: t
            .cycle
            .iter()
            .map(|c| {
                Ok(dynamic::CycleElement {
                    duration: fits_u32(ctx, c.duration.get())?,
                    color: enum_value("traffic light color", c.color.as_str(), TrafficLightState::from_str_name)?,
                })
            })
            .collect::<Result<_, Error>>()?,
        time_offset: Some(fits_u32(ctx, t.time_offset)?),
        // 2024 keeps "active" on the cycle; the light reads it from there (2020a: default true)
        active: Some(t.active.unwrap_or(true)),
    })
}

fn obstacle_type(xsd: &str) -> Result<i32, Error> {
    enum_value("obstacle type", xsd, dynamic::obstacle_type_enum::ObstacleType::from_str_name)
}

fn position(x: f64, y: f64, ctx: &dyn Fn() -> String) -> Result<Option<pb::state::Position>, Error> {
    let p = pb::Point { x: finite(|| format!("{} x", ctx()), x)?, y: finite(|| format!("{} y", ctx()), y)?, z: None };
    Ok(Some(pb::state::Position::Point(p)))
}

fn static_obstacle(o: &StaticObstacle) -> Result<dynamic::StaticObstacle, Error> {
    let ctx = || format!("staticObstacle {}", o.id);
    let zero = |what: &'static str| exact(0.0, move || what.to_string());
    let initial = StateFields {
        position: position(o.x, o.y, &ctx)?,
        orientation: Some(exact(o.orientation, || format!("{} orientation", ctx()))?),
        velocity: Some(zero("velocity")?),
        yaw_rate: Some(zero("yaw rate")?),
        slip_angle: Some(zero("slip angle")?),
        acceleration: Some(zero("acceleration")?),
        time_step: time_exact(0, ctx)?,
    };
    Ok(dynamic::StaticObstacle {
        static_obstacle_id: fits_u32(ctx, o.id.get())?,
        obstacle_type: obstacle_type(o.obstacle_type.as_str())?,
        shape: shape(&o.shape, &ctx)?,
        initial_state: state(initial),
        initial_signal_state: None,
        signal_series: Vec::new(),
    })
}

/// A trajectory state: the fields the 2020a file has for it.
fn trajectory_state(s: &State, ctx: &dyn Fn() -> String) -> Result<pb::State, Error> {
    let at = || format!("{} time step {}", ctx(), s.time_step);
    Ok(state(StateFields {
        position: position(s.x, s.y, &at)?,
        orientation: Some(exact(s.orientation, || format!("{} orientation", at()))?),
        velocity: Some(exact(s.velocity, || format!("{} velocity", at()))?),
        yaw_rate: Some(exact(s.yaw_rate, || format!("{} yaw rate", at()))?),
        slip_angle: None,
        acceleration: Some(exact(s.acceleration, || format!("{} acceleration", at()))?),
        time_step: time_exact(s.time_step, at)?,
    }))
}

fn dynamic_obstacle(o: &DynamicObstacle) -> Result<dynamic::DynamicObstacle, Error> {
    let ctx = || format!("dynamicObstacle {}", o.id);
    let mut initial = trajectory_state(&o.initial_state, &ctx)?;
    // an initial state has all of InitialState's fields (2020a readers: slip angle 0)
    initial.slip_angle = Some(exact(0.0, || "slip angle".to_string())?);
    let obstacle_shape = shape(&o.shape, &ctx)?;
    let states = o.trajectory.iter().map(|s| trajectory_state(s, &ctx)).collect::<Result<Vec<_>, _>>()?;
    // commonroad-io's 2020a reader takes the first state's time step as the trajectory's
    let initial_time_step = o.trajectory.first().map_or(o.initial_state.time_step + 1, |s| s.time_step);
    let prediction = dynamic::TrajectoryPrediction {
        trajectory: dynamic::Trajectory { initial_time_step: fits_u32(ctx, initial_time_step)?, states },
        shape: obstacle_shape.clone(),
    };
    Ok(dynamic::DynamicObstacle {
        dynamic_obstacle_id: fits_u32(ctx, o.id.get())?,
        obstacle_type: obstacle_type(o.obstacle_type.as_str())?,
        shape: obstacle_shape,
        initial_state: initial,
        prediction: Some(dynamic::dynamic_obstacle::Prediction::TrajectoryPrediction(prediction)),
        initial_signal_state: None,
        signal_series: Vec::new(),
        initial_meta_information_state: None,
        meta_information_series: Vec::new(),
        external_dataset_id: None,
    })
}
