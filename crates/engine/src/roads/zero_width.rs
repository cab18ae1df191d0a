//! esmini's rule for a lane that has narrowed to nothing: after every move along the road, an
//! entity whose lane is (or became) zero wide is put on the centre of a lane of the types it
//! snaps to on the same side of the road — the one containing its point, else the one whose
//! centre is nearest (esmini's `Position::MoveAlongS`, "lane is or became zero width, moved to
//! closest available lane", LaneSection::GetClosestLaneIdx with the side of its lane). A merge
//! lane that ends thus drops its vehicle into the neighbouring lane in one step, without a lane
//! change; a pedestrian may land on a sidewalk.

use super::lane_position::LanePos;
use opendrive::RoadNetwork;

/// Narrower than this is zero wide (esmini's SMALL_NUMBER).
const ZERO_WIDTH: f64 = 1e-6;

/// Move `pos` to the centre of the lane esmini picks when its own lane has no width at its s
/// (`sidewalks`: a pedestrian's lane types). Returns whether it moved.
pub(crate) fn leave_zero_width_lane(net: &RoadNetwork, pos: &mut LanePos, sidewalks: bool) -> bool {
    let Some(road) = net.roads.get(pos.road) else { return false };
    leave_zero_width_lane_in(net, pos, road.section_index_at(pos.s), sidewalks)
}

/// [`leave_zero_width_lane`] when the caller knows the lane section at `pos.s` already.
pub(crate) fn leave_zero_width_lane_in(net: &RoadNetwork, pos: &mut LanePos, section: usize, sidewalks: bool) -> bool {
    let Some(road) = net.roads.get(pos.road) else { return false };
    if super::lane_shape::lane_shape(road, section, pos.lane_id).never_zero_width {
        return false;
    }
    // Memoised: the pose of this step asks for the same borders next.
    let Some(b) = super::pose_memo::lane_borders_at(road, pos.lane_id, pos.s) else { return false };
    if pos.lane_id == 0 || b.width() >= ZERO_WIDTH {
        return false;
    }
    let t = b.center + pos.offset;
    let side = pos.lane_id.signum();
    let Some((lane_id, _)) = super::lane_snap::snap_on_side(road, section, pos.s, t, sidewalks, side) else { return false };
    if lane_id == pos.lane_id {
        return false;
    }
    // The direction of travel along s is kept, as esmini keeps the heading.
    pos.lane_id = lane_id;
    pos.offset = 0.0;
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn net(xodr: &str) -> RoadNetwork {
        opendrive::parse_str(xodr, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"))
    }

    /// One 100 m road along +x: lane -1 3.5 m wide, lane -2 3 m wide ending (width 0) from
    /// s = 50 on, lane -3 a border.
    const ROAD: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="100"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/><width sOffset="50" a="0" b="0" c="0" d="0"/></lane>
<lane id="-3" type="border"><width sOffset="0" a="0.3" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;

    #[test]
    fn a_vehicle_in_an_ended_lane_drops_into_the_nearest_driving_lane() {
        let n = net(ROAD);
        // Before the end lane -2 is 3 m wide: nothing happens.
        let mut p = LanePos { road: 0, lane_id: -2, s: 49.0, offset: 0.2, dir: 1.0 };
        assert!(!leave_zero_width_lane(&n, &mut p, false));
        assert_eq!((p.lane_id, p.offset), (-2, 0.2));
        // At s = 60 lane -2 has no width: its centre is t = -3.5, the border's centre -3.65
        // (not drivable), lane -1's centre -1.75: the entity goes to lane -1, offset 0.
        let mut p = LanePos { road: 0, lane_id: -2, s: 60.0, offset: 0.0, dir: 1.0 };
        assert!(leave_zero_width_lane(&n, &mut p, false));
        assert_eq!((p.lane_id, p.offset, p.s), (-1, 0.0, 60.0));
    }
}
