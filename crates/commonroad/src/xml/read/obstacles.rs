//! Static, dynamic and environment obstacles and their shapes.

use roxmltree::Node;

use super::cursor::{child, children, Cursor};
use crate::geometry::{AbsoluteShape, Circle, PlacedCircle, PlacedRectangle, Polygon, Rectangle, Shape};
use crate::ids::ObstacleId;
use crate::obstacle::{DynamicObstacle, DynamicObstacleType, EnvironmentObstacle, EnvironmentObstacleType, State, StaticObstacle, StaticObstacleType};
use crate::Error;

/// The single shape element inside `<shape>` (a shape group keeps its first member).
fn shape_element<'a, 'i>(cx: &mut Cursor, obstacle: Node<'a, 'i>) -> Result<Node<'a, 'i>, Error> {
    let shape = cx.req(obstacle, "shape")?;
    let mut elements = shape.children().filter(|n| n.is_element());
    let first = elements.next().ok_or_else(|| cx.err(shape, "<shape> needs a rectangle, circle or polygon"))?;
    if elements.next().is_some() {
        cx.warn(shape, "<shape> has several parts; only the first is kept");
    }
    Ok(first)
}

pub(crate) fn polygon(cx: &Cursor, node: Node) -> Result<Polygon, Error> {
    let points = children(node, "point").map(|p| cx.point(p)).collect::<Result<Vec<_>, _>>()?;
    Polygon::new(points).map_err(|e| cx.err(node, e.to_string()))
}

pub(crate) fn rectangle(cx: &Cursor, node: Node) -> Result<Rectangle, Error> {
    Rectangle::new(cx.f64_child(node, "length")?, cx.f64_child(node, "width")?).map_err(|e| cx.err(node, e.to_string()))
}

pub(crate) fn circle(cx: &Cursor, node: Node) -> Result<Circle, Error> {
    Circle::new(cx.f64_child(node, "radius")?).map_err(|e| cx.err(node, e.to_string()))
}

/// A rectangle placed in the world (`center` and `orientation` default to 0).
pub(crate) fn placed_rectangle(cx: &Cursor, node: Node) -> Result<PlacedRectangle, Error> {
    Ok(PlacedRectangle {
        rectangle: rectangle(cx, node)?,
        center: child(node, "center").map(|c| cx.point(c)).transpose()?.unwrap_or(crate::geometry::Point::new(0.0, 0.0)),
        orientation: child(node, "orientation").map(|o| cx.f64(o)).transpose()?.unwrap_or(0.0),
    })
}

pub(crate) fn placed_circle(cx: &Cursor, node: Node) -> Result<PlacedCircle, Error> {
    Ok(PlacedCircle {
        circle: circle(cx, node)?,
        center: child(node, "center").map(|c| cx.point(c)).transpose()?.unwrap_or(crate::geometry::Point::new(0.0, 0.0)),
    })
}

/// An obstacle's own-frame shape.
fn shape(cx: &mut Cursor, obstacle: Node) -> Result<Shape, Error> {
    let s = shape_element(cx, obstacle)?;
    let name = s.tag_name().name();
    if matches!(name, "rectangle" | "circle") && (child(s, "center").is_some() || child(s, "orientation").is_some()) {
        cx.warn(s, "an obstacle shape's center/orientation is read differently by commonroad-io versions; ignored");
    }
    match name {
        "rectangle" => Ok(Shape::Rectangle(rectangle(cx, s)?)),
        "circle" => Ok(Shape::Circle(circle(cx, s)?)),
        "polygon" => Ok(Shape::Polygon(polygon(cx, s)?)),
        other => Err(cx.err(s, format!("shape <{other}>: expected rectangle, circle or polygon"))),
    }
}

fn absolute_shape(cx: &mut Cursor, obstacle: Node) -> Result<AbsoluteShape, Error> {
    let s = shape_element(cx, obstacle)?;
    match s.tag_name().name() {
        "rectangle" => Ok(AbsoluteShape::Rectangle(placed_rectangle(cx, s)?)),
        "circle" => Ok(AbsoluteShape::Circle(placed_circle(cx, s)?)),
        "polygon" => Ok(AbsoluteShape::Polygon(polygon(cx, s)?)),
        other => Err(cx.err(s, format!("shape <{other}>: expected rectangle, circle or polygon"))),
    }
}

fn obstacle_type<T: Copy>(cx: &Cursor, node: Node, all: &[T], as_str: fn(T) -> &'static str) -> Result<T, Error> {
    cx.enum_text(cx.req(node, "type")?, all, as_str)
}

pub(crate) fn static_obstacle(cx: &mut Cursor, node: Node) -> Result<StaticObstacle, Error> {
    let id = cx.typed(node, "id", ObstacleId::new)?;
    let obstacle_type = obstacle_type(cx, node, StaticObstacleType::ALL, StaticObstacleType::as_str)?;
    let shape = shape(cx, node)?;
    let init = cx.req(node, "initialState")?;
    let p = cx.position_point(init)?;
    Ok(StaticObstacle { id, obstacle_type, shape, x: p.x, y: p.y, orientation: cx.exact_child(init, "orientation")?.unwrap_or(0.0) })
}

/// A state; fields commonroad-io fills with 0.0 when missing are 0.0 here too.
fn state(cx: &Cursor, node: Node) -> Result<State, Error> {
    let p = cx.position_point(node)?;
    Ok(State {
        time_step: cx.exact_time(node)?,
        x: p.x,
        y: p.y,
        orientation: cx.exact(cx.req(node, "orientation")?)?,
        velocity: cx.exact_child(node, "velocity")?.unwrap_or(0.0),
        acceleration: cx.exact_child(node, "acceleration")?.unwrap_or(0.0),
        yaw_rate: cx.exact_child(node, "yawRate")?.unwrap_or(0.0),
    })
}

/// `None` (with a warning) for an obstacle whose prediction is an occupancy set: the model
/// only holds trajectories.
pub(crate) fn dynamic_obstacle(cx: &mut Cursor, node: Node) -> Result<Option<DynamicObstacle>, Error> {
    let id = cx.typed(node, "id", ObstacleId::new)?;
    let obstacle_type = obstacle_type(cx, node, DynamicObstacleType::ALL, DynamicObstacleType::as_str)?;
    let shape = shape(cx, node)?;
    let initial_state = state(cx, cx.req(node, "initialState")?)?;
    let trajectory = match child(node, "trajectory") {
        Some(t) => children(t, "state").map(|s| state(cx, s)).collect::<Result<Vec<_>, _>>()?,
        None if child(node, "occupancySet").is_some() => {
            cx.warn(node, format!("dynamic obstacle {id}: occupancy sets are not read; obstacle skipped"));
            return Ok(None);
        }
        None => Vec::new(),
    };
    Ok(Some(DynamicObstacle { id, obstacle_type, shape, initial_state, trajectory }))
}

pub(crate) fn environment_obstacle(cx: &mut Cursor, node: Node) -> Result<EnvironmentObstacle, Error> {
    Ok(EnvironmentObstacle {
        id: cx.typed(node, "id", ObstacleId::new)?,
        obstacle_type: obstacle_type(cx, node, EnvironmentObstacleType::ALL, EnvironmentObstacleType::as_str)?,
        shape: absolute_shape(cx, node)?,
    })
}
