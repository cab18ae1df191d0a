//! A free-space euclidean distance between two entities is signed: Object::Distance multiplies
//! Object::FreeSpaceDistance by the sign of the longitudinal gap that
//! CollisionAndRelativeDistLatLong measures along the triggering entity's heading, so a target
//! wholly behind is at a negative distance. TrigByTimeHeadway::CheckCondition then ignores it
//! (rel_dist < 0), and Object::TimeToCollision divides the negative distance by a negative
//! closing speed: a faster car coming up from behind has a time to collision. Fixture
//! `freespace_distance_sign.xosc` on `straight.xodr`: Ego at s = 100 at 10 m/s, Chaser 30 m
//! behind it at 20 m/s (boxes 25.5 m apart); "Ttc" waits for Ego's TTC to Chaser < 2 s, "Headway"
//! for Ego's headway to Chaser < 10 s, both free space, entity coordinates. esmini 3.6.0 on the
//! fixture: Ttc at 0.56 s (TTC 1.99 s), Headway at 2.55 s, when the boxes touch (distance 0).

use crate::common::*;

#[test]
fn a_target_behind_is_at_a_negative_free_space_distance() {
    let run = run_fixture_on("freespace_distance_sign.xosc", "straight.xodr", 5.0);
    let start = |name: &str| run.trace.events.iter().find(|ev| ev.element == name && ev.to == "running").map(|ev| ev.time);
    assert!(start("Ttc").is_some_and(|t| close(t, 0.56, 1e-9)), "{:?}", start("Ttc"));
    assert!(start("Headway").is_some_and(|t| close(t, 2.55, 1e-9)), "{:?}", start("Headway"));
}
