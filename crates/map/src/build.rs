//! One lanelet per kept lane per lane section: bounds from the shared section stations,
//! point order and left/right from the driving direction, types, users and markings.

use crate::borders::border_idx;
use crate::lane_class::{classify, LaneClass};
use crate::markings::border_marking;
use crate::options::LaneletOrigin;
use crate::sampling::{sample_section, Station};
use crate::warn::WarningSink;
use commonroad::{IdAllocator, Lanelet, LaneletBounds, LaneletId, Point};
use opendrive::{drives_along_s, LaneRef, RoadNetwork};
use std::collections::BTreeMap;

/// A lane narrower than this everywhere in its section is skipped (m).
pub(crate) const ZERO_WIDTH: f64 = 0.01;

/// The lanelets made so far and where they came from.
#[derive(Debug, Default)]
pub struct Built {
    pub lanelets: Vec<Lanelet>,
    pub origins: Vec<LaneletOrigin>,
    pub classes: Vec<LaneClass>,
    pub index_of: BTreeMap<LaneRef, usize>,
    /// Lanes of zero width over their whole section: transparent for adjacency.
    pub zero_width: std::collections::BTreeSet<LaneRef>,
    /// Sections of (near) zero length: no lanelets, links pass through them.
    pub degenerate_sections: std::collections::BTreeSet<(usize, usize)>,
}

impl Built {
    pub fn id_of(&self, lane: &LaneRef) -> Option<LaneletId> {
        self.index_of.get(lane).and_then(|&i| self.lanelets.get(i)).map(|l| l.id)
    }
}

fn to_point(p: crate::sampling::P2) -> Point {
    Point::new(p.x, p.y)
}

/// Builds every lanelet of the network.
pub(crate) fn build_lanelets(net: &RoadNetwork, tol: f64, ids: &mut IdAllocator, warn: &mut WarningSink) -> Built {
    let mut out = Built::default();
    for (ri, road) in net.roads.iter().enumerate() {
        for (si, sec) in road.lane_sections.iter().enumerate() {
            let stations: Vec<Station> = sample_section(road, si, tol);
            if stations.len() >= crate::sampling::MAX_STATIONS {
                warn.at(
                    &net.file,
                    sec.pos,
                    format!(
                        "road `{}` lane section {si}: its borders need more than {} points to stay within {tol} m; sampled at that cap, they may deviate more",
                        road.id,
                        crate::sampling::MAX_STATIONS
                    ),
                );
            }
            if stations.len() < 2 {
                out.degenerate_sections.insert((ri, si));
                continue;
            }
            let Some((s0, s1)) = road.section_range(si) else { continue };
            let road_kind = road.type_at(0.5 * (s0 + s1)).map(|t| t.kind);
            let n_left = sec.left.len();
            // left-to-right: outermost left lane first
            let lanes = sec.left.iter().enumerate().rev().map(|(p, l)| (true, p, l)).chain(sec.right.iter().enumerate().map(|(p, l)| (false, p, l)));
            for (left_side, pos, lane) in lanes {
                let lref = LaneRef { road: ri, section: si, lane: lane.id };
                let b = border_idx(n_left, left_side, pos);
                let width = |st: &Station| {
                    let (i, o) = (st.cut.t.get(b.inner), st.cut.t.get(b.outer));
                    match (i, o) {
                        (Some(i), Some(o)) => (o - i).abs(),
                        _ => 0.0,
                    }
                };
                if stations.iter().map(width).fold(0.0, f64::max) < ZERO_WIDTH {
                    out.zero_width.insert(lref);
                    warn.count("lanes of zero width over their whole lane section skipped", &net.file, lane.pos);
                    continue;
                }
                let Some(class) = classify(lane.kind, road_kind, road.junction.is_some()) else {
                    warn.count(&format!("lanes of type `{}` skipped (no CommonRoad lanelet type)", lane.type_raw), &net.file, lane.pos);
                    continue;
                };
                let along = drives_along_s(road.rule, lane.id);
                // (+t border, −t border): the outer border of a left lane is its +t side
                let (plus, minus) = if left_side { (b.outer, b.inner) } else { (b.inner, b.outer) };
                let pts = |k: usize| -> Vec<Point> { stations.iter().filter_map(|st| st.points.get(k).copied().map(to_point)).collect() };
                let (mut lb, mut rb) = if along { (pts(plus), pts(minus)) } else { (pts(minus), pts(plus)) };
                if !along {
                    lb.reverse();
                    rb.reverse();
                }
                let bounds = match LaneletBounds::new(lb, rb) {
                    Ok(b) => b,
                    Err(e) => {
                        warn.at(&net.file, lane.pos, format!("road `{}` lane {}: lanelet not built: {e}", road.id, lane.id));
                        continue;
                    }
                };
                let id = ids.lanelet();
                let mut ll = Lanelet::new(id, bounds, commonroad::LaneletType::Unknown);
                ll.lanelet_types = class.types.clone();
                ll.user_one_way = class.one_way.clone();
                ll.user_bidirectional = class.bidirectional.clone();
                // markings: owner of the inner border is the next lane inward (or the centre)
                let side = if left_side { &sec.left } else { &sec.right };
                let inner_owner = if pos == 0 { sec.center.as_ref() } else { side.get(pos - 1) };
                let len = s1 - s0;
                let inner_mark = border_marking(inner_owner, len, !along);
                let outer_mark = border_marking(Some(lane), len, !along);
                // the +t border is the left bound when driving along s
                let (plus_mark, minus_mark) = if left_side { (outer_mark, inner_mark) } else { (inner_mark, outer_mark) };
                (ll.left_marking, ll.right_marking) = if along { (plus_mark, minus_mark) } else { (minus_mark, plus_mark) };
                out.index_of.insert(lref, out.lanelets.len());
                out.lanelets.push(ll);
                out.origins.push(LaneletOrigin { lane: lref, along_s: along });
                out.classes.push(class);
            }
        }
    }
    out
}
