//! The control domain esmini 3.6 gives a LateralDistanceAction: LatDistanceAction hands the
//! domain index DOMAIN_LAT (1) where a mask is wanted, which is DOMAIN_MASK_LONG, so starting
//! one ends the entity's running speed action, and a speed action started later ends it
//! (Event::Start's conflict check).
//!
//! Fixture `lateral_distance_domain.xosc` on straight.xodr: "Speeding" accelerates from 0.5 s
//! and is held at 13 m/s when its LateralDistanceAction starts at 2 s; "Kept" keeps a
//! continuous lateral distance from 1 s until a speed action at 3 s ends it. The numbers are
//! esmini 3.6.0's run; where esmini runs here the whole run is compared.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn a_lateral_distance_action_ends_a_running_speed_action_and_is_ended_by_one() {
    let run = run_fixture_scenario("lateral_distance_domain.xosc", 20.0);
    for t in [2.5, 4.0, 7.0] {
        let s = at(&run, "Speeding", t);
        assert!(close(s.speed, 13.0, 1e-9), "Speeding at {t}: speed {} (the acceleration goes on)", s.speed);
    }
    assert_esmini_pose_at(&run, "Speeding", 4.0, 16.625, 7.75, std::f64::consts::PI);
    assert_esmini_pose_at(&run, "Kept", 7.0, 8.27, 9.75, std::f64::consts::PI);
    assert_matches_esmini("lateral_distance_domain.xosc", &run, 1e-3);
}
