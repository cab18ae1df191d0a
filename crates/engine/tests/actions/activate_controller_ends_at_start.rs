//! An ActivateControllerAction that finds its controller ends inside its own start:
//! ActivateControllerAction::Start calls End() at once ("action ends immediately"), so a
//! StoryboardElementStateCondition on its end in a later maneuver group is true in the same
//! frame. A TeleportAction, the control, ends in its first step, one frame later. The engine
//! ended the activation after its start frame, like the teleport. Found by a helper on
//! s75075_00617 (a LaneOffsetAction started one frame late, and a Looming car steered the other
//! way from then on).
//!
//! Fixture `activate_controller_ends_at_start.xosc` on straight.xodr: Ego's ACC is activated at
//! 1.01 s and Marker is teleported on that action's end; Marker2 is teleported on the end of a
//! TeleportAction started at 2.01 s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use std::f64::consts::PI;

#[test]
fn the_activation_ends_in_its_start_frame() {
    assert_fixture_matches_esmini(
        "activate_controller_ends_at_start.xosc",
        3.0,
        &[
            ("Marker", 1.01, 200.0, -1.75, 0.0),
            ("Marker", 1.02, 250.0, -1.75, 0.0),
            // the control: a teleport's end is seen the frame after its start
            ("Marker2", 2.02, 200.0, 1.75, PI),
            ("Marker2", 2.03, 250.0, 1.75, PI),
        ],
    );
}
