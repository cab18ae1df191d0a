//! A LongitudinalDistanceAction with displacement "any" takes its side at the start from the
//! reference's position along the actor's own heading (LongDistanceAction::Start:
//! Position::getRelativeDistance's x), whatever coordinate system the distance is measured in.
//! Fixture `long_distance_any_side_from_heading.xosc` on straight.xodr: Ego stands in lane 2
//! facing 1.2 rad left of the road, Target 15 m further along s in lane -2: ahead along the
//! road, behind along Ego's heading. So Ego is to lead it, and drives past it (esmini 3.6.0:
//! x 121.09 at 6 s, Target at 115); in entity coordinates the same for Ego2.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "long_distance_any_side_from_heading.xosc";

#[test]
fn any_takes_the_side_along_the_actors_heading() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    let ego = at(&run, "Ego", 6.0);
    assert!(ego.x > 120.0, "Ego leads Target (x 115): {ego:?}");
    assert_esmini_pose_at(&run, "Ego", 6.0, 121.092787, 5.25, 1.2);
    assert_esmini_pose_at(&run, "Ego2", 6.0, 308.847095, 5.25, 1.2);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}
