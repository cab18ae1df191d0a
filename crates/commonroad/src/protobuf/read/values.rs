//! 2024 message values as model values: points, exact values (an interval read as its midpoint,
//! with the caller told), time steps, obstacle shapes, placed shapes, and enumerations (the
//! messages' UPPER_SNAKE names back to the model's XSD spellings).

use super::super::messages::commonroad_common as pb;
use super::super::values::upper_snake;
use super::Bad;
use crate::geometry::{AbsoluteShape, Circle, PlacedCircle, PlacedRectangle, Point, Polygon, Rectangle, Shape};

pub(super) fn point(p: &pb::Point, ctx: &dyn Fn() -> String) -> Result<Point, Bad> {
    if !(p.x.is_finite() && p.y.is_finite() && !matches!(p.z, Some(z) if !z.is_finite())) {
        return Err(Bad::new(ctx(), "a coordinate is not a finite number"));
    }
    Ok(Point { x: p.x, y: p.y, z: p.z })
}

/// A value: exact, or the midpoint of an interval (`uncertain` is set then); `None` if unset.
pub(super) fn value(v: &Option<pb::FloatExactOrInterval>, uncertain: &mut bool, ctx: &dyn Fn() -> String) -> Result<Option<f64>, Bad> {
    use pb::float_exact_or_interval::ExactOrInterval;
    let x = match v.as_ref().and_then(|v| v.exact_or_interval.as_ref()) {
        None => return Ok(None),
        Some(ExactOrInterval::Exact(x)) => *x,
        Some(ExactOrInterval::Interval(i)) => {
            *uncertain = true;
            0.5 * (i.start + i.end)
        }
    };
    if x.is_finite() {
        Ok(Some(x))
    } else {
        Err(Bad::new(ctx(), "a value is not a finite number"))
    }
}

/// A closed interval (an exact value as the interval of one point).
pub(super) fn interval(v: &Option<pb::FloatExactOrInterval>, ctx: &dyn Fn() -> String) -> Result<Option<crate::planning::Interval>, Bad> {
    use pb::float_exact_or_interval::ExactOrInterval;
    let (a, b) = match v.as_ref().and_then(|v| v.exact_or_interval.as_ref()) {
        None => return Ok(None),
        Some(ExactOrInterval::Exact(x)) => (*x, *x),
        Some(ExactOrInterval::Interval(i)) => (i.start, i.end),
    };
    crate::planning::Interval::new(a, b).map(Some).map_err(|e| Bad::new(ctx(), e.to_string()))
}

/// A time step: exact, or an interval's start (`uncertain` is set then).
pub(super) fn time_step(t: &pb::IntegerExactOrInterval, uncertain: &mut bool, ctx: &dyn Fn() -> String) -> Result<u64, Bad> {
    use pb::integer_exact_or_interval::ExactOrInterval;
    let v = match &t.exact_or_interval {
        Some(ExactOrInterval::Exact(v)) => *v,
        Some(ExactOrInterval::Interval(i)) => {
            *uncertain = true;
            i.start
        }
        None => return Err(Bad::new(ctx(), "no time step")),
    };
    u64::try_from(v).map_err(|_| Bad::new(ctx(), format!("time step {v} is negative")))
}

/// A time-step interval (an exact time as the interval of one step).
pub(super) fn time_interval(t: &pb::IntegerExactOrInterval, ctx: &dyn Fn() -> String) -> Result<(u64, u64), Bad> {
    use pb::integer_exact_or_interval::ExactOrInterval;
    let (a, b) = match &t.exact_or_interval {
        Some(ExactOrInterval::Exact(v)) => (*v, *v),
        Some(ExactOrInterval::Interval(i)) => (i.start, i.end),
        None => return Err(Bad::new(ctx(), "no time")),
    };
    let u = |v: i32| u64::try_from(v).map_err(|_| Bad::new(ctx(), format!("time step {v} is negative")));
    Ok((u(a)?, u(b)?))
}

fn model<T, E>(r: Result<T, E>, ctx: &dyn Fn() -> String) -> Result<T, Bad>
where
    E: std::fmt::Display,
{
    r.map_err(|e| Bad::new(ctx(), e.to_string()))
}

