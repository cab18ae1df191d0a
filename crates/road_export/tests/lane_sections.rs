//! Lanelets cut into lane sections: a neighbour that starts or ends beside a lanelet cuts it
//! there, so that side-by-side lanelets of different lengths stay neighbours (lanes of one
//! section) and read back as a chain that compares as the lanelet it came from.

use crate::common::read_back;
use commonroad::*;
use road_export::{export, round_trip, Options, Subject};

fn lanelet(id: u64, x0: f64, x1: f64, y_right: f64, y_left: f64) -> Lanelet {
    // from x0 to x1; the bounds are at y_left / y_right, points every 10 m
    let n = ((x1 - x0).abs() / 10.0).ceil().max(1.0) as usize;
    let xs: Vec<f64> = (0..=n).map(|k| x0 + (x1 - x0) * k as f64 / n as f64).collect();
    let side = |y: f64| xs.iter().map(|&x| Point::new(x, y)).collect::<Vec<_>>();
    let bounds = LaneletBounds::new(side(y_left), side(y_right)).expect("valid bounds");
    Lanelet::new(LaneletId::new(id).expect("id"), bounds, LaneletType::Urban)
}

fn id(n: u64) -> LaneletId {
    LaneletId::new(n).expect("id")
}

fn adjacent(n: u64, dir: DrivingDir) -> Option<Adjacent> {
    Some(Adjacent { lanelet: id(n), driving_dir: dir })
}

/// Makes `left` the left neighbour of `right` (and `right` the neighbour of `left` on the side
/// facing it: its left when it drives the other way).
fn side_by_side(right: &mut Lanelet, left: &mut Lanelet, dir: DrivingDir) {
    right.adjacent_left = adjacent(left.id.get(), dir);
    let back = adjacent(right.id.get(), dir);
    if dir == DrivingDir::Same {
        left.adjacent_right = back;
    } else {
        left.adjacent_left = back;
    }
}

/// Exports, reads back, compares; the comparison and the warnings.
fn round_trip_of(net: &LaneletNetwork) -> (round_trip::Comparison, Vec<road_export::Warning>) {
    let e = export(net, &Options::default()).expect("exports");
    let c = round_trip::compare(net, &read_back(&e.xodr));
    (c, e.warnings)
}

/// The round trip of `net`, asserted to pass and to keep all its `relations` (neighbours,
/// successors).
fn round_trip_keeping(net: &LaneletNetwork, relations: usize) -> (round_trip::Comparison, Vec<road_export::Warning>) {
    let (c, warnings) = round_trip_of(net);
    assert!(c.passes(0.05, 0.01), "{:?}", c.failures(0.05));
    assert_eq!((c.relations_kept, c.relations), (relations, relations));
    (c, warnings)
}

#[test]
fn a_lane_that_begins_beside_a_longer_one_stays_its_neighbour() {
    // lanelet 2 begins 45 m along lanelet 1, on its left, and both end together; 3 follows 1
    let mut long = lanelet(1, 0.0, 100.0, 0.0, 3.5);
    let mut short = lanelet(2, 45.0, 100.0, 3.5, 7.0);
    let mut next = lanelet(3, 100.0, 150.0, 0.0, 3.5);
    side_by_side(&mut long, &mut short, DrivingDir::Same);
    long.successors = vec![id(3)];
    next.predecessors = vec![id(1)];
    let net = LaneletNetwork { lanelets: vec![long, short, next], ..Default::default() };
    let (c, warnings) = round_trip_keeping(&net, 4);
    // lanelet 1 comes back as two pieces
    let pieces = c.lanelets.iter().find(|l| l.id == 1).map_or(0, |l| l.matched.len());
    assert_eq!(pieces, 2);
    // warnings name the lanelets of the input, never a piece
    assert!(warnings.iter().all(|w| !matches!(w.subject, Subject::Lanelet(n) if n > 3)), "{warnings:?}");
}

#[test]
fn staggered_lanelets_of_opposite_directions_stay_neighbours() {
    // 1 drives +x over [0, 100]; 2 drives −x on its left over [130, 40]
    let mut a = lanelet(1, 0.0, 100.0, 0.0, 3.5);
    let mut b = lanelet(2, 130.0, 40.0, 7.0, 3.5);
    side_by_side(&mut a, &mut b, DrivingDir::Opposite);
    let net = LaneletNetwork { lanelets: vec![a, b], ..Default::default() };
    round_trip_keeping(&net, 2);
}

#[test]
fn a_sign_stays_on_the_piece_where_it_stands() {
    let mut long = lanelet(1, 0.0, 100.0, 0.0, 3.5);
    let mut short = lanelet(2, 50.0, 100.0, 3.5, 7.0);
    side_by_side(&mut long, &mut short, DrivingDir::Same);
    let sign_id = TrafficSignId::new(10).expect("id");
    long.traffic_sign_refs = vec![sign_id];
    let element = TrafficSignElement { sign_id: "274".into(), additional_values: vec!["13.89".into()] };
    let sign = TrafficSign { id: sign_id, elements: vec![element], position: Some(Point::new(20.0, -1.0)), is_virtual: false };
    let net = LaneletNetwork { lanelets: vec![long, short], traffic_signs: vec![sign], ..Default::default() };
    let e = export(&net, &Options::default()).expect("exports");
    // written where it stands, not moved into another piece's section
    assert!(e.warnings.iter().all(|w| !w.message.contains("moved")), "{:?}", e.warnings);
    assert!(e.xodr.contains("id=\"10\""), "{}", e.xodr);
}

