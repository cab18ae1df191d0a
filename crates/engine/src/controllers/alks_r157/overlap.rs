//! Whether an object lies in front of the ego's front face, as esmini's Object::OverlappingFront
//! decides it for the ReferenceDriver's AEB: the corners of the object's bounding box are
//! projected, in the plane, on the line through the ego's front face; the AEB starts only when
//! the object covers that face (corners at or beyond both ends) or lies within it (every corner
//! inside), either within `tolerance`.

use crate::conditions::boxes::corners;
use crate::entities::Entity;

/// esmini's PointInBetweenVectorEndpoints for a point `p` already on the line from `a` to `b`:
/// whether it lies between them, and its position: the fraction of the way from `a` (0..1)
/// inside, the distance to the nearer end outside (negative beyond `a`).
fn between_ends(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> (bool, f64) {
    let (inside, norm) = if (b.1 - a.1).abs() < crate::dynamics::ESMINI_SMALL_NUMBER && (b.0 - a.0).abs() < crate::dynamics::ESMINI_SMALL_NUMBER {
        (true, 0.0)
    } else {
        // the coordinate that changes most along the line decides
        let (v, v1, v2) = if (b.0 - a.0).abs() < (b.1 - a.1).abs() { (p.1, a.1, b.1) } else { (p.0, a.0, b.0) };
        let inside = if v2 > v1 { !(v < v1 || v > v2) } else { !(v > v1 || v < v2) };
        (inside, (v - v1) / (v2 - v1))
    };
    if inside {
        (true, norm)
    } else if norm < 0.0 {
        (false, -(p.0 - a.0).hypot(p.1 - a.1))
    } else {
        (false, (p.0 - b.0).hypot(p.1 - b.1))
    }
}

/// esmini's ProjectPointOnLine2D: the foot of the perpendicular from `p` on the line through
/// `a` and `b` (`a` itself when they coincide).
fn project(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    if dx.abs() < crate::dynamics::ESMINI_SMALL_NUMBER && dy.abs() < crate::dynamics::ESMINI_SMALL_NUMBER {
        return a;
    }
    let k = (dy * (p.0 - a.0) - dx * (p.1 - a.1)) / (dy * dy + dx * dx);
    (p.0 - k * dy, p.1 + k * dx)
}

/// Object::OverlappingFront(target, tolerance) > OverlapType::PART: `o` fully inside the
/// forward projection of `e`'s front face or covering it.
pub(super) fn covers_or_inside_front(e: &Entity, o: &Entity, tolerance: f64) -> bool {
    // `corners`: front left, front right, rear right, rear left
    let [front_left, front_right, ..] = corners(e);
    let width = e.bbox[4];
    let (mut inside, mut left, mut right) = (0, 0, 0);
    for v in corners(o) {
        let (within, norm) = between_ends(project(v, front_left, front_right), front_left, front_right);
        if within {
            inside += 1;
            if norm * width < tolerance {
                left += 1;
            } else if (1.0 - norm) * width < tolerance {
                right += 1;
            }
        } else {
            if norm.abs() < tolerance {
                inside += 1;
            }
            if norm < 0.0 {
                left += 1;
            } else {
                right += 1;
            }
        }
    }
    inside == 4 || (left > 0 && right > 0)
}
