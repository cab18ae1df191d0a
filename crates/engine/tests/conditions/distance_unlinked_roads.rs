//! Distances in road and lane coordinates between roads no road path joins: esmini's
//! Position::Delta finds no path, Position::Distance fails, and the conditions read
//! LARGE_NUMBER (1e10) instead of the offset in the entity's frame (fixture
//! `distance_unlinked_roads.xosc` on `unlinked_roads.xodr`, two parallel roads 30 m apart;
//! esmini 3.6.0 logs rel_dist, HWT, TTC and dist of 1e10 or 1e9 at 0 s and starts every "Far"
//! event then, never LatRoadNear; the entity frame still measures 30 m).

use crate::common::*;

#[test]
fn no_road_path_is_a_large_distance() {
    let run = run_fixture_on("distance_unlinked_roads.xosc", "unlinked_roads.xodr", 4.0);
    for name in ["LatRoadFar", "LongLaneFar", "HeadwayLongRoad", "TtcLatPointRoad", "DistLongPointLane", "LongEntityNear"] {
        assert_eq!(event_time(&run, name, "start"), Some(0.0), "{name}");
    }
    assert_eq!(event_time(&run, "LatRoadNear", "start"), None);
}
