//! What the export makes of small networks built here: roads and directions, traffic rule,
//! junctions of forks and intersections, signals keeping their ids, lane types and road
//! marks, a curved lane's accuracy.

use crate::common::read_back;
use commonroad::*;
use road_export::{export, round_trip, Options};

fn pts(v: &[(f64, f64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::new(x, y)).collect()
}

fn lanelet(id: u64, left: &[(f64, f64)], right: &[(f64, f64)]) -> Lanelet {
    let bounds = LaneletBounds::new(pts(left), pts(right)).expect("valid bounds");
    Lanelet::new(LaneletId::new(id).expect("id"), bounds, LaneletType::Urban)
}

fn id(n: u64) -> LaneletId {
    LaneletId::new(n).expect("id")
}

fn straight(id_: u64, y0: f64, y1: f64, x0: f64, x1: f64) -> Lanelet {
    // driving from x0 to x1; the left bound is at y1 when x1 > x0
    lanelet(id_, &[(x0, y1), (0.5 * (x0 + x1), y1), (x1, y1)], &[(x0, y0), (0.5 * (x0 + x1), y0), (x1, y0)])
}

/// `a` and `b` as each other's neighbour driving the opposite way, on the left of both (`left`)
/// or on the right of both.
fn opposite_neighbours(mut a: Lanelet, mut b: Lanelet, left: bool) -> LaneletNetwork {
    let (of_a, of_b) =
        (Some(Adjacent { lanelet: b.id, driving_dir: DrivingDir::Opposite }), Some(Adjacent { lanelet: a.id, driving_dir: DrivingDir::Opposite }));
    if left {
        (a.adjacent_left, b.adjacent_left) = (of_a, of_b);
    } else {
        (a.adjacent_right, b.adjacent_right) = (of_a, of_b);
    }
    LaneletNetwork { lanelets: vec![a, b], ..Default::default() }
}

fn round_trips(net: &LaneletNetwork) -> (road_export::RoadExport, round_trip::Comparison) {
    let e = export(net, &Options::default()).expect("exports");
    let back = read_back(&e.xodr);
    let c = round_trip::compare(net, &back);
    assert!(c.passes(0.05, 0.01), "round trip fails: {:?}\n{}", c.failures(0.05), e.xodr);
    (e, c)
}

#[test]
fn opposite_neighbours_are_one_road_with_a_centre_line() {
    let a = straight(1, 0.0, 3.5, 0.0, 100.0);
    // lanelet 2 drives towards −x on the left: its left bound is at y = 3.5
    let b = straight(2, 7.0, 3.5, 100.0, 0.0);
    let net = opposite_neighbours(a, b, true);
    let (e, c) = round_trips(&net);
    assert_eq!(e.xodr.matches("<road ").count(), 1);
    assert!(e.xodr.contains("rule=\"RHT\""));
    assert!(e.xodr.contains("<lane id=\"1\"") && e.xodr.contains("<lane id=\"-1\""));
    assert_eq!((c.relations, c.relations_kept), (2, 2));
    assert!(c.worst_bound_error() < 0.01);
}

#[test]
fn traffic_on_the_left_gives_a_left_hand_road() {
    // lanelet 1 drives +x above lanelet 2, which drives −x: left-hand traffic
    let net = opposite_neighbours(straight(1, 3.5, 7.0, 0.0, 80.0), straight(2, 3.5, 0.0, 80.0, 0.0), false);
    let (e, _) = round_trips(&net);
    assert!(e.xodr.contains("rule=\"LHT\""), "{}", e.xodr);
}

#[test]
fn a_fork_is_a_direct_junction() {
    let mut a = straight(1, 0.0, 3.5, 0.0, 50.0);
    let mut b = straight(2, 0.0, 3.5, 50.0, 100.0);
    // lanelet 3 leaves to the right on a gentle curve
    let curve = |off: f64| -> Vec<(f64, f64)> { (0..=10).map(|k| f64::from(k) * 5.0).map(|x| (50.0 + x, off - 0.004 * x * x)).collect() };
    let mut c = lanelet(3, &curve(3.5), &curve(0.0));
    a.successors = vec![id(2), id(3)];
    b.predecessors = vec![id(1)];
    c.predecessors = vec![id(1)];
    let net = LaneletNetwork { lanelets: vec![a, b, c], ..Default::default() };
    let (e, c) = round_trips(&net);
    assert!(e.xodr.contains("type=\"direct\""), "{}", e.xodr);
    assert_eq!(e.xodr.matches("<connection ").count(), 2);
    assert_eq!(c.relations, c.relations_kept);
}

#[test]
fn intersection_lanelets_are_connecting_roads_of_a_junction() {
    let mut inc = straight(1, 0.0, 3.5, 0.0, 50.0);
    let mut through = straight(2, 0.0, 3.5, 50.0, 70.0);
    let mut out = straight(4, 0.0, 3.5, 70.0, 120.0);
    // a right turn: quarter circle around (50, -16.5), radius 16.5 … 20
    let arc = |r: f64| -> Vec<(f64, f64)> { (0..=18).map(|k| f64::from(k) * 5f64.to_radians()).map(|a| (50.0 + r * a.sin(), -16.5 + r * a.cos())).collect() };
    let mut right = lanelet(3, &arc(20.0), &arc(16.5));
    right.lanelet_types = vec![LaneletType::Urban, LaneletType::Intersection];
    through.lanelet_types = vec![LaneletType::Urban, LaneletType::Intersection];
    inc.successors = vec![id(2), id(3)];
    through.predecessors = vec![id(1)];
    through.successors = vec![id(4)];
    out.predecessors = vec![id(2)];
    right.predecessors = vec![id(1)];
    let intersection = Intersection {
        id: IntersectionId::new(10).expect("id"),
        incomings: vec![Incoming {
            id: IncomingId::new(11).expect("id"),
            incoming_lanelets: vec![id(1)],
            successors_right: vec![id(3)],
            successors_straight: vec![id(2)],
            successors_left: vec![],
            is_left_of: None,
        }],
        crossings: vec![],
    };
    let net = LaneletNetwork { lanelets: vec![inc, through, right, out], intersections: vec![intersection], ..Default::default() };
    let (e, c) = round_trips(&net);
    assert!(e.xodr.contains("type=\"default\""), "{}", e.xodr);
    assert_eq!(e.xodr.matches("junction=\"-1\"").count(), 2, "the incoming and outgoing roads are outside the junction");
    assert_eq!(c.relations, c.relations_kept);
}

#[test]
fn signs_lights_and_stop_lines_are_signals_with_their_ids() {
    let mut a = straight(1, 0.0, 3.5, 0.0, 100.0);
    let sign = TrafficSign {
        id: TrafficSignId::new(50).expect("id"),
        elements: vec![TrafficSignElement { sign_id: "274".into(), additional_values: vec!["13.888889".into()] }],
        position: Some(Point::new(10.0, -1.0)),
        is_virtual: false,
    };
    let light = TrafficLight {
        id: TrafficLightId::new(51).expect("id"),
        cycle: vec![CycleElement { duration: std::num::NonZeroU64::new(30).expect("n"), color: TrafficLightColor::Red }],
        time_offset: 0,
        position: Some(Point::new(99.0, -1.0)),
        direction: None,
        active: Some(true),
    };
    a.traffic_sign_refs = vec![sign.id];
    a.traffic_light_refs = vec![light.id];
    a.stop_line = Some(StopLine {
        points: Some([Point::new(98.0, 3.5), Point::new(98.0, 0.0)]),
        line_marking: LineMarking::Solid,
        traffic_sign_refs: vec![],
        traffic_light_refs: vec![light.id],
    });
    let net = LaneletNetwork { lanelets: vec![a], traffic_signs: vec![sign], traffic_lights: vec![light], ..Default::default() };
    let e = export(&net, &Options::default()).expect("exports");
    assert!(e.xodr.contains("id=\"50\""), "{}", e.xodr);
    assert!(e.xodr.contains("id=\"51\"") && e.xodr.contains("dynamic=\"yes\"") && e.xodr.contains("type=\"1000001\""));
    assert!(e.xodr.contains("type=\"294\""));
    let back = {
        let loaded = opendrive::parse_str(&e.xodr, std::path::Path::new("x.xodr")).expect("reads");
        map::convert(&loaded.network, &map::MapOptions::default()).network
    };
    assert_eq!(back.traffic_signs.len(), 1);
    let v: f64 = back.traffic_signs[0].elements[0].additional_values[0].parse().expect("a number");
    assert!((v - 13.888889).abs() < 1e-3, "speed read back as {v}");
    assert_eq!(back.traffic_signs[0].elements[0].sign_id, "274");
    let p = back.traffic_signs[0].position.expect("position");
    assert!((p.x - 10.0).abs() < 1e-6 && (p.y + 1.0).abs() < 1e-6);
    assert_eq!(back.traffic_lights.len(), 1);
    assert!(back.lanelets[0].stop_line.is_some());
}

#[test]
fn lane_types_and_road_marks() {
    let mut bus = straight(1, 0.0, 3.5, 0.0, 50.0);
    bus.lanelet_types = vec![LaneletType::BusLane];
    bus.right_marking = Some(LineMarking::Solid);
    bus.left_marking = Some(LineMarking::SolidDashed);
    let mut bike = straight(2, -2.0, 0.0, 0.0, 50.0);
    bike.lanelet_types = vec![LaneletType::BicycleLane];
    bike.right_marking = Some(LineMarking::Curb);
    bus.adjacent_right = Some(Adjacent { lanelet: id(2), driving_dir: DrivingDir::Same });
    bike.adjacent_left = Some(Adjacent { lanelet: id(1), driving_dir: DrivingDir::Same });
    let mut walk = straight(3, 10.0, 12.0, 0.0, 50.0);
    walk.lanelet_types = vec![LaneletType::Crosswalk];
    let net = LaneletNetwork { lanelets: vec![bus, bike, walk], ..Default::default() };
    let e = export(&net, &Options::default()).expect("exports");
    assert!(e.xodr.contains("restriction=\"bus\""), "{}", e.xodr);
    assert!(e.xodr.contains("type=\"biking\"") && e.xodr.contains("type=\"sidewalk\""));
    assert!(e.xodr.contains("type=\"solid broken\"") && e.xodr.contains("type=\"curb\"") && e.xodr.contains("type=\"solid\""));
    assert!(e.warnings.iter().any(|w| w.subject == road_export::Subject::Lanelet(3) && w.message.contains("crosswalk")));
    let back = read_back(&e.xodr);
    let c = round_trip::compare(&net, &back);
    assert!(c.passes(0.05, 0.01), "{:?}", c.failures(0.05));
    let bus_back = back.lanelets.iter().find(|l| l.lanelet_types.contains(&LaneletType::Urban) || l.user_one_way.contains(&RoadUser::Vehicle));
    assert!(bus_back.is_some_and(|l| l.left_marking == Some(LineMarking::SolidDashed) && l.right_marking == Some(LineMarking::Solid)));
}

#[test]
fn a_curved_lane_is_within_the_tolerance() {
    let arc = |r: f64| -> Vec<(f64, f64)> { (0..=60).map(|k| f64::from(k) * 1.5f64.to_radians()).map(|a| (r * a.sin(), 30.0 - r * a.cos())).collect() };
    let l = lanelet(1, &arc(26.5), &arc(30.0));
    let net = LaneletNetwork { lanelets: vec![l], ..Default::default() };
    let (_, c) = round_trips(&net);
    // fitted within 1 cm, read back within the map conversion's 5 mm more
    assert!(c.worst_bound_error() <= 0.015, "{}", c.worst_bound_error());
}
