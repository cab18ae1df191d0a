//! Each shape against closed forms.

use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};
use trajectory::{Error, Path, Pose, SplineSegment};

fn p(x: f64, y: f64) -> Pose {
    Pose::new(x, y, 0.0, 0.0)
}
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}
fn angle_close(a: f64, b: f64, tol: f64) -> bool {
    let d = (a - b).rem_euclid(2.0 * PI);
    d.min(2.0 * PI - d) <= tol
}

#[test]
fn polyline_length_and_points_are_the_segment_sums() {
    let path = Path::polyline(&[(p(0.0, 0.0), None), (p(3.0, 4.0), None), (p(3.0, 14.0), None)], false).unwrap();
    assert!(close(path.length(), 15.0, 1e-12));
    let q = path.pose_at(2.5);
    assert!(close(q.x, 1.5, 1e-12) && close(q.y, 2.0, 1e-12));
    let q = path.pose_at(10.0);
    assert!(close(q.x, 3.0, 1e-12) && close(q.y, 9.0, 1e-12));
    // past the end clamps on an open path
    let q = path.pose_at(100.0);
    assert!(close(q.y, 14.0, 1e-12) && close(q.s, 15.0, 1e-12));
    assert!(!path.is_timed());
}

#[test]
fn polyline_heading_follows_segments_and_blends_corners_over_2m() {
    // (0,0) → (20,0) → (20,20): a left turn of π/2 at s = 20.
    let path = Path::polyline(&[(p(0.0, 0.0), None), (p(20.0, 0.0), None), (p(20.0, 20.0), None)], false).unwrap();
    assert!(angle_close(path.pose_at(10.0).heading, 0.0, 1e-12));
    assert!(angle_close(path.pose_at(30.0).heading, FRAC_PI_2, 1e-12));
    // at the corner half the turn; 1 m before it a quarter of the turn (linear over ±2 m, as
    // esmini 3.6.0 turns a polyline in position mode), 2 m before it none
    assert!(angle_close(path.pose_at(20.0).heading, PI / 4.0, 1e-12));
    assert!(angle_close(path.pose_at(19.0).heading, PI / 8.0, 1e-12));
    assert!(angle_close(path.pose_at(18.0).heading, 0.0, 1e-12));
    assert!(angle_close(path.pose_at(21.0).heading, 3.0 * PI / 8.0, 1e-12));
    assert!(close(path.pose_at(21.0).curvature, FRAC_PI_2 / 4.0, 1e-12));
    assert!(close(path.pose_at(10.0).curvature, 0.0, 1e-15));
    // no blending at the open ends
    assert!(angle_close(path.pose_at(1.0).heading, 0.0, 1e-12));
}

#[test]
fn timed_polyline_interpolates_linearly_and_waits_at_repeated_vertices() {
    let path = Path::polyline(&[(p(0.0, 0.0), Some(1.0)), (p(10.0, 0.0), Some(3.0)), (p(10.0, 0.0), Some(5.0)), (p(10.0, 30.0), Some(8.0))], false).unwrap();
    assert!(path.is_timed());
    assert_eq!(path.warnings.len(), 1, "{:?}", path.warnings);
    assert!(close(path.length(), 40.0, 1e-12));
    assert!(close(path.s_at_time(2.0).unwrap(), 5.0, 1e-12));
    assert!(close(path.s_at_time(4.0).unwrap(), 10.0, 1e-12)); // waiting
    assert!(close(path.s_at_time(6.5).unwrap(), 25.0, 1e-12));
    assert!(close(path.s_at_time(0.0).unwrap(), 0.0, 1e-12));
    assert!(close(path.s_at_time(99.0).unwrap(), 40.0, 1e-12));
    assert!(close(path.time_at(5.0).unwrap(), 2.0, 1e-12));
    assert!(close(path.time_at(10.0).unwrap(), 3.0, 1e-12)); // arrival time at the stop
    assert!(close(path.time_at(25.0).unwrap(), 6.5, 1e-12));
    assert_eq!(path.time_range(), Some((1.0, 8.0)));
}

