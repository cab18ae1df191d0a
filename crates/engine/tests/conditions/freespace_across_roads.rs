//! Freespace distances in road and lane coordinates across roads (fixture
//! `freespace_across_roads.xosc` on `crossing.xodr`): esmini's Object::
//! FreeSpaceDistancePointRoadLane and FreeSpaceDistanceObjectRoadLane place every corner on the
//! road network from the entity's position and measure each pair by Position::Delta along the
//! road path through the junction. esmini 3.6.0 logs dist 57.52 (PointLongNear), 2.50
//! (PointLatNear), rel_dist 76.42 (TargetLongNear), and 0.00, 0.00, 2.50 for Edge, whose front
//! corners inside the junction keep its heading relative to its own road and so face against
//! the connecting road; it starts every Near event and Edge's at 0 s, never a Far one. The
//! world-frame gaps measured before gave 34.35 m and 33.35 m along, 27 m across.

use crate::common::*;

#[test]
fn corners_on_other_roads_are_measured_along_the_road_path() {
    let run = run_fixture_on("freespace_across_roads.xosc", "crossing.xodr", 1.0);
    for name in ["PointLongNear", "PointLatNear", "TargetLongNear", "EdgeAhead", "EdgeBehind", "EdgeLat"] {
        assert_eq!(event_time(&run, name, "start"), Some(0.0), "{name}");
    }
    for name in ["PointLongFar", "PointLatFar", "TargetLongFar"] {
        assert_eq!(event_time(&run, name, "start"), None, "{name}");
    }
}

#[test]
fn a_target_on_an_unreachable_road_is_measured_on_the_entitys_own_road() {
    // freespace_unlinked_roads.xosc on unlinked_roads.xodr: esmini 3.6.0 logs dist 1e10 to the
    // point on the other road (no path: not measured) and rel_dist 15.00 and 28.00 to Target,
    // whose corners it places on Ego's road (connectedOnly).
    let run = run_fixture_on("freespace_unlinked_roads.xosc", "unlinked_roads.xodr", 1.0);
    for name in ["PointFar", "TargetLongNear", "TargetLatNear"] {
        assert_eq!(event_time(&run, name, "start"), Some(0.0), "{name}");
    }
    for name in ["TargetFar", "TargetLongUnder", "TargetLatUnder"] {
        assert_eq!(event_time(&run, name, "start"), None, "{name}");
    }
}
