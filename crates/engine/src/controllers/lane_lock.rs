//! A position locked on its lane (esmini's `Position::SetLockOnLane(true)`, which the looming
//! controller sets before it places its entity): when a world pose is attached to the road, the
//! lane is not the one containing the point but the one at the lateral position of the lane
//! the entity was in (Position::XYZ2TrackPos, `lockOnLane_` branch), and the offset is measured
//! from that lateral position. So a lane change under a longitudinal-only controller makes the
//! target lane the entity's lane at once, and the controller's vehicle then steers towards it.

use crate::angles::wrap;
use crate::entities::{Entity, EntityKind};
use crate::roads::lane_geometry::lane_borders;
use crate::roads::LanePos;
use opendrive::{ContactPoint, Road, RoadNetwork};

/// The signed lateral position (t) of lane `lp`'s centre without the road's lane offset
/// (`SIGN(lane_id) · LaneSection::GetCenterOffset`), in the section at `lp.s`.
fn centre_without_lane_offset(road: &Road, lp: &LanePos) -> Option<f64> {
    let section = road.section_index_at(lp.s);
    let b = lane_borders(road, section, lp.lane_id, lp.s)?;
    Some(b.center - road.lane_offset_at(lp.s))
}

/// Whether `from` links directly to `to` end to end or start to start (XYZ2TrackPos's
/// `change_direction`: the road ids are compared whatever the link's element type).
fn turns_round(from: &Road, to: &Road) -> bool {
    let links_to = |link: Option<&opendrive::RoadLink>, contact: ContactPoint| link.is_some_and(|l| l.element_id == to.id && l.contact_point == Some(contact));
    links_to(from.successor.as_ref(), ContactPoint::End) || links_to(from.predecessor.as_ref(), ContactPoint::Start)
}

impl Entity {
    /// Position::SetInertiaPos with `lockOnLane_`: place the entity at the world pose, then keep
    /// it in the lane at the lateral position of `before` (its lane before the move), the offset
    /// measured from that position (`latOffset − fixed_t`).
    pub(crate) fn set_world_lane_locked(&mut self, net: Option<&RoadNetwork>, x: f64, y: f64, h: f64, before: Option<LanePos>) {
        self.set_world_from(net, x, y, h, before);
        let (Some(net), Some(before), Some(now)) = (net, before, self.lane) else { return };
        let (Some(old_road), Some(road)) = (net.roads.get(before.road), net.roads.get(now.road)) else { return };
        let Some(centre) = centre_without_lane_offset(old_road, &before) else { return };
        let section = road.section_index_at(now.s);
        let Some(b) = lane_borders(road, section, now.lane_id, now.s) else { return };
        let t = b.center + now.offset;
        let flip = before.road != now.road && turns_round(old_road, road);
        // XYZ2TrackPos divides fixed_t by cos(GetRRoad()) ("compensate for banking"): the roll
        // the position still holds, the road's at the position before the move.
        let roll_before = crate::roads::banking::roll_at(old_road, before.s).0;
        let fixed_t = (if flip { -centre } else { centre } + road.lane_offset_at(now.s)) / crate::dynamics::esmini_avoid_zero(roll_before.cos());
        let sidewalks = self.kind == EntityKind::Pedestrian;
        let Some((lane_id, _)) = crate::roads::lane_snap::snap(road, section, now.s, fixed_t, sidewalks) else { return };
        if lane_id == now.lane_id && (t - fixed_t - now.offset).abs() < 1e-12 {
            return;
        }
        let locked = LanePos { lane_id, offset: t - fixed_t, ..now };
        // The heading relative to the lane leaves out the drift of the lane it is in.
        let yaw = self.yaw_offset + self.drift(net, &now);
        self.yaw_offset = wrap(yaw - self.drift(net, &locked));
        self.lane = Some(locked);
    }
}