#[test]
fn a_missing_polyline_time_stamp_is_time_0_with_a_warning() {
    // esmini's ScenarioReader reads a vertex without a time as 0
    let path = Path::polyline(&[(p(0.0, 0.0), Some(1.0)), (p(1.0, 0.0), None)], false).unwrap();
    assert_eq!(path.time_table().map(|t| t.points().to_vec()), Some(vec![(0.0, 1.0), (1.0, 0.0)]));
    assert_eq!(path.warnings.len(), 1);
}

#[test]
fn closed_polyline_adds_the_closing_segment_and_wraps() {
    let sq = [(p(0.0, 0.0), None), (p(10.0, 0.0), None), (p(10.0, 10.0), None), (p(0.0, 10.0), None)];
    let path = Path::polyline(&sq, true).unwrap();
    assert!(path.is_closed());
    assert!(close(path.length(), 40.0, 1e-12));
    let q = path.pose_at(35.0);
    assert!(close(q.x, 0.0, 1e-12) && close(q.y, 5.0, 1e-12));
    assert!(angle_close(q.heading, 3.0 * FRAC_PI_2, 1e-12));
    let q = path.pose_at(45.0); // second lap
    assert!(close(q.x, 5.0, 1e-12) && close(q.y, 0.0, 1e-12));
    // the corner at the start vertex blends with the closing segment
    assert!(angle_close(path.pose_at(0.0).heading, -PI / 4.0, 1e-12));
    let open = Path::polyline(&sq, false).unwrap();
    assert!(close(open.length(), 30.0, 1e-12));
}

/// Clothoid position by brute-force midpoint integration of the heading.
fn numeric_clothoid(x0: f64, y0: f64, h0: f64, k0: f64, dk: f64, s: f64) -> (f64, f64) {
    let n = 200_000;
    let ds = s / n as f64;
    let (mut x, mut y) = (x0, y0);
    for i in 0..n {
        let m = (i as f64 + 0.5) * ds;
        let h = h0 + k0 * m + 0.5 * dk * m * m;
        x += h.cos() * ds;
        y += h.sin() * ds;
    }
    (x, y)
}

#[test]
fn clothoid_matches_numeric_integration() {
    let start = Pose::new(5.0, -3.0, 1.5, 0.3);
    let (k0, dk, len) = (0.01, 0.002, 80.0);
    let path = Path::clothoid(start, k0, dk, len, (None, None), false).unwrap();
    assert!(close(path.length(), len, 1e-12));
    for s in [0.0, 7.3, 40.0, 63.25, 80.0] {
        let q = path.pose_at(s);
        let (x, y) = numeric_clothoid(5.0, -3.0, 0.3, k0, dk, s);
        assert!(close(q.x, x, 1e-6) && close(q.y, y, 1e-6), "s={s}: {q:?} vs ({x}, {y})");
        assert!(angle_close(q.heading, 0.3 + k0 * s + 0.5 * dk * s * s, 1e-12));
        assert!(close(q.curvature, k0 + dk * s, 1e-12));
        assert!(close(q.z, 1.5, 0.0));
    }
}

#[test]
fn constant_curvature_clothoid_is_a_circle_arc() {
    let r = 25.0;
    let path = Path::clothoid(p(0.0, 0.0), 1.0 / r, 0.0, PI * r, (Some(2.0), Some(12.0)), false).unwrap();
    let end = path.pose_at(PI * r);
    assert!(close(end.x, 0.0, 1e-9) && close(end.y, 2.0 * r, 1e-9), "{end:?}");
    assert!(angle_close(end.heading, PI, 1e-12));
    let mid = path.pose_at(FRAC_PI_2 * r);
    assert!(close(mid.x, r, 1e-9) && close(mid.y, r, 1e-9));
    // time spread linearly over the arc
    assert!(close(path.s_at_time(7.0).unwrap(), FRAC_PI_2 * r, 1e-9));
    assert!(close(path.time_at(PI * r).unwrap(), 12.0, 1e-12));
}

