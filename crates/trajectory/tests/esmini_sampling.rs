//! esmini's sampling of ClothoidSpline shapes: a polyline with a vertex every metre of arc
//! length, the true end placed at the last whole metre.

use trajectory::{Path, Pose, SplineSegment};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn straight(length: f64) -> SplineSegment {
    SplineSegment { start: None, curvature_start: 0.0, curvature_end: 0.0, length, h_offset: 0.0, time_start: None }
}

#[test]
fn the_last_metre_covers_the_fractional_rest() {
    // 15.5 m straight along +x: vertices at x = 0..14 (s = x), the end x = 15.5 at s = 15.
    let start = Pose { x: 0.0, y: 0.0, z: 0.0, heading: 0.0 };
    let path = Path::clothoid_spline(start, &[straight(15.5)], None, false).unwrap();
    assert!(close(path.length(), 15.5, 1e-12));
    assert!(close(path.pose_at(7.25).x, 7.25, 1e-9));
    // halfway through the last metre: 14 + 0.5 · 1.5
    assert!(close(path.pose_at(14.5).x, 14.75, 1e-9));
    // beyond s = 15 the path stays at its end
    assert!(close(path.pose_at(15.2).x, 15.5, 1e-9));
    assert!(close(path.pose_at(15.5).x, 15.5, 1e-9));
}

#[test]
fn positions_between_vertices_are_chords_of_the_arc() {
    // A quarter circle of radius 10 (length 5π): the point at s = 0.5 lies halfway along the
    // chord from the start to the point 1 m along the arc, inside the circle.
    let start = Pose { x: 0.0, y: 0.0, z: 0.0, heading: 0.0 };
    let k = 0.1;
    let seg = SplineSegment { start: None, curvature_start: k, curvature_end: k, length: 5.0 * std::f64::consts::PI, h_offset: 0.0, time_start: None };
    let path = Path::clothoid_spline(start, &[seg], None, false).unwrap();
    let (x1, y1) = (10.0 * (0.1f64).sin(), 10.0 - 10.0 * (0.1f64).cos());
    let q = path.pose_at(0.5);
    assert!(close(q.x, 0.5 * x1, 1e-6) && close(q.y, 0.5 * y1, 1e-6), "{q:?}");
    // the heading turns linearly: half of the 0.1 rad turned over the first metre
    assert!(close(q.heading, 0.05, 1e-6), "{q:?}");
}
