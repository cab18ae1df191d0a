//! Whether a world point lies beyond the end of the road it was located on: esmini's
//! Position::XYZ2TrackPos sets POS_STATUS_END_OF_ROAD when the closest point of the road network
//! does not fall inside any road's s range (`closestPointInside`), as for an entity a trajectory
//! has carried past a dead end; and the status a re-attachment leaves at a road's end
//! (`unlinked_end_at`).

use crate::dynamics::ESMINI_SMALL_NUMBER as PAST;
use opendrive::projection::project_onto_road;
use opendrive::RoadNetwork;

/// (x, y), located on road `road` at `s`, projects beyond that road's start or end.
pub(crate) fn past_road_end(net: &RoadNetwork, road: usize, s: f64, x: f64, y: f64) -> bool {
    let Some(r) = net.roads.get(road) else { return false };
    if s > PAST && s < r.length - PAST {
        return false;
    }
    let (_, _, along) = project_onto_road(r, x, y, s);
    along.abs() > PAST
}

/// The end-of-road status a re-attachment at (road, s) leaves: esmini's XYZ2TrackPos ends
/// with SetTrackPosMode → Position::SetLongitudinalTrackPos, which sets POS_STATUS_END_OF_ROAD
/// only at an end the road has no link element at (s within SMALL_NUMBER of 0 without a
/// predecessor, of its length without a successor) and clears it otherwise, whatever the
/// projection found: a link to a road the map lacks keeps the status clear.
pub(crate) fn unlinked_end_at(net: &RoadNetwork, road: usize, s: f64) -> bool {
    let Some(r) = net.roads.get(road) else { return false };
    (s < PAST && r.predecessor.is_none()) || (s > r.length - PAST && r.successor.is_none())
}
