//! Traffic signs (German as they are, Swedish translated, others dropped with a warning),
//! traffic lights, stop lines, and intersections with turns checked by hand against the file.

use crate::common::*;
use commonroad::{Lanelet, LaneletId};
use std::collections::BTreeMap;

#[test]
fn straight_500m_signs() {
    let Some(p) = corpus("esmini/xodr/straight_500m_signs.xodr") else { return };
    let net = load(&p);
    let r = convert(&net);
    let signs = &r.network.traffic_signs;
    // 19 signals: 2 Chinese and 1 without a type are dropped (warnings), 16 remain
    assert_eq!(signs.len(), 16, "{signs:#?}");
    let dropped: Vec<_> = r.warnings.iter().filter(|w| w.message.contains("dropped")).collect();
    assert_eq!(dropped.len(), 3, "{dropped:#?}");
    assert!(dropped.iter().any(|w| w.message.contains("`cn`")));
    // every sign is referenced by at least one lanelet
    for s in signs {
        assert!(r.network.lanelets.iter().any(|l| l.traffic_sign_refs.contains(&s.id)), "sign {} unreferenced", s.id);
    }
    // SWE C31-5 at s = 0 → 274 with 50 km/h = 13.8889 m/s; SWE C31-3 → 30 km/h = 8.3333 m/s
    let values: Vec<f64> = signs.iter().filter(|s| s.elements[0].sign_id == "274").map(|s| s.elements[0].additional_values[0].parse().unwrap()).collect();
    assert!(values.iter().any(|v| (v - 50.0 / 3.6).abs() < 1e-3));
    assert!(values.iter().any(|v| (v - 30.0 / 3.6).abs() < 1e-3));
    // SWE C27 / C28 (overtaking ban begin / end) → 276 / 280; SWE A20 and DE 123 → 123
    let ids: Vec<&str> = signs.iter().map(|s| s.elements[0].sign_id.as_str()).collect();
    assert!(ids.contains(&"276") && ids.contains(&"280"));
    assert_eq!(ids.iter().filter(|i| **i == "123").count(), 2);
    // signal 9 (s = 200, validity -3..-2, 1..2, 3..3) → the lanelets of lanes -3, -2, 1, 2, 3
    let sign9 = signs.iter().find(|s| {
        let p = s.position.unwrap();
        let w = net.road("1").unwrap().st_to_world(200.0, -3.57);
        (p.x - w.x).hypot(p.y - w.y) < 1e-9 && s.elements[0].additional_values[0].starts_with("8.33")
    });
    let sign9 = sign9.expect("sign 9");
    let mut lanes: Vec<i32> =
        r.network.lanelets.iter().zip(&r.origins).filter(|(l, _)| l.traffic_sign_refs.contains(&sign9.id)).map(|(_, o)| o.lane.lane).collect();
    lanes.sort();
    assert_eq!(lanes, vec![-3, -2, 1, 2, 3]);
}

#[test]
fn lights_and_stop_lines() {
    let Some(p) = corpus("esmini/xodr/multi_intersections.xodr") else { return };
    let net = load(&p);
    let r = convert(&net);
    let n_lights = net.roads.iter().flat_map(|rd| &rd.signals).filter(|s| map::signals::is_light(s)).count();
    assert!(n_lights > 0);
    assert_eq!(r.network.traffic_lights.len(), n_lights);
    for l in &r.network.traffic_lights {
        assert!(r.network.lanelets.iter().any(|x| x.traffic_light_refs.contains(&l.id)));
    }
    // stop lines (type 294) lie across their lanelet: both points within the lanelet's width
    let stops: Vec<&Lanelet> = r.network.lanelets.iter().filter(|l| l.stop_line.is_some()).collect();
    assert!(!stops.is_empty());
    for l in stops {
        let [a, b] = l.stop_line.as_ref().unwrap().points.unwrap();
        assert!(dist_to_polyline(a.x, a.y, l.bounds.left()) < 0.01);
        assert!(dist_to_polyline(b.x, b.y, l.bounds.right()) < 0.01);
    }
}