#[test]
fn neighbours_that_meet_halfway_are_neighbours_from_there_on() {
    // 2 runs 2 m left of 1 and meets it at x = 40, sharing its bound from there; 3 lies on
    // the right of 1 all along, so the cut of 1 cuts 3 in turn
    let mut a = lanelet(1, 0.0, 100.0, 0.0, 3.5);
    let gap = |x: f64| 2.0 * (1.0 - x / 40.0).max(0.0);
    let xs: Vec<f64> = (0..=20).map(|k| f64::from(k) * 5.0).collect();
    let side = |off: f64| xs.iter().map(|&x| Point::new(x, 3.5 + gap(x) + off)).collect::<Vec<_>>();
    let mut b = Lanelet::new(id(2), LaneletBounds::new(side(3.5), side(0.0)).expect("bounds"), LaneletType::Urban);
    let mut c = lanelet(3, 0.0, 100.0, -3.5, 0.0);
    side_by_side(&mut a, &mut b, DrivingDir::Same);
    side_by_side(&mut c, &mut a, DrivingDir::Same);
    let net = LaneletNetwork { lanelets: vec![a, b, c], ..Default::default() };
    round_trip_keeping(&net, 4);
}

#[test]
fn a_neighbour_beside_no_piece_is_a_warning() {
    // 2 cuts 1 in two; 3 is called 1's right neighbour but lies 3 m away from it
    let mut long = lanelet(1, 0.0, 100.0, 0.0, 3.5);
    let mut short = lanelet(2, 50.0, 100.0, 3.5, 7.0);
    let mut far = lanelet(3, 0.0, 100.0, -6.5, -3.0);
    side_by_side(&mut long, &mut short, DrivingDir::Same);
    side_by_side(&mut far, &mut long, DrivingDir::Same);
    let net = LaneletNetwork { lanelets: vec![long, short, far], ..Default::default() };
    let (c, warnings) = round_trip_of(&net);
    assert_eq!((c.relations_kept, c.relations), (2, 4));
    for (lanelet, side, other) in [(1, "right", 3), (3, "left", 1)] {
        let said = warnings
            .iter()
            .any(|w| w.subject == Subject::Lanelet(lanelet) && w.message.contains(&format!("adjacent {side} lanelet {other} lies beside no part")));
        assert!(said, "no warning about lanelet {lanelet}'s {side} neighbour: {warnings:?}");
    }
}

#[test]
fn a_fork_on_top_of_its_neighbour_is_its_neighbour_at_the_end() {
    // 1 forks into 2 (straight on) and 3, which starts on the same cross-section as 2 and
    // ends beside it on its right: their facing bounds meet only at the end (10 degrees
    // apart), yet CommonRoad calls them adjacent; 4 follows 2, 5 follows 3
    let mut before = lanelet(1, -20.0, 0.0, 0.0, 3.5);
    let mut straight = lanelet(2, 0.0, 20.0, 0.0, 3.5);
    let line = |pts: &[(f64, f64)]| pts.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
    let bounds = LaneletBounds::new(line(&[(0.0, 3.5), (10.0, 1.75), (20.0, 0.0)]), line(&[(0.0, 0.0), (10.0, -1.75), (20.0, -3.5)])).expect("valid bounds");
    let mut fork = Lanelet::new(id(3), bounds, LaneletType::Urban);
    let mut after_straight = lanelet(4, 20.0, 40.0, 0.0, 3.5);
    let bounds = LaneletBounds::new(line(&[(20.0, 0.0), (40.0, -3.5)]), line(&[(20.0, -3.5), (40.0, -7.0)])).expect("valid bounds");
    let mut after_fork = Lanelet::new(id(5), bounds, LaneletType::Urban);
    side_by_side(&mut fork, &mut straight, DrivingDir::Same);
    before.successors = vec![id(2), id(3)];
    (straight.predecessors, straight.successors) = (vec![id(1)], vec![id(4)]);
    (fork.predecessors, fork.successors) = (vec![id(1)], vec![id(5)]);
    after_straight.predecessors = vec![id(2)];
    after_fork.predecessors = vec![id(3)];
    let net = LaneletNetwork { lanelets: vec![before, straight, fork, after_straight, after_fork], ..Default::default() };
    let (c, warnings) = round_trip_keeping(&net, 10);
    // each comes back as the fork and a short end beside the other
    for n in [2, 3] {
        assert_eq!(c.lanelets.iter().find(|l| l.id == n).map_or(0, |l| l.matched.len()), 2, "lanelet {n}");
        let said = warnings.iter().any(|w| w.subject == Subject::Lanelet(n) && w.message.contains("overlaps it"));
        assert!(said, "lanelet {n}: {warnings:?}");
    }
}
