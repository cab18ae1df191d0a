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

use super::LanePos;
use opendrive::{ContactPoint, ElementType, LanePosition, RoadNetwork};

/// The connecting road XYZ2TrackPos puts (x, y) on when the entity was at `from`, on a road
/// outside a junction, and the point lies on a road directly connected to it from its lane;
/// `None` when no such road contains the point (the general search then answers).
pub(crate) fn entry_connector(net: &RoadNetwork, from: &LanePos, x: f64, y: f64) -> Option<LanePosition> {
    let road = net.roads.get(from.road)?;
    if road.junction.is_some() {
        return None;
    }
    // The connecting roads directly connected from this lane, by either end of the road.
    let mut connected: Vec<(usize, ContactPoint)> = Vec::new();
    for link in [road.predecessor.as_ref(), road.successor.as_ref()].into_iter().flatten() {
        if link.element_type != ElementType::Junction {
            continue;
        }
        let Some(j) = net.junction_index(&link.element_id) else { continue };
        for c in super::junction_connections::entering(net, j, from.road) {
            if c.lane_links.iter().any(|l| l.0 == from.lane_id) && !connected.iter().any(|k| k.0 == c.connecting) {
                connected.push((c.connecting, c.contact));
            }
        }
    }
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
        let curvature = cr.reference_pose(s_contact).curvature.abs();
        if best.as_ref().is_none_or(|b| curvature <= b.1) {
            best = Some((p, curvature));
        }
    }
    best.map(|b| b.0)
}
