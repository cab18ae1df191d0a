//! Scenario tags that follow from the lanelet network alone (the converter adds the ones
//! that depend on the traffic).

use commonroad::{DrivingDir, Lanelet, LaneletNetwork, LaneletType, RoadUser, Tag};
use std::collections::{BTreeMap, BTreeSet};

fn is_road_lane(l: &Lanelet) -> bool {
    l.user_one_way.contains(&RoadUser::Vehicle) || l.user_bidirectional.contains(&RoadUser::Vehicle)
}

/// Width in lanes of the carriageway a lanelet belongs to: itself plus its same-direction
/// neighbours (adjacency chains), counting road lanes only.
fn same_direction_lanes(net: &LaneletNetwork, start: usize, pos: &BTreeMap<commonroad::LaneletId, usize>) -> usize {
    let mut n = 1;
    for left in [true, false] {
        let mut cur = net.lanelets.get(start);
        let mut guard = 0;
        while let Some(l) = cur {
            let adj = if left { l.adjacent_left } else { l.adjacent_right };
            let next = adj.filter(|a| a.driving_dir == DrivingDir::Same).and_then(|a| pos.get(&a.lanelet)).and_then(|&k| net.lanelets.get(k));
            match next {
                Some(nl) if is_road_lane(nl) && guard < 64 => {
                    n += 1;
                    guard += 1;
                    cur = Some(nl);
                }
                _ => break,
            }
        }
    }
    n
}

/// Tags derivable from the map: road class (interstate, highway, urban, rural),
/// intersection, lane count (single_lane / two_lane / multi_lane: the widest carriageway in
/// lanes of one direction), oncoming_traffic / no_oncoming_traffic (a road lane with an
/// opposite-direction road lane beside it).
pub fn derived_tags(net: &LaneletNetwork) -> BTreeSet<Tag> {
    let mut tags = BTreeSet::new();
    let pos: BTreeMap<_, _> = net.lanelets.iter().enumerate().map(|(i, l)| (l.id, i)).collect();
    let mut widest = 0;
    let mut oncoming = false;
    let mut any_road = false;
    for (i, l) in net.lanelets.iter().enumerate() {
        if !is_road_lane(l) {
            continue;
        }
        any_road = true;
        for t in &l.lanelet_types {
            match t {
                LaneletType::Interstate => {
                    tags.insert(Tag::Interstate);
                }
                LaneletType::Highway => {
                    tags.insert(Tag::Highway);
                }
                LaneletType::Urban => {
                    tags.insert(Tag::Urban);
                }
                LaneletType::Country => {
                    tags.insert(Tag::Rural);
                }
                _ => {}
            }
        }
        widest = widest.max(same_direction_lanes(net, i, &pos));
        for adj in [l.adjacent_left, l.adjacent_right].into_iter().flatten() {
            if adj.driving_dir == DrivingDir::Opposite && pos.get(&adj.lanelet).and_then(|&k| net.lanelets.get(k)).is_some_and(is_road_lane) {
                oncoming = true;
            }
        }
    }
    if !net.intersections.is_empty() {
        tags.insert(Tag::Intersection);
    }
    if any_road {
        tags.insert(match widest {
            0 | 1 => Tag::SingleLane,
            2 => Tag::TwoLane,
            _ => Tag::MultiLane,
        });
        if widest >= 2 {
            tags.insert(Tag::MultiLane);
        }
        tags.insert(if oncoming { Tag::OncomingTraffic } else { Tag::NoOncomingTraffic });
    }
    tags
}
