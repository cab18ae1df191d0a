//! The lane esmini attaches a point to: the lane containing it among the lane types its
//! entity snaps to (esmini's "any driving" set; a pedestrian's own position adds sidewalks), else the one whose
//! centre is nearest, lanes of zero width left out (LaneSection::GetClosestLaneIdx with
//! Position::snapToLaneTypes_). A car put on a border lane or a parking bay beside the road is
//! in the nearest driving lane, at a large offset from its centre.

use super::lane_geometry::lane_borders;
use opendrive::{LanePosition, LaneType, Road, RoadNetwork};

/// esmini's SMALL_NUMBER: narrower lanes do not count.
const MIN_WIDTH: f64 = 1e-6;

/// The lane and the offset from its centre of point (s, t) in section `section` of `road`
/// (`sidewalks`: a pedestrian's types); `None` when no lane of the types qualifies (esmini then
/// keeps the reference lane).
pub(crate) fn snap(road: &Road, section: usize, s: f64, t: f64, sidewalks: bool) -> Option<(i32, f64)> {
    snap_on_side(road, section, s, t, sidewalks, 0)
}

/// The lane and offset of a point located from world coordinates (Position::XYZ2TrackPos):
/// [`snap`]ped, else the located lane and offset as they are.
pub(crate) fn snap_located(net: &RoadNetwork, found: &LanePosition, sidewalks: bool) -> (i32, f64) {
    net.roads.get(found.road).and_then(|r| snap(r, found.section, found.s, found.t, sidewalks)).unwrap_or((found.lane_id, found.offset))
}

/// [`snap`] among the lanes of one side (`side` −1 right, +1 left; 0 both).
pub(crate) fn snap_on_side(road: &Road, section: usize, s: f64, t: f64, sidewalks: bool, side: i32) -> Option<(i32, f64)> {
    let sec = road.lane_sections.get(section)?;
    let allowed = |k: LaneType| k.is_any_driving() || (sidewalks && k == LaneType::Sidewalk);
    let mut best: Option<(f64, i32, f64)> = None;
    for lane in sec.left.iter().rev().chain(sec.right.iter()) {
        if !allowed(lane.kind) || (side != 0 && lane.id.signum() != side) {
            continue;
        }
        let Some(b) = lane_borders(road, section, lane.id, s) else { continue };
        let width = b.width();
        if width <= MIN_WIDTH {
            continue;
        }
        let off = t - b.center;
        if off.abs() < 0.5 * width {
            return Some((lane.id, off));
        }
        if best.is_none_or(|(d, _, _)| off.abs() < d) {
            best = Some((off.abs(), lane.id, off));
        }
    }
    best.map(|(_, id, off)| (id, off))
}
