//! A LateralDistanceAction in entity coordinates sets its entity's position from world
//! coordinates (Position::SetInertiaPos), whose XYZ2TrackPos sets the end-of-road status
//! afresh: only a point beyond the road's end has it. ScenarioEngine::step stops an entity
//! stuck at a road's end (status end of road, flagged there before, no motion in the last
//! step) — one the action has just moved back onto the road is not.
//!
//! Fixture `entity_frame_off_a_dead_end.xosc` on `straight.xodr`: Act drives (8 m/s) into the
//! road's end at s = 1000 at 1.25 s and stands there a step; the action (from 1.26 s) keeps it
//! 6 m left of Ref, standing at a heading of 6.27 rad, and its first step moves it onto that
//! line, a few millimetres back onto the road. In esmini's run (3.6.0) Act keeps its 8 m/s and
//! drives on along the line, past the road's end; an engine that still took it for stuck at
//! the end would stop it there. The numbers are esmini's.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn an_entity_moved_back_onto_the_road_is_not_stuck_at_its_end() {
    let run = assert_fixture_matches_esmini(
        "entity_frame_off_a_dead_end.xosc",
        3.0,
        &[("Act", 1.27, 999.993234, -2.263111, 6.27), ("Act", 2.0, 1005.832726, -2.340111, 6.27)],
    );
    assert!(close(at(&run, "Act", 1.27).speed, 8.0, 1e-9), "{:?}", at(&run, "Act", 1.27));
}
