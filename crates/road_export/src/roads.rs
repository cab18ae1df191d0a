//! Roads from chains of sections: each section's reference line continues the previous one
//! (same point, same heading on the shared cross-section), lane widths and the lane offset
//! are the differences of the fitted borders, lane types and road marks come from the
//! lanelets, and every lanelet learns where it went (road, section, lane id).

use crate::groups::Group;
use crate::lane_kind::{lane_type, road_type};
use crate::lanelets::Prepared;
use crate::marks::road_mark;
use crate::model::{Lane, Mark, Road, Section};
use crate::offsets::Cubic;
use crate::reference::Knot;
use crate::section::{build, SectionGeom};
use crate::warning::{Subject, Warning};
use commonroad::{LaneletNetwork, LineMarking};

/// Where a lanelet went.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Placed {
    /// Index into the document's roads.
    pub road: usize,
    pub section: usize,
    pub lane: i32,
    /// Whether traffic drives along +s.
    pub along: bool,
}

/// The lane id of member `k` of a group whose centre line is after `centre` members.
pub(crate) fn lane_id(k: usize, centre: usize) -> i32 {
    let (k, c) = (k as i64, centre as i64);
    (if k < c { c - k } else { -(k - c + 1) }) as i32
}

/// A road under construction: its sections' groups and geometry.
pub(crate) struct Built {
    pub road: Road,
    pub groups: Vec<Group>,
}

fn marking(net: &LaneletNetwork, g: &Group, k: usize, ref_left: bool, warnings: &mut Vec<Warning>) -> Option<Mark> {
    let m = g.members.get(k)?;
    let l = net.lanelets.get(m.idx)?;
    // the lanelet's own side that lies on the reference left
    let own_left = ref_left != m.flipped;
    let mk = if own_left { l.left_marking } else { l.right_marking };
    let (mark, approx) = road_mark(mk.unwrap_or(LineMarking::Unknown), m.flipped);
    if approx {
        warnings.push(Warning::new(
            Subject::Lanelet(l.id.get()),
            format!("line marking {} has no OpenDRIVE road mark; written as the nearest one", mk.map_or("unknown", |m| m.as_str())),
        ));
    }
    mark
}

/// The lanes of one section of `g` from its fitted borders.
fn lanes(net: &LaneletNetwork, g: &Group, geom: &SectionGeom, warnings: &mut Vec<Warning>) -> (Vec<Lane>, Option<Mark>, Vec<Lane>) {
    let (mut left, mut right) = (Vec::new(), Vec::new());
    let cubics = &geom.fitted.cubics;
    for (k, m) in g.members.iter().enumerate() {
        let Some(l) = net.lanelets.get(m.idx) else { continue };
        let (kind, note) = lane_type(l);
        if let Some(n) = note {
            warnings.push(Warning::new(Subject::Lanelet(l.id.get()), n));
        }
        let widths: Vec<Cubic> = match (cubics.get(k), cubics.get(k + 1)) {
            (Some(a), Some(b)) => a.iter().zip(b).map(|(x, y)| x.minus(y)).collect(),
            _ => Vec::new(),
        };
        let id = lane_id(k, g.centre);
        let is_left = id > 0;
        // a lane's mark is on its outer border: the reference left of a left lane
        let mark = marking(net, g, k, is_left, warnings);
        let lane = Lane { id, kind: kind.kind, access: kind.access, predecessors: Vec::new(), successors: Vec::new(), widths, mark };
        if is_left {
            left.push(lane);
        } else {
            right.push(lane);
        }
    }
    // shared borders: the outer lane's view is written; a different view is a warning
    for k in 1..g.members.len() {
        let (a, b) = (marking(net, g, k - 1, false, &mut Vec::new()), marking(net, g, k, true, &mut Vec::new()));
        if let (Some(a), Some(b)) = (a, b) {
            if a != b && k != g.centre {
                let id = g.members.get(k).and_then(|m| net.lanelets.get(m.idx)).map_or(0, |l| l.id.get());
                warnings.push(Warning::new(
                    Subject::Lanelet(id),
                    "its line marking differs from its neighbour's on their shared bound; OpenDRIVE has one road mark per border, the outer lane's is written",
                ));
            }
        }
    }
    left.sort_by_key(|l| l.id);
    right.sort_by_key(|l| -l.id);
    let centre =
        if g.centre < g.members.len() { marking(net, g, g.centre, true, warnings) } else { marking(net, g, g.centre.wrapping_sub(1), false, warnings) };
    (left, centre, right)
}

/// Builds the road made of `groups` (a chain of sections, each continuing the previous one).
pub(crate) fn build_road(id: u64, groups: Vec<Group>, net: &LaneletNetwork, prep: &[Option<Prepared>], tol: f64, warnings: &mut Vec<Warning>) -> Option<Built> {
    let mut road = Road {
        id,
        name: String::new(),
        junction: None,
        lht: groups.first().is_some_and(|g| g.lht),
        road_type: road_type(groups.iter().flat_map(|g| g.members.iter()).filter_map(|m| net.lanelets.get(m.idx))),
        length: 0.0,
        predecessor: None,
        successor: None,
        geometries: Vec::new(),
        lane_offsets: Vec::new(),
        sections: Vec::new(),
        signals: Vec::new(),
        signal_references: Vec::new(),
    };
    let mut kept = Vec::new();
    let mut start: Option<Knot> = None;
    for g in groups {
        let Some(geom) = build(&g, net, prep, tol, start, warnings) else { continue };
        let s0 = road.length;
        let end = geom.line.pose(geom.line.length);
        start = Some(Knot { p: end.p, hdg: end.hdg });
        for geo in &geom.line.geometries {
            let mut geo = geo.clone();
            geo.s += s0;
            road.geometries.push(geo);
        }
        if let Some(centre) = geom.fitted.cubics.get(g.centre) {
            road.lane_offsets.extend(centre.iter().map(|c| Cubic { s: c.s + s0, ..*c }));
        }
        let (left, centre_mark, right) = lanes(net, &g, &geom, warnings);
        road.sections.push(Section { s: s0, left, centre_mark, right });
        road.length = s0 + geom.line.length;
        kept.push(g);
    }
    if kept.is_empty() {
        return None;
    }
    road.name =
        kept.first().and_then(|g| g.members.first()).and_then(|m| net.lanelets.get(m.idx)).map(|l| format!("lanelets {}…", l.id.get())).unwrap_or_default();
    Some(Built { road, groups: kept })
}
