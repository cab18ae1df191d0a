//! The scenario file: the header (benchmark id from its parts, file information, time step),
//! the planning problems with their goals, and the scenario tags (which 2024 keeps with each
//! planning problem: those of the first are the scenario's).

use std::collections::BTreeSet;

use super::super::messages::{commonroad_common as pb, commonroad_scenario as sc};
use super::values::{enum_from, interval, occupancies, point, time_interval, value};
use super::Bad;
use crate::geometry::AbsoluteShape;
use crate::header::{BenchmarkId, Date, Header};
use crate::ids::{LaneletId, PlanningProblemId};
use crate::planning::{GoalPosition, GoalState, PlanningInitialState, PlanningProblem, PlanningProblemSet, TimeInterval};
use crate::tags::Tag;

fn benchmark_id(id: &pb::ScenarioId) -> String {
    let mut s =
        format!("{}{}_{}-{}_{}", if id.cooperative { "C-" } else { "" }, id.map_id.country_id, id.map_id.map_name, id.map_id.map_id, id.configuration_id);
    if let (Some(b), Some(p)) = (&id.obstacle_behavior, id.prediction_id) {
        s.push_str(&format!("_{b}-{p}"));
    }
    s
}

pub(super) fn header(meta: &pb::ScenarioMetaInformation, warnings: &mut Vec<String>) -> Result<Header, Bad> {
    let raw = benchmark_id(&meta.benchmark_id);
    let benchmark_id = match BenchmarkId::parse(&raw) {
        Ok(id) => id,
        Err(e) => {
            let id = BenchmarkId::for_converted("ZAM", &raw).map_err(|e| Bad::new("benchmark id", e.to_string()))?;
            warnings.push(format!("{e}; using {id}"));
            id
        }
    };
    let d = &meta.file_information.date;
    let date = match (d.year, d.month, d.day) {
        (Some(y), Some(m), Some(day)) => {
            u16::try_from(y).ok().zip(u8::try_from(m).ok()).zip(u8::try_from(day).ok()).and_then(|((y, m), day)| Date::new(y, m, day).ok())
        }
        _ => None,
    };
    let date = match date {
        Some(d) => d,
        None => {
            warnings.push("the scenario file has no valid date; 1970-01-01 is used".to_string());
            Date::new(1970, 1, 1).map_err(|e| Bad::new("date", e.to_string()))?
        }
    };
    let step = meta.time_step_size;
    if !(step.is_finite() && step > 0.0) {
        return Err(Bad::new("time step size", format!("{step} is not a positive number of seconds")));
    }
    let f = &meta.file_information;
    Ok(Header { benchmark_id, date, author: f.author.clone(), affiliation: f.affiliation.clone(), source: f.source.clone(), time_step_size: step })
}

fn goal(g: &sc::GoalState, warnings: &mut Vec<String>, ctx: &dyn Fn() -> String) -> Result<GoalState, Bad> {
    let (start, end) = time_interval(&g.state.time_step, ctx)?;
    let time = TimeInterval::new(start, end).map_err(|e| Bad::new(ctx(), e.to_string()))?;
    let position = if !g.goal_position_lanelets.is_empty() {
        let ids =
            g.goal_position_lanelets.iter().map(|l| LaneletId::new(u64::from(*l)).ok_or_else(|| Bad::new(ctx(), "lanelet id 0"))).collect::<Result<_, _>>()?;
        Some(GoalPosition::Lanelets(ids))
    } else {
        match &g.state.position {
            None => None,
            Some(pb::state::Position::Point(p)) => {
                warnings.push(format!("{}: a goal position that is a point is read as a circle of 1 mm", ctx()));
                let circle = crate::geometry::Circle::new(0.001).map_err(|e| Bad::new(ctx(), e.to_string()))?;
                Some(GoalPosition::Circles(vec![crate::geometry::PlacedCircle { circle, center: point(p, ctx)? }]))
            }
            Some(pb::state::Position::Shape(o)) => Some(one_kind(occupancies(o, ctx)?, warnings, ctx)?),
        }
    };
    Ok(GoalState { time, position, orientation: interval(&g.state.orientation, ctx)?, velocity: interval(&g.state.velocity, ctx)? })
}

