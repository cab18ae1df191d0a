//! Degenerate and hostile input: errors, never panics.

use openscenario::model::{ControlPoint, Position, Shape, Vertex};
use proptest::prelude::*;
use trajectory::{Error, Path, Pose, TimeDomain, TimeMapping};

fn p(x: f64, y: f64) -> Pose {
    Pose::new(x, y, 0.0, 0.0)
}

#[test]
fn too_few_vertices_and_bad_numbers_are_errors() {
    assert!(matches!(Path::polyline(&[(p(0.0, 0.0), None)], false), Err(Error::TooFew { .. })));
    assert!(matches!(Path::polyline(&[(p(0.0, 0.0), None), (p(f64::NAN, 1.0), None)], false), Err(Error::BadNumber { .. })));
}

#[test]
fn coincident_vertices_make_a_path_without_length_as_in_esmini() {
    // esmini keeps the entity at the point for the time the stamps span
    let path = Path::polyline(&[(p(1.0, 1.0), Some(0.0)), (p(1.0, 1.0), Some(3.0))], false).expect("a path");
    assert_eq!(path.length(), 0.0);
    assert_eq!(path.time_range(), Some((0.0, 3.0)));
    let at = path.pose_at(0.5);
    assert_eq!((at.x, at.y), (1.0, 1.0));
    assert!(path.warnings.iter().any(|w| w.contains("one point")), "{:?}", path.warnings);
}

#[test]
fn polyline_times_are_taken_as_written() {
    // esmini walks the vertices for a time and reads a missing stamp as 0
    let path = Path::polyline(&[(p(0.0, 0.0), Some(2.0)), (p(1.0, 0.0), Some(1.0))], false).expect("a path");
    assert_eq!(path.time_table().map(|t| t.points().to_vec()), Some(vec![(0.0, 2.0), (1.0, 1.0)]));
    let partial = Path::polyline(&[(p(0.0, 0.0), None), (p(1.0, 0.0), Some(1.0))], false).expect("a path");
    assert_eq!(partial.time_table().map(|t| t.points().to_vec()), Some(vec![(0.0, 0.0), (1.0, 1.0)]));
}

#[test]
fn clothoid_bad_numbers_are_errors() {
    assert!(matches!(Path::clothoid(p(0.0, 0.0), 0.1, 0.0, 0.0, (None, None), false), Err(Error::ZeroLength { .. })));
    assert!(matches!(Path::clothoid(p(0.0, 0.0), 0.1, 0.0, -5.0, (None, None), false), Err(Error::BadNumber { .. })));
    assert!(matches!(Path::clothoid(p(0.0, 0.0), f64::INFINITY, 0.0, 5.0, (None, None), false), Err(Error::BadNumber { .. })));
    assert!(matches!(Path::clothoid(p(0.0, 0.0), 0.0, 0.0, 1e9, (None, None), false), Err(Error::BadNumber { .. })));
    // stop before start
    assert!(matches!(Path::clothoid(p(0.0, 0.0), 0.0, 0.0, 5.0, (Some(3.0), Some(1.0)), false), Err(Error::NotMonotone { .. })));
}

#[test]
fn nurbs_structural_errors() {
    let cps = [(p(0.0, 0.0), None, None), (p(1.0, 0.0), None, None), (p(2.0, 1.0), None, None)];
    assert_eq!(Path::nurbs(3, &cps, &[0.0, 0.0, 0.0, 1.0, 1.0], false), Err(Error::KnotCount { expected: 6, found: 5 }));
    assert!(matches!(Path::nurbs(3, &cps, &[0.0, 0.0, 1.0, 0.5, 1.0, 1.0], false), Err(Error::NotMonotone { .. })));
    assert!(matches!(Path::nurbs(4, &cps, &[0.0; 7], false), Err(Error::BadOrder { .. })));
    assert!(matches!(Path::nurbs(1, &cps, &[0.0, 1.0, 2.0, 3.0], false), Err(Error::BadOrder { .. })));
    assert_eq!(Path::nurbs(3, &cps, &[1.0; 6], false), Err(Error::EmptyDomain));
    let bad_w = [(p(0.0, 0.0), Some(0.0), None), (p(1.0, 0.0), None, None), (p(2.0, 1.0), None, None)];
    assert!(matches!(Path::nurbs(3, &bad_w, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], false), Err(Error::BadNumber { .. })));
    let same = [(p(1.0, 1.0), None, None), (p(1.0, 1.0), None, None), (p(1.0, 1.0), None, None)];
    assert_eq!(Path::nurbs(3, &same, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], false), Err(Error::ZeroLength { shape: "NURBS" }));
    assert!(matches!(Path::nurbs(2, &cps[..1], &[0.0, 0.0, 1.0], false), Err(Error::TooFew { .. })));
}

fn world(x: f64, y: f64) -> Position {
    Position::World { x, y, z: None, h: None, p: None, r: None }
}

fn resolver(pos: &Position) -> Option<Pose> {
    match pos {
        Position::World { x, y, .. } if *x >= 0.0 => Some(Pose::new(*x, *y, 0.0, 0.0)),
        _ => None,
    }
}

