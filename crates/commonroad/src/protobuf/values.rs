//! The model's values as 2024 message values: points, exact values and intervals, time steps,
//! obstacle shapes (in the obstacle's frame), occupancies (placed in the world), states, and the
//! enumerations (the model's XSD spellings become the messages' UPPER_SNAKE names).

use super::error::finite;
use super::messages::commonroad_common as pb;
use crate::geometry::{AbsoluteShape, PlacedCircle, PlacedRectangle, Point, Polygon, Shape};
use crate::planning::{Interval, TimeInterval};
use crate::Error;

pub(super) fn point(p: &Point, context: &dyn Fn() -> String) -> Result<pb::Point, Error> {
    Ok(pb::Point {
        x: finite(|| format!("{} x", context()), p.x)?,
        y: finite(|| format!("{} y", context()), p.y)?,
        z: p.z.map(|z| finite(|| format!("{} z", context()), z)).transpose()?,
    })
}

pub(super) fn exact(v: f64, context: impl FnOnce() -> String) -> Result<pb::FloatExactOrInterval, Error> {
    use pb::float_exact_or_interval::ExactOrInterval;
    Ok(pb::FloatExactOrInterval { exact_or_interval: Some(ExactOrInterval::Exact(finite(context, v)?)) })
}

/// A closed interval (finite by construction).
pub(super) fn interval(i: &Interval) -> pb::FloatExactOrInterval {
    use pb::float_exact_or_interval::ExactOrInterval;
    pb::FloatExactOrInterval { exact_or_interval: Some(ExactOrInterval::Interval(pb::FloatInterval { start: i.start(), end: i.end() })) }
}

fn time_step(t: u64, context: impl FnOnce() -> String) -> Result<i32, Error> {
    super::error::fits_i32(context, t)
}

pub(super) fn time_exact(t: u64, context: impl FnOnce() -> String) -> Result<pb::IntegerExactOrInterval, Error> {
    use pb::integer_exact_or_interval::ExactOrInterval;
    Ok(pb::IntegerExactOrInterval { exact_or_interval: Some(ExactOrInterval::Exact(time_step(t, context)?)) })
}

pub(super) fn time_interval(i: &TimeInterval, context: &dyn Fn() -> String) -> Result<pb::IntegerExactOrInterval, Error> {
    use pb::integer_exact_or_interval::ExactOrInterval;
    let interval = pb::IntegerInterval { start: time_step(i.start(), context)?, end: time_step(i.end(), context)? };
    Ok(pb::IntegerExactOrInterval { exact_or_interval: Some(ExactOrInterval::Interval(interval)) })
}

fn polygon_points(p: &Polygon, context: &dyn Fn() -> String) -> Result<Vec<pb::Point>, Error> {
    p.points().iter().map(|pt| point(pt, context)).collect()
}

/// An obstacle's shape, in its own frame (no centre, no orientation: the state places it).
pub(super) fn shape(s: &Shape, context: &dyn Fn() -> String) -> Result<pb::Shape, Error> {
    use pb::shape::Shape as Kind;
    let kind = match s {
        Shape::Rectangle(r) => Kind::Rectangle(pb::Rect { length: r.length(), width: r.width() }),
        Shape::Circle(c) => Kind::Circle(pb::Circle { radius: c.radius() }),
        Shape::Polygon(p) => Kind::Polygon(pb::Polygon { vertices: polygon_points(p, context)? }),
    };
    Ok(pb::Shape { shape: Some(kind) })
}

pub(super) fn placed_rectangle(r: &PlacedRectangle, context: &dyn Fn() -> String) -> Result<pb::Occupancy, Error> {
    let rect = pb::RectOccupancy {
        length: r.rectangle.length(),
        width: r.rectangle.width(),
        center: Some(point(&r.center, context)?),
        orientation: Some(finite(|| format!("{} orientation", context()), r.orientation)?),
    };
    Ok(pb::Occupancy { shape: Some(pb::occupancy::Shape::Rectangle(rect)) })
}

pub(super) fn placed_circle(c: &PlacedCircle, context: &dyn Fn() -> String) -> Result<pb::Occupancy, Error> {
    let circle = pb::CircleOccupancy { radius: c.circle.radius(), center: Some(point(&c.center, context)?) };
    Ok(pb::Occupancy { shape: Some(pb::occupancy::Shape::Circle(circle)) })
}

pub(super) fn polygon_occupancy(points: Vec<pb::Point>) -> pb::Occupancy {
    pb::Occupancy { shape: Some(pb::occupancy::Shape::Polygon(pb::PolygonOccupancy { vertices: points })) }
}

pub(super) fn absolute_shape(s: &AbsoluteShape, context: &dyn Fn() -> String) -> Result<pb::Occupancy, Error> {
    match s {
        AbsoluteShape::Rectangle(r) => placed_rectangle(r, context),
        AbsoluteShape::Circle(c) => placed_circle(c, context),
        AbsoluteShape::Polygon(p) => Ok(polygon_occupancy(polygon_points(p, context)?)),
    }
}

/// One occupancy, or a group when there are several (what the readers make of a 2020a
/// `position` with several shapes).
pub(super) fn occupancy_of(mut shapes: Vec<pb::Occupancy>) -> pb::Occupancy {
    if shapes.len() == 1 {
        if let Some(only) = shapes.pop() {
            return only;
        }
    }
    pb::Occupancy { shape: Some(pb::occupancy::Shape::ShapeGroup(pb::OccupancyGroup { shapes })) }
}

/// The fields of a state that are set; every other field of the message stays unset.
pub(super) struct StateFields {
    pub position: Option<pb::state::Position>,
    pub orientation: Option<pb::FloatExactOrInterval>,
    pub velocity: Option<pb::FloatExactOrInterval>,
    pub yaw_rate: Option<pb::FloatExactOrInterval>,
    pub slip_angle: Option<pb::FloatExactOrInterval>,
    pub acceleration: Option<pb::FloatExactOrInterval>,
    pub time_step: pb::IntegerExactOrInterval,
}

pub(super) fn state(f: StateFields) -> pb::State {
    pb::State {
        position: f.position,
        orientation: f.orientation,
        velocity: f.velocity,
        yaw_rate: f.yaw_rate,
        slip_angle: f.slip_angle,
        acceleration: f.acceleration,
        time_step: f.time_step,
        ..Default::default()
    }
}

/// `busLane` → `BUS_LANE`, `solid_solid` → `SOLID_SOLID`, `redYellow` → `RED_YELLOW`: the
/// protobuf enumeration name of an XSD spelling.
pub(super) fn upper_snake(xsd: &str) -> String {
    let mut out = String::with_capacity(xsd.len() + 4);
    for c in xsd.chars() {
        if c.is_ascii_uppercase() {
            out.push('_');
        }
        out.push(c.to_ascii_uppercase());
    }
    out
}

/// The enumeration value named like the XSD spelling `xsd` (`from_str_name` of a generated enum).
pub(super) fn enum_value<E: Into<i32>>(what: &'static str, xsd: &str, from_str_name: fn(&str) -> Option<E>) -> Result<i32, Error> {
    let name = upper_snake(xsd);
    from_str_name(&name).map(Into::into).ok_or(Error::NoEnumValue { what, name })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xsd_spellings_become_enumeration_names() {
        assert_eq!(upper_snake("busLane"), "BUS_LANE");
        assert_eq!(upper_snake("restricted_area"), "RESTRICTED_AREA");
        assert_eq!(upper_snake("redYellow"), "RED_YELLOW");
        assert_eq!(upper_snake("car"), "CAR");
    }
}
