//! adjacentLeft / adjacentRight between lanelets of one lane section: the next kept lane in
//! t order on each side (lanes of zero width are looked through; any other skipped lane
//! breaks adjacency). Across the centre line the direction is usually `opposite`.

use crate::build::Built;
use commonroad::{Adjacent, DrivingDir};
use opendrive::{LaneRef, RoadNetwork};

pub(crate) fn adjacent(net: &RoadNetwork, built: &mut Built) {
    for (ri, road) in net.roads.iter().enumerate() {
        for (si, sec) in road.lane_sections.iter().enumerate() {
            // lanes from +t to −t, zero-width ones removed
            let order: Vec<LaneRef> = sec
                .left
                .iter()
                .rev()
                .chain(&sec.right)
                .map(|l| LaneRef { road: ri, section: si, lane: l.id })
                .filter(|r| !built.zero_width.contains(r))
                .collect();
            for (k, r) in order.iter().enumerate() {
                let Some(&i) = built.index_of.get(r) else { continue };
                let plus = k.checked_sub(1).and_then(|p| order.get(p)).and_then(|n| built.index_of.get(n)).copied();
                let minus = order.get(k + 1).and_then(|n| built.index_of.get(n)).copied();
                let Some(me) = built.origins.get(i).copied() else { continue };
                let adj = |j: Option<usize>| -> Option<Adjacent> {
                    let j = j?;
                    let other = built.origins.get(j)?;
                    let dir = if other.along_s == me.along_s { DrivingDir::Same } else { DrivingDir::Opposite };
                    Some(Adjacent { lanelet: built.lanelets.get(j)?.id, driving_dir: dir })
                };
                let (left, right) = if me.along_s { (adj(plus), adj(minus)) } else { (adj(minus), adj(plus)) };
                if let Some(l) = built.lanelets.get_mut(i) {
                    l.adjacent_left = left;
                    l.adjacent_right = right;
                }
            }
        }
    }
}
