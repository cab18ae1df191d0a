//! Driving direction (RHT and LHT), successor/predecessor and adjacency symmetry, link
//! continuity, zero-width lanes.

use crate::common::*;
use commonroad::{DrivingDir, Lanelet, LaneletId};
use std::collections::BTreeMap;

/// Fraction of segments where the left bound lies left of the driving direction.
fn left_is_left(l: &Lanelet) -> (usize, usize) {
    let (lb, rb) = (l.bounds.left(), l.bounds.right());
    let (mut ok, mut tot) = (0, 0);
    for i in 0..lb.len() - 1 {
        let c0 = ((lb[i].x + rb[i].x) / 2.0, (lb[i].y + rb[i].y) / 2.0);
        let c1 = ((lb[i + 1].x + rb[i + 1].x) / 2.0, (lb[i + 1].y + rb[i + 1].y) / 2.0);
        let (tx, ty) = (c1.0 - c0.0, c1.1 - c0.1);
        let (wx, wy) = (lb[i].x - rb[i].x, lb[i].y - rb[i].y);
        if tx.hypot(ty) < 1e-6 || wx.hypot(wy) < 1e-6 {
            continue;
        }
        tot += 1;
        if tx * wy - ty * wx > 0.0 {
            ok += 1;
        }
    }
    (ok, tot)
}

#[test]
fn lht_left_lanes_drive_along_s_and_left_bound_is_left() {
    let Some(p) = corpus("esmini/xodr/e6mini-lht.xodr") else { return };
    let net = load(&p);
    assert_eq!(net.roads[0].rule, opendrive::TrafficRule::LeftHand);
    let r = convert(&net);
    for (l, o) in r.network.lanelets.iter().zip(&r.origins) {
        // left-hand traffic: lanes with positive ids drive along s
        assert_eq!(o.along_s, o.lane.lane > 0, "lane {}", o.lane.lane);
        let (ok, tot) = left_is_left(l);
        assert!(tot > 0 && ok == tot, "lanelet {}: left bound left at {ok}/{tot} segments", l.id);
        // the first centre point lies at the lane's start in driving order
        let road = &net.roads[o.lane.road];
        let (s0, s1) = road.section_range(o.lane.section).unwrap();
        let s_start = if o.along_s { s0 } else { s1 };
        let c = net.lane_to_world(o.lane.road, o.lane.lane, s_start, 0.0).unwrap();
        let (a, b) = (l.bounds.left()[0], l.bounds.right()[0]);
        let d = ((a.x + b.x) / 2.0 - c.x).hypot((a.y + b.y) / 2.0 - c.y);
        assert!(d < 0.05, "lanelet {} starts {d} m from its lane's start", l.id);
    }
    // the same road under RHT drives the other way
    let Some(p) = corpus("esmini/xodr/e6mini.xodr") else { return };
    let r = convert(&load(&p));
    for (l, o) in r.network.lanelets.iter().zip(&r.origins) {
        assert_eq!(o.along_s, o.lane.lane < 0);
        let (ok, tot) = left_is_left(l);
        assert!(ok == tot, "lanelet {}", l.id);
    }
}

fn check_topology(name: &str, r: &map::MapResult) {
    let by_id: BTreeMap<LaneletId, &Lanelet> = r.network.lanelets.iter().map(|l| (l.id, l)).collect();
    for l in &r.network.lanelets {
        for s in &l.successors {
            let o = by_id[s];
            assert!(o.predecessors.contains(&l.id), "{name}: {} -> {} not mirrored", l.id, s);
            let gap = map_gap(l, o);
            assert!(gap <= 0.1, "{name}: {} -> {}: ends {gap} m apart", l.id, s);
        }
        for p in &l.predecessors {
            assert!(by_id[p].successors.contains(&l.id), "{name}: {} <- {} not mirrored", l.id, p);
        }
        for (adj, left) in [(l.adjacent_left, true), (l.adjacent_right, false)] {
            let Some(a) = adj else { continue };
            let o = by_id[&a.lanelet];
            let back = match (a.driving_dir, left) {
                (DrivingDir::Same, true) => o.adjacent_right,
                (DrivingDir::Same, false) => o.adjacent_left,
                (DrivingDir::Opposite, true) => o.adjacent_left,
                (DrivingDir::Opposite, false) => o.adjacent_right,
            };
            assert_eq!(back.map(|b| (b.lanelet, b.driving_dir)), Some((l.id, a.driving_dir)), "{name}: adjacency of {}", l.id);
            // the shared bound is the same polyline (reversed for opposite lanelets)
            let mine = if left { l.bounds.left() } else { l.bounds.right() };
            let theirs: Vec<_> = match (a.driving_dir, left) {
                (DrivingDir::Same, true) => o.bounds.right().to_vec(),
                (DrivingDir::Same, false) => o.bounds.left().to_vec(),
                (DrivingDir::Opposite, true) => o.bounds.left().iter().rev().copied().collect(),
                (DrivingDir::Opposite, false) => o.bounds.right().iter().rev().copied().collect(),
            };
            assert_eq!(mine.len(), theirs.len());
            for (p, q) in mine.iter().zip(&theirs) {
                assert!((p.x - q.x).hypot(p.y - q.y) < 1e-9, "{name}: shared bound of {} and {} differs", l.id, o.id);
            }
        }
    }
}

