//! Entities' bounding boxes in the plane: their corners, whether two overlap (separating axes),
//! the gap between their shadows on an axis and the shortest distance between them — the
//! geometry the distance conditions, collisions and the free-space measures share.

use crate::entities::Entity;

/// The four corners of an entity's bounding box in world coordinates.
pub(crate) fn corners(e: &Entity) -> [(f64, f64); 4] {
    let (s, c) = e.h.sin_cos();
    let (cx, cy) = e.box_center();
    let (hl, hw) = (0.5 * e.bbox[3], 0.5 * e.bbox[4]);
    let mut out = [(0.0, 0.0); 4];
    for (i, (a, b)) in [(hl, hw), (hl, -hw), (-hl, -hw), (-hl, hw)].into_iter().enumerate() {
        out[i] = (cx + a * c - b * s, cy + a * s + b * c);
    }
    out
}

/// Signed gap between the projections of two point sets on axis (ux, uy), measured from `a` to `b`.
pub(crate) fn interval_gap(a: &[(f64, f64)], b: &[(f64, f64)], ux: f64, uy: f64) -> f64 {
    let proj = |p: &[(f64, f64)]| {
        p.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &(x, y)| {
            let d = x * ux + y * uy;
            (lo.min(d), hi.max(d))
        })
    };
    let (a0, a1) = proj(a);
    let (b0, b1) = proj(b);
    if b0 > a1 {
        b0 - a1
    } else if a0 > b1 {
        -(a0 - b1)
    } else {
        0.0
    }
}

fn seg_point_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let u = if l2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (p.0 - a.0 - u * dx).hypot(p.1 - a.1 - u * dy)
}

/// Whether two convex quadrilaterals overlap (separating axis test).
pub(crate) fn boxes_overlap(a: &[(f64, f64); 4], b: &[(f64, f64); 4]) -> bool {
    for poly in [a, b] {
        for i in 0..4 {
            let (p, q) = (poly[i], poly[(i + 1) % 4]);
            let (nx, ny) = (-(q.1 - p.1), q.0 - p.0);
            if interval_gap(a, b, nx, ny) != 0.0 {
                return false;
            }
        }
    }
    true
}

/// Shortest distance between two boxes (0 when they overlap).
pub(crate) fn box_distance(a: &[(f64, f64); 4], b: &[(f64, f64); 4]) -> f64 {
    if boxes_overlap(a, b) {
        return 0.0;
    }
    let mut d = f64::MAX;
    for i in 0..4 {
        for j in 0..4 {
            d = d.min(seg_point_dist(a[i], b[j], b[(j + 1) % 4]));
            d = d.min(seg_point_dist(b[j], a[i], a[(i + 1) % 4]));
        }
    }
    d
}