#[test]
fn fabriksgatan_intersection_turns_checked_by_hand() {
    let Some(p) = corpus("esmini/xodr/fabriksgatan.xodr") else { return };
    let net = load(&p);
    let r = convert(&net);
    assert_eq!(r.network.intersections.len(), 1);
    let inter = &r.network.intersections[0];
    // four arms (roads 0, 1, 2, 3), each with one driving lane into the junction
    assert_eq!(inter.incomings.len(), 4);
    // connecting roads of junction 4 (lane -1 drives along s). Read from the file: an arc
    // with positive curvature turns left, negative right; a nearly straight paramPoly3
    // (|cV| < 2e-3) goes straight:
    //   5: arc +0.108 L   6: arc −0.172 R   7: pp3 S   8: arc −0.174 R   9: pp3 S
    //  10: arc +0.101 L  11: arc −0.156 R  12: pp3 S  13: arc +0.108 L  14: pp3 S
    //  15: arc +0.107 L  16: arc −0.174 R
    let expected =
        [("5", 'L'), ("6", 'R'), ("7", 'S'), ("8", 'R'), ("9", 'S'), ("10", 'L'), ("11", 'R'), ("12", 'S'), ("13", 'L'), ("14", 'S'), ("15", 'L'), ("16", 'R')];
    let id = |road: &str| r.lanelet_of[&opendrive::LaneRef { road: net.road_index(road).unwrap(), section: 0, lane: -1 }];
    let mut turn: BTreeMap<LaneletId, char> = BTreeMap::new();
    for inc in &inter.incomings {
        for (v, c) in [(&inc.successors_left, 'L'), (&inc.successors_straight, 'S'), (&inc.successors_right, 'R')] {
            for x in v {
                turn.insert(*x, c);
            }
        }
    }
    for (road, c) in expected {
        assert_eq!(turn.get(&id(road)), Some(&c), "connecting road {road}");
    }
    // isLeftOf by hand: road 0 traffic enters heading ≈ −1.359 + π ≈ 102° (north); the
    // arm on its left is road 3, whose lane −1 enters heading 0.146 rad ≈ 8° (eastward,
    // coming from the west)
    let inc_of = |road: &str| {
        let lane = if road == "0" || road == "1" { 1 } else { -1 };
        let l = r.lanelet_of[&opendrive::LaneRef { road: net.road_index(road).unwrap(), section: 0, lane }];
        inter.incomings.iter().find(|i| i.incoming_lanelets.contains(&l)).map(|i| i.id).unwrap()
    };
    let inc0 = inter.incomings.iter().find(|i| i.id == inc_of("0")).unwrap();
    assert_eq!(inc0.is_left_of, Some(inc_of("3")));
    // road 1 enters heading ≈ 0.193 + π (west); on its left is the arm from the south, road 0
    let inc1 = inter.incomings.iter().find(|i| i.id == inc_of("1")).unwrap();
    assert_eq!(inc1.is_left_of, Some(inc_of("0")));
}

#[test]
fn derived_tags_of_a_motorway_and_a_town_crossing() {
    use commonroad::Tag;
    let Some(p) = corpus("osc-examples-1.3/Databases/AB_RQ31_Straight.xodr") else { return };
    let tags = map::derived_tags(&convert(&load(&p)).network);
    assert!(tags.contains(&Tag::Highway) && tags.contains(&Tag::Interstate), "{tags:?}");
    assert!(!tags.contains(&Tag::Urban));
    assert!(tags.contains(&Tag::MultiLane));
    let Some(p) = corpus("esmini/xodr/fabriksgatan.xodr") else { return };
    let tags = map::derived_tags(&convert(&load(&p)).network);
    assert!(tags.contains(&Tag::Intersection) && tags.contains(&Tag::OncomingTraffic), "{tags:?}");
}
