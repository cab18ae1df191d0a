//! Hostile lanelets: no panic, and a warning or an error naming the lanelet.

use commonroad::*;
use road_export::{export, Error, Options, Subject};

fn lanelet(id: u64, left: Vec<Point>, right: Vec<Point>) -> Lanelet {
    Lanelet::new(LaneletId::new(id).expect("id"), LaneletBounds::new(left, right).expect("bounds"), LaneletType::Urban)
}

fn good(id: u64) -> Lanelet {
    lanelet(id, vec![Point::new(0.0, 3.5), Point::new(50.0, 3.5)], vec![Point::new(0.0, 0.0), Point::new(50.0, 0.0)])
}

#[test]
fn the_model_refuses_what_cannot_be_a_lanelet() {
    assert!(LaneletBounds::new(vec![Point::new(f64::NAN, 0.0), Point::new(1.0, 0.0)], vec![Point::new(0.0, 1.0), Point::new(1.0, 1.0)]).is_err());
    assert!(LaneletBounds::new(vec![Point::new(0.0, 0.0)], vec![Point::new(0.0, 1.0)]).is_err());
}

#[test]
fn a_zero_length_lanelet_is_named_and_left_out() {
    let p = Point::new(5.0, 5.0);
    let zero = lanelet(7, vec![p, p, p], vec![p, p, p]);
    let e = export(&LaneletNetwork { lanelets: vec![zero.clone(), good(8)], ..Default::default() }, &Options::default()).expect("exports the good one");
    assert!(e.warnings.iter().any(|w| w.subject == Subject::Lanelet(7)), "{:?}", e.warnings);
    assert_eq!(e.xodr.matches("<road ").count(), 1);
    match export(&LaneletNetwork { lanelets: vec![zero], ..Default::default() }, &Options::default()) {
        Err(Error::NoRoads(w)) => assert!(w.iter().any(|w| w.subject == Subject::Lanelet(7))),
        other => panic!("expected NoRoads, got {other:?}"),
    }
}

#[test]
fn a_self_intersecting_lanelet_is_named() {
    // the bounds cross half way
    let l = lanelet(9, vec![Point::new(0.0, 3.0), Point::new(10.0, 0.0)], vec![Point::new(0.0, 0.0), Point::new(10.0, 3.0)]);
    let e = export(&LaneletNetwork { lanelets: vec![l], ..Default::default() }, &Options::default()).expect("exports");
    assert!(e.warnings.iter().any(|w| w.subject == Subject::Lanelet(9) && w.message.contains("intersects")), "{:?}", e.warnings);
}

#[test]
fn too_many_bound_points_is_an_error() {
    let n = road_export::MAX_BOUND_POINTS + 1;
    let left: Vec<Point> = (0..n).map(|i| Point::new(i as f64 * 1e-3, 3.0)).collect();
    let right: Vec<Point> = (0..n).map(|i| Point::new(i as f64 * 1e-3, 0.0)).collect();
    let net = LaneletNetwork { lanelets: vec![lanelet(1, left, right)], ..Default::default() };
    assert!(matches!(export(&net, &Options::default()), Err(Error::TooLarge { .. })));
}

/// A small deterministic generator (no dependency needed for a few hundred draws).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn random_lanelets_never_panic() {
    let mut r = Lcg(7);
    for round in 0..40 {
        let mut lanelets = Vec::new();
        for k in 0..(1 + (r.next() * 6.0) as u64) {
            let n = 2 + (r.next() * 12.0) as usize;
            let scale = [1e-4, 1.0, 100.0, 2e3][(r.next() * 4.0) as usize % 4];
            let mut left = Vec::new();
            let mut right = Vec::new();
            for _ in 0..n {
                let (x, y) = (r.next() * scale, r.next() * scale);
                left.push(Point::new(x, y));
                // sometimes the same point, sometimes far away
                let w = if r.next() < 0.2 { 0.0 } else { r.next() * scale };
                right.push(Point::new(x + w, y - w));
            }
            let mut l = lanelet(k + 1, left, right);
            if r.next() < 0.3 {
                l.adjacent_left = Some(Adjacent { lanelet: LaneletId::new(1 + (r.next() * 6.0) as u64).expect("id"), driving_dir: DrivingDir::Opposite });
            }
            if r.next() < 0.3 {
                l.successors = vec![LaneletId::new(1 + (r.next() * 6.0) as u64).expect("id")];
            }
            lanelets.push(l);
        }
        let net = LaneletNetwork { lanelets, ..Default::default() };
        if let Ok(e) = export(&net, &Options::default()) {
            assert!(opendrive::parse_str(&e.xodr, std::path::Path::new("r.xodr")).is_ok(), "round {round}: the export does not parse");
        }
    }
}
