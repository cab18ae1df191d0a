//! Planning problems: initial state and goal states.

use roxmltree::Node;

use super::cursor::{child, children, Cursor};
use super::obstacles::{placed_circle, placed_rectangle, polygon};
use crate::ids::{LaneletId, PlanningProblemId};
use crate::planning::{GoalPosition, GoalState, Interval, PlanningInitialState, PlanningProblem, TimeInterval};
use crate::Error;

fn interval(cx: &Cursor, node: Node) -> Result<Interval, Error> {
    let (a, b) = cx.interval(node)?;
    Interval::new(a, b).map_err(|e| cx.err(node, e.to_string()))
}

fn time_interval(cx: &Cursor, goal: Node) -> Result<TimeInterval, Error> {
    let t = cx.req(goal, "time")?;
    let start = cx.u64(cx.req(t, "intervalStart")?)?;
    let end = cx.u64(cx.req(t, "intervalEnd")?)?;
    TimeInterval::new(start, end).map_err(|e| cx.err(t, e.to_string()))
}

fn goal_position(cx: &Cursor, pos: Node) -> Result<GoalPosition, Error> {
    let first = pos.children().find(|n| n.is_element()).ok_or_else(|| cx.err(pos, "goal <position> is empty"))?;
    let kind = first.tag_name().name();
    let all = children(pos, kind);
    Ok(match kind {
        "rectangle" => GoalPosition::Rectangles(all.map(|n| placed_rectangle(cx, n)).collect::<Result<_, _>>()?),
        "circle" => GoalPosition::Circles(all.map(|n| placed_circle(cx, n)).collect::<Result<_, _>>()?),
        "polygon" => GoalPosition::Polygons(all.map(|n| polygon(cx, n)).collect::<Result<_, _>>()?),
        "lanelet" => GoalPosition::Lanelets(cx.refs(pos, "lanelet", LaneletId::new)?),
        other => return Err(cx.err(first, format!("goal position <{other}>: expected rectangle, circle, polygon or lanelet"))),
    })
}

fn goal_state(cx: &Cursor, node: Node) -> Result<GoalState, Error> {
    Ok(GoalState {
        time: time_interval(cx, node)?,
        position: child(node, "position").map(|p| goal_position(cx, p)).transpose()?,
        orientation: child(node, "orientation").map(|o| interval(cx, o)).transpose()?,
        velocity: child(node, "velocity").map(|v| interval(cx, v)).transpose()?,
    })
}

pub(crate) fn planning_problem(cx: &mut Cursor, node: Node) -> Result<PlanningProblem, Error> {
    let id = cx.typed(node, "id", PlanningProblemId::new)?;
    let init = cx.req(node, "initialState")?;
    let p = cx.position_point(init)?;
    let initial_state = PlanningInitialState {
        x: p.x,
        y: p.y,
        orientation: cx.exact_child(init, "orientation")?.unwrap_or(0.0),
        velocity: cx.exact_child(init, "velocity")?.unwrap_or(0.0),
        yaw_rate: cx.exact_child(init, "yawRate")?.unwrap_or(0.0),
        slip_angle: cx.exact_child(init, "slipAngle")?.unwrap_or(0.0),
        acceleration: cx.exact_child(init, "acceleration")?,
    };
    let goal_states = children(node, "goalState").map(|g| goal_state(cx, g)).collect::<Result<Vec<_>, _>>()?;
    Ok(PlanningProblem { id, initial_state, goal_states })
}