/// An obstacle's shape. A truck shape becomes the box of its truck (a semi-trailer truck: of
/// truck and trailer end to end), with a warning.
pub(super) fn shape(s: &pb::Shape, warnings: &mut Vec<String>, ctx: &dyn Fn() -> String) -> Result<Shape, Bad> {
    use pb::shape::Shape as K;
    match &s.shape {
        Some(K::Rectangle(r)) => model(Shape::rectangle(r.length, r.width), ctx),
        Some(K::Circle(c)) => model(Shape::circle(c.radius), ctx),
        Some(K::Polygon(p)) => {
            let points = p.vertices.iter().map(|v| point(v, ctx)).collect::<Result<Vec<_>, _>>()?;
            model(Polygon::new(points).map(Shape::Polygon), ctx)
        }
        Some(K::TruckShape(t)) => {
            warnings.push(format!("{}: a truck shape is read as its box", ctx()));
            model(Shape::rectangle(t.truck_dims.length, t.truck_dims.width), ctx)
        }
        Some(K::SemiTrailerTruckShape(t)) => {
            warnings.push(format!("{}: a semi-trailer truck shape is read as one box the length of truck and trailer", ctx()));
            let d = &t.truck_shape.truck_dims;
            model(Shape::rectangle(d.length + t.trailer_dims.length, d.width.max(t.trailer_dims.width)), ctx)
        }
        None => Err(Bad::new(ctx(), "no shape")),
    }
}

/// A shape placed in the world; a group is read as its first member, with a warning.
pub(super) fn occupancy(o: &pb::Occupancy, warnings: &mut Vec<String>, ctx: &dyn Fn() -> String) -> Result<AbsoluteShape, Bad> {
    let mut all = occupancies(o, ctx)?;
    if all.len() > 1 {
        warnings.push(format!("{}: a group of {} shapes is read as its first", ctx(), all.len()));
    }
    if all.is_empty() {
        return Err(Bad::new(ctx(), "an empty shape group"));
    }
    Ok(all.swap_remove(0))
}

/// Every shape of an occupancy (a group's members in order, nested groups flattened).
pub(super) fn occupancies(o: &pb::Occupancy, ctx: &dyn Fn() -> String) -> Result<Vec<AbsoluteShape>, Bad> {
    use pb::occupancy::Shape as K;
    let origin = pb::Point::default();
    Ok(match &o.shape {
        Some(K::Rectangle(r)) => vec![AbsoluteShape::Rectangle(PlacedRectangle {
            rectangle: model(Rectangle::new(r.length, r.width), ctx)?,
            center: point(r.center.as_ref().unwrap_or(&origin), ctx)?,
            orientation: r.orientation.unwrap_or(0.0),
        })],
        Some(K::Circle(c)) => {
            vec![AbsoluteShape::Circle(PlacedCircle { circle: model(Circle::new(c.radius), ctx)?, center: point(c.center.as_ref().unwrap_or(&origin), ctx)? })]
        }
        Some(K::Polygon(p)) => {
            let points = p.vertices.iter().map(|v| point(v, ctx)).collect::<Result<Vec<_>, _>>()?;
            vec![AbsoluteShape::Polygon(model(Polygon::new(points), ctx)?)]
        }
        Some(K::ShapeGroup(g)) => {
            let mut out = Vec::new();
            for member in &g.shapes {
                out.extend(occupancies(member, ctx)?);
            }
            out
        }
        None => return Err(Bad::new(ctx(), "no shape")),
    })
}

/// The centre of a placed shape (a polygon's vertex mean).
pub(super) fn centre(s: &AbsoluteShape) -> Point {
    match s {
        AbsoluteShape::Rectangle(r) => r.center,
        AbsoluteShape::Circle(c) => c.center,
        AbsoluteShape::Polygon(p) => {
            let n = p.points().len().max(1) as f64;
            Point::new(p.points().iter().map(|q| q.x).sum::<f64>() / n, p.points().iter().map(|q| q.y).sum::<f64>() / n)
        }
    }
}

/// The model enumeration value whose XSD spelling is the message's name `name` (UPPER_SNAKE).
pub(super) fn enum_from<T: Copy>(what: &str, name: Option<&str>, all: &[T], as_str: fn(T) -> &'static str, ctx: &dyn Fn() -> String) -> Result<T, Bad> {
    let Some(name) = name else {
        return Err(Bad::new(ctx(), format!("{what}: a value the 2024 enumeration does not have")));
    };
    all.iter().copied().find(|v| upper_snake(as_str(*v)) == name).ok_or_else(|| Bad::new(ctx(), format!("{what} {name} has no 2020a spelling")))
}
