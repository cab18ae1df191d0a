//! The connecting road esmini attaches a world point to when an entity placed by its world pose
//! (the looming controller's vehicle) leaves its road into a junction. esmini's
//! Position::XYZ2TrackPos visits every road in the network's order; where several contain the
//! point, a road directly connected to the entity's road from its lane (Road::IsDirectlyConnected:
//! a junction connection, the counter connections included, with a lane link from that lane)
//! wins over one that is not, and among directly connected ones that contain it equally a later
//! one wins unless its curvature at the contact point is larger in magnitude than the best so
//! far ("the one which goes the most straight forward"). So from the stem of a T, whose two arms
//! bend alike, the later arm in the file is taken — not the one a move along the lane would
//! choose.

use opendrive::{ContactPoint, ElementType, LanePosition, Road, RoadNetwork, Shape};

// esmini's SMALL_NUMBER: a spiral whose end curvatures differ by less is a line or an arc.
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;

/// The curvature Road::IsDirectlyConnected reports at a connecting road's contact point: its
/// first geometry at the start or its last at the end, as esmini evaluates it
/// (Spiral::EvaluateCurvatureDS: a spiral whose curvatures differ by less than SMALL_NUMBER was
/// made a line, curvature 0, or an arc when it was read). Other shapes: the plan view's.
fn contact_curvature(road: &Road, contact: ContactPoint) -> f64 {
    let end = contact == ContactPoint::End;
    let s = if end { road.length } else { 0.0 };
    let g = if end { road.geometries.last() } else { road.geometries.first() };
    match g.map(|g| (&g.shape, g.length)) {
        Some((Shape::Line, _)) => 0.0,
        Some((Shape::Arc { curvature }, _)) => *curvature,
        Some((Shape::Spiral(sp), _)) if (sp.curv_end - sp.curv_start).abs() < SMALL_NUMBER => {
            if sp.curv_start.abs() < SMALL_NUMBER {
                0.0
            } else {
                sp.curv_start
            }
        }
        Some((Shape::Spiral(sp), length)) => {
            let ds = if end { length } else { 0.0 };
            sp.curv_start + (ds / length) * (sp.curv_end - sp.curv_start)
        }
        _ => road.reference_pose(s).curvature,
    }
}

/// The connecting roads a junction at either end of road `road` (outside a junction) leads to
/// from lane `lane_id` (Road::IsDirectlyConnected through a junction: a connection that road
/// enters by, the counter connections included, with a lane link from that lane; lane 0: any
/// connection), each once, with the contact point at the connecting road.
fn junction_arms(net: &RoadNetwork, road_index: usize, lane_id: i32) -> Vec<(usize, ContactPoint)> {
    let mut connected: Vec<(usize, ContactPoint)> = Vec::new();
    let Some(road) = net.roads.get(road_index) else { return connected };
    for link in [road.predecessor.as_ref(), road.successor.as_ref()].into_iter().flatten() {
        if link.element_type != ElementType::Junction {
            continue;
        }
        let Some(j) = net.junction_index(&link.element_id) else { continue };
        for c in super::junction_connections::entering(net, j, road_index) {
            let from_lane = lane_id == 0 || c.lane_links.iter().any(|l| l.0 == lane_id);
            if from_lane && !connected.iter().any(|k| k.0 == c.connecting) {
                connected.push((c.connecting, c.contact));
            }
        }
    }
    connected
}

/// The roads Road::IsDirectlyConnected finds from road `road` and its lane `lane_id`: those its
/// road links name, and the connecting roads of a junction it links to (`junction_arms`).
pub(crate) fn directly_connected(net: &RoadNetwork, road: usize, lane_id: i32) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::new();
    if let Some(r) = net.roads.get(road) {
        for link in [r.successor.as_ref(), r.predecessor.as_ref()].into_iter().flatten() {
            if link.element_type == ElementType::Road {
                if let Some(i) = net.road_index(&link.element_id) {
                    out.push(i);
                }
            }
        }
    }
    out.extend(junction_arms(net, road, lane_id).into_iter().map(|c| c.0));
    out
}

/// The connecting road XYZ2TrackPos puts (x, y) on when the entity was on road `from_road`
/// (outside a junction) in lane `from_lane`, and the point lies on a road directly connected to
/// it from that lane;
/// `None` when no such road contains the point (the general search then answers).
pub(crate) fn entry_connector(net: &RoadNetwork, from_road: usize, from_lane: i32, x: f64, y: f64) -> Option<LanePosition> {
    let road = net.roads.get(from_road)?;
    if road.junction.is_some() {
        return None;
    }
    let mut connected = junction_arms(net, from_road, from_lane);
    if connected.is_empty() {
        return None;
    }
    // XYZ2TrackPos visits the roads in the network's order.
    connected.sort_by_key(|k| k.0);
    let mut best: Option<(LanePosition, f64)> = None;
    for (r, contact) in connected {
        let Some(cr) = net.roads.get(r) else { continue };
        let s_contact = if contact == ContactPoint::End { cr.length } else { 0.0 };
        let Some(p) = net.locate_on_road_by(r, x, y, s_contact, &super::banking::surface_t) else { continue };
        if !p.is_on_road() {
            continue;
        }
        let curvature = contact_curvature(cr, contact).abs();
        if best.as_ref().is_none_or(|b| curvature <= b.1) {
            best = Some((p, curvature));
        }
    }
    best.map(|b| b.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn road(planview: &str) -> Road {
        let xodr = format!(
            r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="40" junction="-1"><planView>{planview}</planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
</OpenDRIVE>"#
        );
        let net = opendrive::parse_str(&xodr, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"));
        net.roads.into_iter().next().unwrap_or_else(|| panic!("one road"))
    }

    #[test]
    fn a_spiral_whose_curvatures_barely_differ_is_straight_for_esmini() {
        // A spiral from −5e−10 to 1e−9 1/m: esmini reads it as a line, curvature 0, which then
        // bends less than a clothoid ending at 0.9999999995e−9 1/m (the arm it prefers).
        let straight = road(r#"<geometry s="0" x="0" y="0" hdg="0" length="40"><spiral curvStart="-5e-10" curvEnd="1e-9"/></geometry>"#);
        assert_eq!(contact_curvature(&straight, ContactPoint::End), 0.0);
        let clothoid =
            road(r#"<geometry s="0" x="0" y="0" hdg="0" length="40"><spiral curvStart="0.0690948457876379" curvEnd="9.999999994736442e-10"/></geometry>"#);
        assert!(contact_curvature(&clothoid, ContactPoint::End).abs() > 0.0);
        assert!((contact_curvature(&clothoid, ContactPoint::Start) - 0.0690948457876379).abs() < 1e-15);
        let arc = road(r#"<geometry s="0" x="0" y="0" hdg="0" length="40"><spiral curvStart="0.05" curvEnd="0.0500000001"/></geometry>"#);
        assert_eq!(contact_curvature(&arc, ContactPoint::End), 0.05);
    }
}