/// A goal position set of shapes: the 2020a format holds one kind per goal; shapes of other
/// kinds than the first are left out, with a warning.
fn one_kind(shapes: Vec<AbsoluteShape>, warnings: &mut Vec<String>, ctx: &dyn Fn() -> String) -> Result<GoalPosition, Bad> {
    let n = shapes.len();
    let pos = match shapes.first() {
        Some(AbsoluteShape::Rectangle(_)) => {
            GoalPosition::Rectangles(shapes.into_iter().filter_map(|s| if let AbsoluteShape::Rectangle(r) = s { Some(r) } else { None }).collect())
        }
        Some(AbsoluteShape::Circle(_)) => {
            GoalPosition::Circles(shapes.into_iter().filter_map(|s| if let AbsoluteShape::Circle(c) = s { Some(c) } else { None }).collect())
        }
        Some(AbsoluteShape::Polygon(_)) => {
            GoalPosition::Polygons(shapes.into_iter().filter_map(|s| if let AbsoluteShape::Polygon(p) = s { Some(p) } else { None }).collect())
        }
        None => return Err(Bad::new(ctx(), "an empty goal position")),
    };
    let kept = match &pos {
        GoalPosition::Rectangles(v) => v.len(),
        GoalPosition::Circles(v) => v.len(),
        GoalPosition::Polygons(v) => v.len(),
        GoalPosition::Lanelets(v) => v.len(),
    };
    if kept < n {
        warnings.push(format!("{}: a goal of shapes of several kinds keeps the {kept} of the first kind ({} left out)", ctx(), n - kept));
    }
    Ok(pos)
}

fn planning_problem(p: &sc::PlanningProblem, warnings: &mut Vec<String>) -> Result<PlanningProblem, Bad> {
    let ctx = || format!("planningProblem {}", p.planning_problem_id);
    let s = &p.initial_state;
    let position = match &s.position {
        Some(pb::state::Position::Point(q)) => point(q, &ctx)?,
        _ => return Err(Bad::new(ctx(), "the initial state has no exact position")),
    };
    let mut uncertain = false;
    let mut field = |v: &Option<pb::FloatExactOrInterval>| value(v, &mut uncertain, &ctx);
    let initial_state = PlanningInitialState {
        x: position.x,
        y: position.y,
        orientation: field(&s.orientation)?.unwrap_or(0.0),
        velocity: field(&s.velocity)?.unwrap_or(0.0),
        yaw_rate: field(&s.yaw_rate)?.unwrap_or(0.0),
        slip_angle: field(&s.slip_angle)?.unwrap_or(0.0),
        acceleration: field(&s.acceleration)?,
    };
    if uncertain {
        warnings.push(format!("{}: an uncertain initial value is read as its midpoint", ctx()));
    }
    Ok(PlanningProblem {
        id: PlanningProblemId::new(u64::from(p.planning_problem_id)).ok_or_else(|| Bad::new(ctx(), "id 0"))?,
        initial_state,
        goal_states: p.goal_states.iter().map(|g| goal(g, warnings, &ctx)).collect::<Result<_, _>>()?,
    })
}

/// The planning problems and the scenario's tags.
pub(super) fn planning_problems(s: &sc::CommonRoadScenario, warnings: &mut Vec<String>) -> Result<(PlanningProblemSet, BTreeSet<Tag>), Bad> {
    if !s.cooperative_planning_problems.is_empty() {
        warnings.push("cooperative planning problems are not part of the model; their single problems are read".to_string());
    }
    let problems = s.planning_problems.iter().map(|p| planning_problem(p, warnings)).collect::<Result<Vec<_>, _>>()?;
    let mut tags = BTreeSet::new();
    if let Some(first) = s.planning_problems.first() {
        for t in &first.scenario_tags.tags {
            let name = sc::tag_enum::Tag::try_from(*t).ok().map(|v| v.as_str_name());
            tags.insert(enum_from("scenario tag", name, &Tag::ALL, Tag::as_str, &|| "scenario tags".to_string())?);
        }
    }
    Ok((PlanningProblemSet { problems }, tags))
}
