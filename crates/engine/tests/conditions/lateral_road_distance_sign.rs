//! A lateral distance in road coordinates between entities on one road is the second's t less
//! the first's whichever way the first faces (esmini's Position::Delta), so an entity facing
//! against s with its target right of the reference line has neither time headway nor time to
//! collision (fixture `lateral_road_distance_sign.xosc`; esmini 3.6.0 starts HeadwayAlong and
//! TtcAlong at 0 s, logging 0.35 s, and never HeadwayAgainst or TtcAgainst).

use crate::common::*;

#[test]
fn a_lateral_road_distance_does_not_turn_with_the_entity() {
    let run = run_straight_fixture("lateral_road_distance_sign.xosc", 1.0);
    assert_eq!(event_time(&run, "HeadwayAlong", "start"), Some(0.0));
    assert_eq!(event_time(&run, "TtcAlong", "start"), Some(0.0));
    assert_eq!(event_time(&run, "HeadwayAgainst", "start"), None);
    assert_eq!(event_time(&run, "TtcAgainst", "start"), None);
}
