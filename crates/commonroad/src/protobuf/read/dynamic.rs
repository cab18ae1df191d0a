//! The dynamic file: the traffic-light cycles (into the map's lights), static obstacles and
//! dynamic obstacles with trajectories. Set-based predictions and phantom obstacles are not
//! part of the model: warnings.

use super::super::messages::{commonroad_common as pb, commonroad_dynamic as dy};
use super::values::{centre, enum_from, occupancies, point, shape, time_step, value};
use super::Bad;
use crate::geometry::Point;
use crate::ids::ObstacleId;
use crate::obstacle::{DynamicObstacle, DynamicObstacleType, State, StaticObstacle, StaticObstacleType};
use crate::scenario::LaneletNetwork;
use crate::traffic::{CycleElement, TrafficLightColor};

/// Puts each cycle of the dynamic file into its light of the map.
pub(super) fn apply_cycles(network: &mut LaneletNetwork, d: &dy::CommonRoadDynamic, warnings: &mut Vec<String>) -> Result<(), Bad> {
    for c in &d.traffic_light_cycle {
        let ctx = || format!("trafficLight {} cycle", c.traffic_light_id);
        let Some(light) = network.traffic_lights.iter_mut().find(|l| l.id.get() == u64::from(c.traffic_light_id)) else {
            warnings.push(format!("{}: the map has no such light; left out", ctx()));
            continue;
        };
        let cycle = c
            .cycle_elements
            .iter()
            .map(|e| {
                let name = pb::traffic_light_state_enum::TrafficLightState::try_from(e.color).ok().map(|v| v.as_str_name());
                let color = enum_from("traffic light color", name, TrafficLightColor::ALL, TrafficLightColor::as_str, &ctx)?;
                let duration = std::num::NonZeroU64::new(u64::from(e.duration)).ok_or_else(|| Bad::new(ctx(), "a phase of duration 0"))?;
                Ok(CycleElement { duration, color })
            })
            .collect::<Result<Vec<_>, Bad>>()?;
        if !cycle.is_empty() {
            light.cycle = cycle;
        }
        light.time_offset = u64::from(c.time_offset.unwrap_or(0));
        // 2020a's default is active: only an inactive light says so
        light.active = (c.active == Some(false)).then_some(false);
    }
    Ok(())
}

fn obstacle_type(raw: i32, ctx: &dyn Fn() -> String) -> Result<&'static str, Bad> {
    dy::obstacle_type_enum::ObstacleType::try_from(raw)
        .ok()
        .map(|v| v.as_str_name())
        .ok_or_else(|| Bad::new(ctx(), format!("obstacle type {raw} is not a 2024 value")))
}

/// A state's position: a point, or the centre of a shape (`uncertain` is set then).
fn position(s: &pb::State, uncertain: &mut bool, ctx: &dyn Fn() -> String) -> Result<Point, Bad> {
    match &s.position {
        Some(pb::state::Position::Point(p)) => point(p, ctx),
        Some(pb::state::Position::Shape(o)) => {
            *uncertain = true;
            let shapes = occupancies(o, ctx)?;
            shapes.first().map(centre).ok_or_else(|| Bad::new(ctx(), "an empty position shape"))
        }
        None => Err(Bad::new(ctx(), "a state without position")),
    }
}

fn state(s: &pb::State, uncertain: &mut bool, ctx: &dyn Fn() -> String) -> Result<State, Bad> {
    let p = position(s, uncertain, ctx)?;
    Ok(State {
        time_step: time_step(&s.time_step, uncertain, ctx)?,
        x: p.x,
        y: p.y,
        orientation: value(&s.orientation, uncertain, ctx)?.unwrap_or(0.0),
        velocity: value(&s.velocity, uncertain, ctx)?.unwrap_or(0.0),
        acceleration: value(&s.acceleration, uncertain, ctx)?.unwrap_or(0.0),
        yaw_rate: value(&s.yaw_rate, uncertain, ctx)?.unwrap_or(0.0),
    })
}

fn note_uncertain(uncertain: bool, warnings: &mut Vec<String>, ctx: &dyn Fn() -> String) {
    if uncertain {
        warnings.push(format!("{}: uncertain state values (intervals, position shapes) are read as their midpoints and centres", ctx()));
    }
}

pub(super) fn static_obstacles(d: &dy::CommonRoadDynamic, warnings: &mut Vec<String>) -> Result<Vec<StaticObstacle>, Bad> {
    d.static_obstacles
        .iter()
        .map(|o| {
            let ctx = || format!("staticObstacle {}", o.static_obstacle_id);
            let kind =
                enum_from("static obstacle type", Some(obstacle_type(o.obstacle_type, &ctx)?), StaticObstacleType::ALL, StaticObstacleType::as_str, &ctx)?;
            let mut uncertain = false;
            let s = state(&o.initial_state, &mut uncertain, &ctx)?;
            note_uncertain(uncertain, warnings, &ctx);
            Ok(StaticObstacle {
                id: ObstacleId::new(u64::from(o.static_obstacle_id)).ok_or_else(|| Bad::new(ctx(), "id 0"))?,
                obstacle_type: kind,
                shape: shape(&o.shape, warnings, &ctx)?,
                x: s.x,
                y: s.y,
                orientation: s.orientation,
            })
        })
        .collect()
}

pub(super) fn dynamic_obstacles(d: &dy::CommonRoadDynamic, warnings: &mut Vec<String>) -> Result<Vec<DynamicObstacle>, Bad> {
    if !d.phantom_obstacles.is_empty() {
        warnings.push(format!("{} phantom obstacle(s) (set-based occupancies) are not part of the model; left out", d.phantom_obstacles.len()));
    }
    let mut out = Vec::with_capacity(d.dynamic_obstacles.len());
    for o in &d.dynamic_obstacles {
        let ctx = || format!("dynamicObstacle {}", o.dynamic_obstacle_id);
        let trajectory = match &o.prediction {
            Some(dy::dynamic_obstacle::Prediction::TrajectoryPrediction(p)) => &p.trajectory.states,
            Some(dy::dynamic_obstacle::Prediction::SetBasedPrediction(_)) => {
                warnings.push(format!("{}: a set-based prediction (occupancies) is not part of the model; obstacle left out", ctx()));
                continue;
            }
            None => {
                warnings.push(format!("{}: no prediction; obstacle left out", ctx()));
                continue;
            }
        };
        let kind =
            enum_from("dynamic obstacle type", Some(obstacle_type(o.obstacle_type, &ctx)?), DynamicObstacleType::ALL, DynamicObstacleType::as_str, &ctx)?;
        let mut uncertain = false;
        let initial_state = state(&o.initial_state, &mut uncertain, &ctx)?;
        let trajectory = trajectory.iter().map(|s| state(s, &mut uncertain, &ctx)).collect::<Result<Vec<_>, _>>()?;
        note_uncertain(uncertain, warnings, &ctx);
        out.push(DynamicObstacle {
            id: ObstacleId::new(u64::from(o.dynamic_obstacle_id)).ok_or_else(|| Bad::new(ctx(), "id 0"))?,
            obstacle_type: kind,
            shape: shape(&o.shape, warnings, &ctx)?,
            initial_state,
            trajectory,
        });
    }
    Ok(out)
}