#[test]
fn clothoid_spline_chains_segments_and_restarts_at_given_positions() {
    let r = 10.0;
    let arc = FRAC_PI_2 * r;
    let segs = [
        SplineSegment { start: None, curvature_start: 1.0 / r, curvature_end: 1.0 / r, length: arc, h_offset: 0.0, time_start: Some(0.0) },
        SplineSegment { start: None, curvature_start: 0.0, curvature_end: 0.0, length: 5.0, h_offset: 0.0, time_start: Some(2.0) },
        SplineSegment { start: Some(p(100.0, 0.0)), curvature_start: 0.0, curvature_end: 0.0, length: 10.0, h_offset: FRAC_PI_2, time_start: Some(3.0) },
    ];
    let path = Path::clothoid_spline(p(0.0, 0.0), &segs, Some(5.0), false).unwrap();
    assert!(close(path.length(), arc + 15.0, 1e-12));
    // esmini's polyline has a vertex every whole metre, exactly on the curve.
    // quarter circle left ends at (r, r) heading north, then 5 m north: s = 20 is 20 − arc north
    let q = path.pose_at(20.0);
    assert!(close(q.x, r, 1e-8) && close(q.y, r + 20.0 - arc, 1e-8), "{q:?}");
    // third segment starts at its own position, heading offset by π/2: s = 25 is 25 − arc − 5 north of it
    let q = path.pose_at(25.0);
    assert!(close(q.x, 100.0, 1e-9) && close(q.y, 25.0 - arc - 5.0, 1e-9), "{q:?}");
    assert!(close(path.s_at_time(4.0).unwrap(), arc + 10.0, 1e-9));
}

#[test]
fn clothoid_spline_zero_length_segment_is_skipped_with_warning() {
    let segs = [
        SplineSegment { start: None, curvature_start: 0.0, curvature_end: 0.0, length: 0.0, h_offset: 0.0, time_start: None },
        SplineSegment { start: None, curvature_start: 0.0, curvature_end: 0.0, length: 3.0, h_offset: 0.0, time_start: None },
    ];
    let path = Path::clothoid_spline(p(1.0, 1.0), &segs, None, false).unwrap();
    assert_eq!(path.warnings.len(), 1);
    assert!(close(path.pose_at(3.0).x, 4.0, 1e-12));
    let only_zero = [segs[0]];
    assert_eq!(Path::clothoid_spline(p(0.0, 0.0), &only_zero, None, false), Err(Error::ZeroLength { shape: "ClothoidSpline" }));
}

/// Quarter circle as a rational quadratic: (r,0), (r,r) with weight √2/2, (0,r).
fn circle_nurbs(r: f64) -> Path {
    let w = SQRT_2 / 2.0;
    let cps = [
        (p(r, 0.0), Some(1.0), None),
        (p(r, r), Some(w), None),
        (p(0.0, r), Some(1.0), None),
        (p(-r, r), Some(w), None),
        (p(-r, 0.0), Some(1.0), None),
        (p(-r, -r), Some(w), None),
        (p(0.0, -r), Some(1.0), None),
        (p(r, -r), Some(w), None),
        (p(r, 0.0), Some(1.0), None),
    ];
    let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
    Path::nurbs(3, &cps, &knots, false).unwrap()
}

