//! Joints and free road ends whose end points lie on no straight line, sliced (`joints.rs`,
//! `free_ends.rs`): the end of an intersection's connecting road of four lanes that fans out
//! into two roads, its lanes ending on two lines at an angle (`test_reading_complex_tl`'s
//! five-lane connecting road 3667 … 3610, whose ends lie 1.46 m off any straight line), and a
//! road of two lanes each way whose free end is bowed (the generator's intersection arms).

use crate::common::read_back;
use commonroad::*;
use road_export::{export, round_trip, Options};

fn id(n: u64) -> LaneletId {
    LaneletId::new(n).expect("id")
}

/// A lanelet between two polylines, points every metre or so.
fn lanelet(id_: u64, left: &[(f64, f64)], right: &[(f64, f64)], kind: LaneletType) -> Lanelet {
    let pts = |v: &[(f64, f64)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
    let bounds = LaneletBounds::new(pts(left), pts(right)).expect("valid bounds");
    Lanelet::new(id(id_), bounds, kind)
}

/// A straight bound from `a` along `dir` (a unit vector) for `len` m, a point a metre.
fn ray(a: (f64, f64), dir: (f64, f64), len: f64) -> Vec<(f64, f64)> {
    (0..=len as usize).map(|k| (a.0 + dir.0 * k as f64, a.1 + dir.1 * k as f64)).collect()
}

fn neighbours(net: &mut [Lanelet], right: usize, left: usize) {
    let (r, l) = (net[right].id, net[left].id);
    net[right].adjacent_left = Some(Adjacent { lanelet: l, driving_dir: DrivingDir::Same });
    net[left].adjacent_right = Some(Adjacent { lanelet: r, driving_dir: DrivingDir::Same });
}

fn link(net: &mut [Lanelet], from: usize, to: usize) {
    let (f, t) = (net[from].id, net[to].id);
    net[from].successors.push(t);
    net[to].predecessors.push(f);
}

#[test]
fn a_connecting_road_that_fans_out_on_a_bent_end_round_trips() {
    // four lanes along +x; the connecting lanelets end on line A (lanes 1 and 2, from
    // (60.5, 0) to (62, 7)) and line B (lanes 3 and 4, from (62, 7) to (60.8, 14)): a bent
    // end 1.35 m off the line through its outer ends, its two lines 22° apart, as in
    // test_reading_complex_tl. Lanes 1 and 2 go on into road A (turned 12° right), lanes 3
    // and 4 into road B (turned 10° left); the two roads are not neighbours.
    let on_a = |y: f64| (60.5 + 1.5 * y / 7.0, y);
    let on_b = |y: f64| (62.0 - 0.6 * (y - 7.0) / 3.5, y);
    let (da, db) = ((7.0 / 51.25f64.sqrt(), -1.5 / 51.25f64.sqrt()), (3.5 / 12.61f64.sqrt(), 0.6 / 12.61f64.sqrt()));
    let x_run = |x0: f64, x1: f64, y: f64| -> Vec<(f64, f64)> { (0..=12).map(|k| (x0 + (x1 - x0) * f64::from(k) / 12.0, y)).collect() };
    let ys = [0.0, 3.5, 7.0, 10.5, 14.0];
    let end = |y: f64| if y <= 7.0 { on_a(y).0 } else { on_b(y).0 };
    let mut l = Vec::new();
    for k in 0..4 {
        let (yr, yl) = (ys[k], ys[k + 1]);
        l.push(lanelet(1 + k as u64, &x_run(0.0, 50.0, yl), &x_run(0.0, 50.0, yr), LaneletType::Urban));
        let mut c = lanelet(11 + k as u64, &x_run(50.0, end(yl), yl), &x_run(50.0, end(yr), yr), LaneletType::Urban);
        c.lanelet_types.push(LaneletType::Intersection);
        l.push(c);
        let (pl, pr, d) = if k < 2 { (on_a(yl), on_a(yr), da) } else { (on_b(yl), on_b(yr), db) };
        l.push(lanelet(21 + k as u64, &ray(pl, d, 30.0), &ray(pr, d, 30.0), LaneletType::Urban));
    }
    // indices: lane k's incoming 3k, connecting 3k+1, outgoing 3k+2
    for k in 0..4 {
        link(&mut l, 3 * k, 3 * k + 1);
        link(&mut l, 3 * k + 1, 3 * k + 2);
    }
    for k in 0..3 {
        neighbours(&mut l, 3 * k, 3 * k + 3);
        neighbours(&mut l, 3 * k + 1, 3 * k + 4);
    }
    neighbours(&mut l, 2, 5); // road A's two lanes
    neighbours(&mut l, 8, 11); // road B's
    let intersection = Intersection {
        id: IntersectionId::new(100).expect("id"),
        incomings: vec![Incoming {
            id: IncomingId::new(101).expect("id"),
            incoming_lanelets: vec![id(1), id(2), id(3), id(4)],
            successors_right: vec![],
            successors_straight: vec![id(11), id(12), id(13), id(14)],
            successors_left: vec![],
            is_left_of: None,
        }],
        crossings: vec![],
    };
    let net = LaneletNetwork { lanelets: l, intersections: vec![intersection], ..Default::default() };
    let e = export(&net, &Options::default()).expect("exports");
    let c = round_trip::compare(&net, &read_back(&e.xodr));
    // before: one lane section ended on a straight line covering the bent end, so the
    // connecting lanelets of the outer lanes came back up to 1.5 m longer and matched nothing
    assert!(c.passes(0.05, 0.01), "{:?}", c.failures(0.05));
    assert_eq!(c.relations_kept, c.relations);
    assert!(e.xodr.contains("type=\"default\""), "still a junction of the intersection");
}

#[test]
fn a_bowed_free_end_round_trips() {
    // three lanes each way along x, from a bowed end x = 1.5 (y / 10.5)² (the middle 1.5 m
    // ahead of the outer edges; the outer lanes' own ends slanted by 0.83 m) to x = 60;
    // lanes 1, 2, 3 drive +x (y from -10.5 to 0), lanes 4, 5, 6 drive -x
    let bow = |y: f64| 1.5 * (y / 10.5) * (y / 10.5);
    let along = |y: f64, forward: bool| -> Vec<(f64, f64)> {
        let x0 = bow(y);
        let v: Vec<(f64, f64)> = (0..=12).map(|k| (x0 + (60.0 - x0) * f64::from(k) / 12.0, y)).collect();
        if forward {
            v
        } else {
            v.into_iter().rev().collect()
        }
    };
    let mut l = Vec::new();
    for k in 0..3u64 {
        // lane k + 1 drives +x between y = -10.5 + 3.5 k and 3.5 above; lane k + 4 mirrors it
        let (yr, yl) = (-10.5 + 3.5 * k as f64, -7.0 + 3.5 * k as f64);
        l.push(lanelet(k + 1, &along(yl, true), &along(yr, true), LaneletType::Urban));
    }
    for k in 0..3u64 {
        let (yl, yr) = (3.5 * k as f64, 3.5 * (k + 1) as f64);
        l.push(lanelet(k + 4, &along(yl, false), &along(yr, false), LaneletType::Urban));
    }
    neighbours(&mut l, 0, 1);
    neighbours(&mut l, 1, 2);
    neighbours(&mut l, 4, 3); // lane 5's left is lane 4 (both drive -x)
    neighbours(&mut l, 5, 4);
    l[2].adjacent_left = Some(Adjacent { lanelet: id(4), driving_dir: DrivingDir::Opposite });
    l[3].adjacent_left = Some(Adjacent { lanelet: id(3), driving_dir: DrivingDir::Opposite });
    let net = LaneletNetwork { lanelets: l, ..Default::default() };
    let e = export(&net, &Options::default()).expect("exports");
    let c = round_trip::compare(&net, &read_back(&e.xodr));
    // before: the road's lane section began on a straight line holding the whole bow, so the
    // outer lanes came back 1.5 m longer and matched nothing
    assert!(c.passes(0.05, 0.01), "{:?}", c.failures(0.05));
    assert_eq!(c.relations_kept, c.relations);
}
