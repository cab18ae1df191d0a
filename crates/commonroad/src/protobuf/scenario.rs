//! The scenario file (`CommonRoadScenario`): meta information, the planning problems with
//! their goals, the id of the map (`map_id`, the map file's name without `.pb`) and of the
//! dynamic file (`dynamic_id`, the benchmark id, as commonroad-io's writer sets it). In 2024 the
//! scenario tags travel with each planning problem.

use super::error::fits_u32;
use super::messages::{commonroad_common as pb, commonroad_scenario as sc};
use super::values::{
    enum_value, exact, interval, occupancy_of, placed_circle, placed_rectangle, point, polygon_occupancy, state, time_exact, time_interval, StateFields,
};
use crate::geometry::Point;
use crate::planning::{GoalPosition, GoalState, PlanningProblem, PlanningProblemSet};
use crate::scenario::{LaneletNetwork, Scenario};
use crate::Error;

pub(super) fn scenario_message(
    scenario: &Scenario,
    problems: &PlanningProblemSet,
    meta: pb::ScenarioMetaInformation,
    map_id: &str,
) -> Result<sc::CommonRoadScenario, Error> {
    if problems.problems.is_empty() {
        return Err(Error::NoPlanningProblem { hint: "" });
    }
    let tags = sc::ScenarioTags {
        tags: scenario.tags.iter().map(|t| enum_value("scenario tag", t.as_str(), sc::tag_enum::Tag::from_str_name)).collect::<Result<_, _>>()?,
    };
    Ok(sc::CommonRoadScenario {
        scenario_meta_information: meta,
        map_id: map_id.to_string(),
        dynamic_id: scenario.header.benchmark_id.to_string(),
        planning_problems: problems.problems.iter().map(|p| planning_problem(p, &scenario.network, &tags)).collect::<Result<_, _>>()?,
        cooperative_planning_problems: Vec::new(),
    })
}

fn planning_problem(p: &PlanningProblem, net: &LaneletNetwork, tags: &sc::ScenarioTags) -> Result<sc::PlanningProblem, Error> {
    let ctx = || format!("planningProblem {}", p.id);
    let s = &p.initial_state;
    let field = |what: &'static str, v: f64| exact(v, move || format!("planningProblem {} initial {what}", p.id));
    let initial = StateFields {
        position: Some(pb::state::Position::Point(point(&Point::new(s.x, s.y), &ctx)?)),
        orientation: Some(field("orientation", s.orientation)?),
        velocity: Some(field("velocity", s.velocity)?),
        yaw_rate: Some(field("yaw rate", s.yaw_rate)?),
        slip_angle: Some(field("slip angle", s.slip_angle)?),
        // every InitialState field (the 2020a readers fill a missing acceleration with 0)
        acceleration: Some(field("acceleration", s.acceleration.unwrap_or(0.0))?),
        time_step: time_exact(0, ctx)?,
    };
    Ok(sc::PlanningProblem {
        planning_problem_id: fits_u32(ctx, p.id.get())?,
        initial_state: state(initial),
        goal_states: p.goal_states.iter().map(|g| goal_state(g, net, &ctx)).collect::<Result<_, _>>()?,
        ego_id: None,
        scenario_tags: tags.clone(),
    })
}

/// A lanelet's outline as the readers make it: the right bound, then the left bound backwards.
fn lanelet_outline(net: &LaneletNetwork, id: u64, ctx: &dyn Fn() -> String) -> Result<pb::Occupancy, Error> {
    let Some(l) = net.lanelets.iter().find(|l| l.id.get() == id) else {
        return Err(Error::UnknownLanelet { context: ctx(), id });
    };
    let points = l.bounds.right().iter().chain(l.bounds.left().iter().rev()).map(|q| point(q, ctx)).collect::<Result<_, _>>()?;
    Ok(polygon_occupancy(points))
}

fn goal_state(g: &GoalState, net: &LaneletNetwork, ctx: &dyn Fn() -> String) -> Result<sc::GoalState, Error> {
    let mut goal_lanelets = Vec::new();
    let position = match &g.position {
        None => None,
        Some(pos) => {
            let shapes = match pos {
                GoalPosition::Rectangles(rs) => rs.iter().map(|r| placed_rectangle(r, ctx)).collect::<Result<Vec<_>, _>>()?,
                GoalPosition::Circles(cs) => cs.iter().map(|c| placed_circle(c, ctx)).collect::<Result<Vec<_>, _>>()?,
                GoalPosition::Polygons(ps) => ps
                    .iter()
                    .map(|p| Ok(polygon_occupancy(p.points().iter().map(|q| point(q, ctx)).collect::<Result<_, _>>()?)))
                    .collect::<Result<Vec<_>, Error>>()?,
                GoalPosition::Lanelets(ls) => {
                    goal_lanelets = ls.iter().map(|l| fits_u32(ctx, l.get())).collect::<Result<_, _>>()?;
                    // the readers make a group of the lanelets' outlines, even of one lanelet
                    let outlines = ls.iter().map(|l| lanelet_outline(net, l.get(), ctx)).collect::<Result<Vec<_>, _>>()?;
                    vec![pb::Occupancy { shape: Some(pb::occupancy::Shape::ShapeGroup(pb::OccupancyGroup { shapes: outlines })) }]
                }
            };
            Some(pb::state::Position::Shape(occupancy_of(shapes)))
        }
    };
    let fields = StateFields {
        position,
        orientation: g.orientation.as_ref().map(interval),
        velocity: g.velocity.as_ref().map(interval),
        yaw_rate: None,
        slip_angle: None,
        acceleration: None,
        time_step: time_interval(&g.time, ctx)?,
    };
    Ok(sc::GoalState { state: state(fields), goal_position_lanelets: goal_lanelets })
}
