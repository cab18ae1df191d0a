//! Whether a world point lies beyond the end of the road it was located on: esmini's
//! Position::XYZ2TrackPos sets POS_STATUS_END_OF_ROAD when the closest point of the road network
//! does not fall inside any road's s range (`closestPointInside`), as for an entity a trajectory
//! has carried past a dead end.

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