#[test]
fn nurbs_full_circle_lies_on_the_circle() {
    let r = 12.0;
    let path = circle_nurbs(r);
    // esmini's length is that of a polyline through ~1 sample per metre of control polygon:
    // inscribed in the circle, so a little shorter than the circumference.
    assert!(path.length() <= 2.0 * PI * r && path.length() > 2.0 * PI * r * (1.0 - 1e-3), "{}", path.length());
    for i in 0..=200 {
        let q = path.pose_at(path.length() * i as f64 / 200.0);
        // esmini's NurbsShape::EvaluateInternal leaves control points of basis value ≤ 1e-6
        // out of the position's sum (not out of the weight), so just past a knot the point
        // sits up to about 1e-6 of the radius inside the circle: 8.4e-6 m here.
        assert!(close(q.x.hypot(q.y), r, 2e-5), "{q:?}");
        // tangent perpendicular to the radius, counter-clockwise; the first sample borrows the
        // heading of the second (esmini), so the first metre or so is off by up to one step's turn
        let expect = q.y.atan2(q.x) + FRAC_PI_2;
        if q.s > 1.5 {
            assert!(angle_close(q.heading, expect, 2e-3), "{q:?}");
            assert!(close(q.curvature, 1.0 / r, 5e-3), "{q:?}");
        } else {
            assert!(angle_close(q.heading, expect, 0.1), "{q:?}");
        }
    }
}

#[test]
fn nurbs_with_clamped_knots_interpolates_the_end_control_points() {
    let cps = [(p(0.0, 0.0), None, None), (p(10.0, 20.0), Some(2.0), None), (p(30.0, -5.0), None, None), (p(40.0, 10.0), None, None)];
    let path = Path::nurbs(3, &cps, &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], false).unwrap();
    let a = path.pose_at(0.0);
    let b = path.pose_at(path.length());
    assert!(close(a.x, 0.0, 1e-12) && close(a.y, 0.0, 1e-12));
    // the end is evaluated just inside the last knot (less esmini's SMALL_NUMBER, 1e-6), as
    // esmini does: tens of µm short of the last control point
    assert!(close(b.x, 40.0, 1e-4) && close(b.y, 10.0, 1e-4), "{b:?}");
    // end tangents point along the first and last legs of the control polygon; the start takes
    // the heading of the second sample (about 1 m on), as esmini does, so only roughly
    assert!(angle_close(a.heading, 20f64.atan2(10.0), 0.1));
    // (the last heading is probed 0.001 back in the parameter)
    assert!(angle_close(b.heading, 15f64.atan2(10.0), 5e-3), "{b:?}");
}

#[test]
fn nurbs_times_follow_control_point_peaks() {
    // Order 2 (a polyline): basis of point i peaks exactly at its knot, so time is linear
    // in the parameter between control points, and the parameter is linear in s per leg.
    // Control polygon 39.5 m: floor(1 + 39.5) = 40 samples, Δu = 0.05, so the corner (u = 1)
    // is sample 20 and the sampled polyline is the polygon itself.
    let cps = [(p(0.0, 0.0), None, Some(0.0)), (p(10.0, 0.0), None, Some(1.0)), (p(10.0, 29.5), None, Some(4.0))];
    let path = Path::nurbs(2, &cps, &[0.0, 0.0, 1.0, 2.0, 2.0], false).unwrap();
    // (up to the last knot less esmini's SMALL_NUMBER, 1e-6: 29.5 µm short)
    assert!(close(path.length(), 39.5, 1e-4), "{}", path.length());
    assert!(close(path.s_at_time(0.5).unwrap(), 5.0, 1e-6));
    // t = 2.5 is halfway from 1 s to 4 s: u = 1.5, s = 10 + 29.5 / 2
    assert!(close(path.s_at_time(2.5).unwrap(), 24.75, 1e-6));
    assert!(close(path.time_at(path.length()).unwrap(), 4.0, 1e-9));
}

#[test]
fn closest_s_finds_the_projection() {
    let path = Path::polyline(&[(p(0.0, 0.0), None), (p(100.0, 0.0), None)], false).unwrap();
    assert!(close(path.closest_s(37.3, 5.0), 37.3, 1e-6));
    let circle = circle_nurbs(10.0);
    let s = circle.closest_s(0.0, 20.0);
    assert!(close(s, circle.length() / 4.0, 1e-3), "{s}");
    let q = circle.pose_at(s);
    let (ox, oy) = q.offset(-2.0); // 2 m to the right of a CCW circle: outward
    assert!(close(ox.hypot(oy), 12.0, 1e-6));
}