fn map_gap(a: &Lanelet, b: &Lanelet) -> f64 {
    let (al, ar) = (a.bounds.left().last().unwrap(), a.bounds.right().last().unwrap());
    let (bl, br) = (b.bounds.left()[0], b.bounds.right()[0]);
    (al.x - bl.x).hypot(al.y - bl.y).max((ar.x - br.x).hypot(ar.y - br.y))
}

#[test]
fn links_and_adjacency_are_symmetric_and_continuous_on_every_corpus_map() {
    let files = testkit::corpus_files("xodr");
    for f in &files {
        let r = convert(&load(f));
        check_topology(&f.display().to_string(), &r);
    }
    check_topology("example", &convert(&load(&example("two_lane_curve.xodr"))));
}

#[test]
fn lanes_link_across_sections_roads_and_junctions() {
    let Some(p) = corpus("esmini/xodr/fabriksgatan.xodr") else { return };
    let net = load(&p);
    let r = convert(&net);
    let id = |road: &str, sec: usize, lane: i32| r.lanelet_of[&opendrive::LaneRef { road: net.road_index(road).unwrap(), section: sec, lane }];
    let by_id: BTreeMap<LaneletId, &Lanelet> = r.network.lanelets.iter().map(|l| (l.id, l)).collect();
    // road 0 lane 1 drives against s into junction 4 at road 0's start, where connections
    // 8, 9, 10 (lane -1, along s) begin (file: connection incomingRoad=0 → 8, 9, 10)
    let from = by_id[&id("0", 0, 1)];
    for c in ["8", "9", "10"] {
        assert!(from.successors.contains(&id(c, 0, -1)), "road 0 lane 1 → road {c}");
    }
    // road 9 ends at road 2's end (contactPoint end): lane -1 continues into road 2 lane 1,
    // which drives against road 2's s (away from the junction)
    assert_eq!(by_id[&id("9", 0, -1)].successors, vec![id("2", 0, 1)]);
}

#[test]
fn zero_width_opening_lane_does_not_overlap() {
    let net = load(&example("two_lane_curve.xodr"));
    let r = convert(&net);
    let lane = |sec: usize, l: i32| r.network.lanelets.iter().zip(&r.origins).find(|(_, o)| o.lane.section == sec && o.lane.lane == l).map(|(x, _)| x).unwrap();
    // lane -2 of the section at s = 250 opens from zero width (a = 0)
    let opening = lane(1, -2);
    let inner = lane(1, -1);
    let (l0, r0) = (opening.bounds.left()[0], opening.bounds.right()[0]);
    assert!((l0.x - r0.x).hypot(l0.y - r0.y) < 1e-9, "starts at zero width");
    // its left bound is exactly its neighbour's right bound: no overlap, no gap
    assert_eq!(opening.bounds.left(), inner.bounds.right());
    // never negative width: the right bound stays right of the left bound (w(ds) = 0.0065625 ds² − 0.000109375 ds³ ≥ 0 on [0, 40])
    let (ok, tot) = left_is_left(opening);
    assert_eq!(ok, tot);
    // width at the end of the opening (ds = 40): 0.0065625·1600 − 0.000109375·64000 = 3.5
    let s = 290.0;
    let b = net.roads[0].lane_borders(1, -2, s).unwrap();
    assert!((b.width() - 3.5).abs() < 1e-9);
    // the shoulder of section 0 (lane -2) continues into lane -3 of section 1 (link in file)
    assert!(lane(0, -2).successors.contains(&lane(1, -3).id));
    // the opening lane has no predecessor (nothing in section 0 links to it)
    assert!(opening.predecessors.is_empty());
}

#[test]
fn output_is_deterministic() {
    let net = load(&example("two_lane_curve.xodr"));
    let a = convert(&net);
    let b = convert(&net);
    assert_eq!(a.network, b.network);
}
