//! FollowTrajectoryAction with a TimeReference on an entity whose ACC controller in override
//! mode owns the longitudinal domain, as esmini 3.6 runs it (FollowTrajectoryAction::Move: the
//! timing is ignored and the entity moves along the trajectory at its own speed; Step: the
//! time never advances, so the action does not end, the entity staying at the trajectory's
//! end). Fixture `trajectory_under_acc.xosc` (straight.xodr; relative and absolute timing under
//! an ACC in override mode, and one in additive mode where the timing applies); the numbers are
//! esmini 3.6.0's run of it, and where esmini runs here the whole run is compared too.

mod common;
use common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn timing_is_ignored_while_an_acc_overrides_the_speed() {
    let run = run_fixture_scenario("trajectory_under_acc.xosc", 20.0);
    assert_matches_esmini("trajectory_under_acc.xosc", &run, 1e-3);
}
