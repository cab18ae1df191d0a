//! Small plane geometry for drawing: placing obstacle shapes, offsetting polylines.

use commonroad::{AbsoluteShape, Shape};

use crate::view::View;

/// A shape as drawn: a polygon or a circle, in world coordinates.
#[derive(Debug, Clone, PartialEq)]
pub enum Placed {
    Polygon(Vec<(f64, f64)>),
    Circle((f64, f64), f64),
}

/// Rotates the local point (u, v) by `h` and moves it to (x, y).
pub fn local_to_world(x: f64, y: f64, h: f64, u: f64, v: f64) -> (f64, f64) {
    let (s, c) = h.sin_cos();
    (x + c * u - s * v, y + s * u + c * v)
}

/// The four corners of a `length` × `width` box centred at (x, y), heading `h`.
pub fn box_corners(x: f64, y: f64, h: f64, length: f64, width: f64) -> Vec<(f64, f64)> {
    let (a, b) = (0.5 * length, 0.5 * width);
    [(a, b), (-a, b), (-a, -b), (a, -b)].iter().map(|&(u, v)| local_to_world(x, y, h, u, v)).collect()
}

/// An obstacle shape placed at a state.
pub fn place(shape: &Shape, x: f64, y: f64, h: f64) -> Placed {
    match shape {
        Shape::Rectangle(r) => Placed::Polygon(box_corners(x, y, h, r.length(), r.width())),
        Shape::Circle(c) => Placed::Circle((x, y), c.radius()),
        Shape::Polygon(p) => Placed::Polygon(p.points().iter().map(|q| local_to_world(x, y, h, q.x, q.y)).collect()),
    }
}

/// A shape already in world coordinates.
pub fn place_absolute(shape: &AbsoluteShape) -> Placed {
    match shape {
        AbsoluteShape::Rectangle(r) => Placed::Polygon(box_corners(r.center.x, r.center.y, r.orientation, r.rectangle.length(), r.rectangle.width())),
        AbsoluteShape::Circle(c) => Placed::Circle((c.center.x, c.center.y), c.circle.radius()),
        AbsoluteShape::Polygon(p) => Placed::Polygon(p.points().iter().map(|q| (q.x, q.y)).collect()),
    }
}

/// World points to pixels.
pub fn to_px(view: &View, pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    pts.iter().map(|&(x, y)| view.px(x, y)).collect()
}

/// `pts` moved sideways by `d` (to the left of the direction of travel for d > 0, in a
/// y-down pixel frame), each vertex along the mean normal of its two segments.
pub fn offset_polyline(pts: &[(f64, f64)], d: f64) -> Vec<(f64, f64)> {
    let normal = |a: (f64, f64), b: (f64, f64)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let n = dx.hypot(dy);
        if n > 0.0 {
            (dy / n, -dx / n)
        } else {
            (0.0, 0.0)
        }
    };
    (0..pts.len())
        .map(|i| {
            let before = (i > 0).then(|| normal(pts[i - 1], pts[i]));
            let after = pts.get(i + 1).map(|&q| normal(pts[i], q));
            let (nx, ny) = match (before, after) {
                (Some(a), Some(b)) => {
                    let (sx, sy) = (a.0 + b.0, a.1 + b.1);
                    let n = sx.hypot(sy);
                    if n > 1e-9 {
                        (sx / n, sy / n)
                    } else {
                        a
                    }
                }
                (Some(a), None) | (None, Some(a)) => a,
                (None, None) => (0.0, 0.0),
            };
            (pts[i].0 + d * nx, pts[i].1 + d * ny)
        })
        .collect()
}
