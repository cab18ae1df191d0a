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

/// A state; fields commonroad-io fills with 0.0 when missing are 0.0 here too. A value given
/// as an interval (uncertain states, as 2018b dataset files have) is read as its midpoint and a
/// position given as a shape as the shape's centre; `uncertain` is set when that happened.
///
/// A point-mass state (commonroad-io's `PMState`: `velocity` and `velocityY` are the x and y
/// components, no orientation) gives its heading and speed from the components; `uncertain` is
/// set for it too (its warning says so).
fn state(cx: &Cursor, node: Node, uncertain: &mut bool) -> Result<State, Error> {
    let p = cx.position_point_or_centre(node, uncertain)?;
    let mut velocity = cx.exact_or_midpoint_child(node, "velocity", uncertain)?.unwrap_or(0.0);
    let orientation = match child(node, "orientation") {
        Some(o) => cx.exact_or_midpoint(o, uncertain)?,
        None => {
            *uncertain = true;
            match cx.exact_or_midpoint_child(node, "velocityY", uncertain)? {
                Some(vy) => {
                    let heading = vy.atan2(velocity);
                    velocity = vy.hypot(velocity);
                    heading
                }
                None => 0.0,
            }
        }
    };
    Ok(State {
        time_step: cx.exact_time(node)?,
        x: p.x,
        y: p.y,
        orientation,
        velocity,
        acceleration: cx.exact_or_midpoint_child(node, "acceleration", uncertain)?.unwrap_or(0.0),
        yaw_rate: cx.exact_or_midpoint_child(node, "yawRate", uncertain)?.unwrap_or(0.0),
    })
}

/// The warning of an obstacle whose states had intervals or shapes.
fn warn_uncertain(cx: &mut Cursor, node: Node, id: ObstacleId, uncertain: bool) {
    if uncertain {
        cx.warn(
            node,
            format!(
                "obstacle {id}: uncertain state values (intervals, position shapes) are read as their midpoints and centres, \
                 a state without orientation gets the heading of its velocity components (or 0)"
            ),
        );
    }
}

/// `None` (with a warning) for an obstacle whose prediction is an occupancy set: the model
/// only holds trajectories.
pub(crate) fn dynamic_obstacle(cx: &mut Cursor, node: Node) -> Result<Option<DynamicObstacle>, Error> {
    let id = cx.typed(node, "id", ObstacleId::new)?;
    let obstacle_type = obstacle_type(cx, node, DynamicObstacleType::ALL, DynamicObstacleType::as_str)?;
    let shape = shape(cx, node)?;
    let mut uncertain = false;
    let initial_state = state(cx, cx.req(node, "initialState")?, &mut uncertain)?;
    let trajectory = match child(node, "trajectory") {
        Some(t) => children(t, "state").map(|s| state(cx, s, &mut uncertain)).collect::<Result<Vec<_>, _>>()?,
        None if child(node, "occupancySet").is_some() => {
            cx.warn(node, format!("dynamic obstacle {id}: occupancy sets are not read; obstacle skipped"));
            return Ok(None);
        }
        None => Vec::new(),
    };
    warn_uncertain(cx, node, id, uncertain);
    Ok(Some(DynamicObstacle { id, obstacle_type, shape, initial_state, trajectory }))
}

/// The type of a 2018b obstacle for its role's element: one of `own`, or `fallback` with a
/// warning when it is a type only the other role's element has (`other`).
fn type_2018b<T: Copy>(cx: &mut Cursor, node: Node, text: &str, own: &[T], as_str: fn(T) -> &'static str, other: bool, fallback: T) -> Result<T, Error> {
    if let Some(t) = own.iter().copied().find(|t| as_str(*t) == text) {
        return Ok(t);
    }
    if !other {
        return Err(cx.err(node, format!("obstacle type {text:?} is not a CommonRoad obstacle type")));
    }
    cx.warn(node, format!("obstacle type {text:?} is read as {:?}: 2020a has no such obstacle of this role", as_str(fallback)));
    Ok(fallback)
}

/// A 2018b `<obstacle>` (its `<role>` says static or dynamic; one type list for both), as the
/// 2020a element it became. A static obstacle whose type only a dynamic one may have (a parked
/// `car`) becomes a static `parkedVehicle`; a dynamic one whose type only a static one may have
/// becomes a dynamic `unknown`, each with a warning.
pub(crate) fn obstacle_2018b(cx: &mut Cursor, node: Node) -> Result<Option<Obstacle2018b>, Error> {
    let id = cx.typed(node, "id", ObstacleId::new)?;
    let role_node = cx.req(node, "role")?;
    let role = cx.text(role_node).to_string();
    let type_node = cx.req(node, "type")?;
    let type_text = cx.text(type_node).to_string();
    match role.as_str() {
        "static" => {
            let other = DynamicObstacleType::ALL.iter().any(|t| t.as_str() == type_text);
            let obstacle_type =
                type_2018b(cx, type_node, &type_text, StaticObstacleType::ALL, StaticObstacleType::as_str, other, StaticObstacleType::ParkedVehicle)?;
            let shape = shape(cx, node)?;
            let init = cx.req(node, "initialState")?;
            let mut uncertain = false;
            let p = cx.position_point_or_centre(init, &mut uncertain)?;
            let orientation = cx.exact_or_midpoint_child(init, "orientation", &mut uncertain)?.unwrap_or(0.0);
            warn_uncertain(cx, node, id, uncertain);
            Ok(Some(Obstacle2018b::Static(StaticObstacle { id, obstacle_type, shape, x: p.x, y: p.y, orientation })))
        }
        "dynamic" => {
            let other = StaticObstacleType::ALL.iter().any(|t| t.as_str() == type_text);
            let obstacle_type =
                type_2018b(cx, type_node, &type_text, DynamicObstacleType::ALL, DynamicObstacleType::as_str, other, DynamicObstacleType::Unknown)?;
            let shape = shape(cx, node)?;
            let mut uncertain = false;
            let initial_state = state(cx, cx.req(node, "initialState")?, &mut uncertain)?;
            let trajectory = match child(node, "trajectory") {
                Some(t) => children(t, "state").map(|s| state(cx, s, &mut uncertain)).collect::<Result<Vec<_>, _>>()?,
                None => {
                    cx.warn(node, format!("dynamic obstacle {id}: occupancy sets are not read; obstacle skipped"));
                    return Ok(None);
                }
            };
            warn_uncertain(cx, node, id, uncertain);
            Ok(Some(Obstacle2018b::Dynamic(DynamicObstacle { id, obstacle_type, shape, initial_state, trajectory })))
        }
        other => Err(cx.err(role_node, format!("obstacle role {other:?}: expected static or dynamic"))),
    }
}

/// A 2018b obstacle as the 2020a element it became.
pub(crate) enum Obstacle2018b {
    Static(StaticObstacle),
    Dynamic(DynamicObstacle),
}

pub(crate) fn environment_obstacle(cx: &mut Cursor, node: Node) -> Result<EnvironmentObstacle, Error> {
    Ok(EnvironmentObstacle {
        id: cx.typed(node, "id", ObstacleId::new)?,
        obstacle_type: obstacle_type(cx, node, EnvironmentObstacleType::ALL, EnvironmentObstacleType::as_str)?,
        shape: absolute_shape(cx, node)?,
    })
}