#[test]
fn from_shape_resolves_through_the_closure_and_reports_failures() {
    let shape = Shape::Polyline(vec![Vertex { time: Some(0.0), position: world(0.0, 0.0) }, Vertex { time: Some(2.0), position: world(6.0, 8.0) }]);
    let path = Path::from_shape(&shape, false, Pose::default(), &resolver).unwrap();
    assert!((path.length() - 10.0).abs() < 1e-12);
    assert!((path.s_at_time(1.0).unwrap() - 5.0).abs() < 1e-12);
    let bad = Shape::Polyline(vec![Vertex { time: None, position: world(0.0, 0.0) }, Vertex { time: None, position: world(-1.0, 0.0) }]);
    assert_eq!(Path::from_shape(&bad, false, Pose::default(), &resolver), Err(Error::Unresolved { shape: "Polyline", what: "vertex 1".into() }));
    // a clothoid without position starts at the entity's pose
    let cl = Shape::Clothoid { curvature: 0.0, curvature_prime: 0.0, length: 5.0, start_time: None, stop_time: None, position: None };
    let path = Path::from_shape(&cl, false, Pose::new(1.0, 2.0, 0.0, std::f64::consts::FRAC_PI_2), &resolver).unwrap();
    let end = path.pose_at(5.0);
    assert!((end.x - 1.0).abs() < 1e-12 && (end.y - 7.0).abs() < 1e-12);
    let nurbs = Shape::Nurbs {
        order: 2,
        control_points: vec![
            ControlPoint { time: None, weight: None, position: world(0.0, 0.0) },
            ControlPoint { time: None, weight: None, position: world(3.0, 4.0) },
        ],
        knots: vec![0.0, 0.0, 1.0, 1.0],
    };
    let path = Path::from_shape(&nurbs, false, Pose::default(), &resolver).unwrap();
    // evaluated up to the last knot less esmini's SMALL_NUMBER (1e-6): 5 m less 5 µm
    assert!((path.length() - 5.0).abs() < 1e-5, "{}", path.length());
}

#[test]
fn time_mapping_relative_and_absolute() {
    let rel = TimeMapping { domain: TimeDomain::Relative, scale: 2.0, offset: 1.0 };
    assert_eq!(rel.trajectory_time(13.0, 10.0), 7.0);
    assert_eq!(rel.simulation_time(7.0, 10.0), Some(13.0));
    let abs = TimeMapping { domain: TimeDomain::Absolute, scale: 0.5, offset: -1.0 };
    assert_eq!(abs.trajectory_time(4.0, 99.0), 1.0);
    assert_eq!(abs.simulation_time(1.0, 99.0), Some(4.0));
    assert_eq!(TimeMapping { domain: TimeDomain::Absolute, scale: 0.0, offset: 0.0 }.simulation_time(1.0, 0.0), None);
}

fn num() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -1e3f64..1e3,
        1 => Just(0.0),
        1 => prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300, 1e-300]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn polyline_never_panics(pts in prop::collection::vec((num(), num(), prop::option::of(num())), 0..8), closed: bool, s in num(), t in num()) {
        let v: Vec<(Pose, Option<f64>)> = pts.iter().map(|(x, y, t)| (p(*x, *y), *t)).collect();
        if let Ok(path) = Path::polyline(&v, closed) {
            let q = path.pose_at(s);
            prop_assert!(q.x.is_finite() && q.y.is_finite() && q.heading.is_finite());
            let _ = path.time_at(s);
            let _ = path.s_at_time(t);
        }
    }

    #[test]
    fn clothoid_spline_never_panics(segs in prop::collection::vec((num(), num(), num(), num()), 0..5), s in num()) {
        let segs: Vec<trajectory::SplineSegment> = segs.iter().map(|(a, b, l, h)| trajectory::SplineSegment {
            start: None, curvature_start: *a, curvature_end: *b, length: *l, h_offset: *h, time_start: None,
        }).collect();
        if let Ok(path) = Path::clothoid_spline(p(0.0, 0.0), &segs, None, false) {
            let _ = path.pose_at(s);
        }
    }

    #[test]
    fn nurbs_never_panics(order in 0u32..6, pts in prop::collection::vec((num(), num(), prop::option::of(num()), prop::option::of(num())), 0..7),
                          knots in prop::collection::vec(num(), 0..14), s in num(), t in num()) {
        let cps: Vec<(Pose, Option<f64>, Option<f64>)> = pts.iter().map(|(x, y, w, tt)| (p(*x, *y), *w, *tt)).collect();
        if let Ok(path) = Path::nurbs(order, &cps, &knots, false) {
            let q = path.pose_at(s);
            prop_assert!(q.heading.is_finite());
            let _ = path.s_at_time(t);
            let _ = path.closest_s(s, t);
        }
    }

    #[test]
    fn sorted_knots_give_a_curve_inside_the_control_hull(order in 2u32..5, pts in prop::collection::vec((-100f64..100.0, -100f64..100.0, 0.1f64..10.0), 5..8), frac in 0f64..1.0) {
        let n = pts.len();
        let k = order as usize;
        // clamped uniform knots
        let inner = n - k;
        let mut knots = vec![0.0; k];
        knots.extend((1..=inner).map(|i| i as f64));
        knots.extend(std::iter::repeat_n((inner + 1) as f64, k));
        let cps: Vec<(Pose, Option<f64>, Option<f64>)> = pts.iter().map(|(x, y, w)| (p(*x, *y), Some(*w), None)).collect();
        if let Ok(path) = Path::nurbs(order, &cps, &knots, false) {
            let q = path.pose_at(frac * path.length());
            let (minx, maxx) = pts.iter().fold((f64::MAX, f64::MIN), |a, p| (a.0.min(p.0), a.1.max(p.0)));
            let (miny, maxy) = pts.iter().fold((f64::MAX, f64::MIN), |a, p| (a.0.min(p.1), a.1.max(p.1)));
            // positive weights: convex-hull property, so inside the bounding box
            prop_assert!(q.x >= minx - 1e-9 && q.x <= maxx + 1e-9 && q.y >= miny - 1e-9 && q.y <= maxy + 1e-9);
        }
    }
}
