//! A timed FollowTrajectoryAction under an ACC in override mode is followed at the ACC's speed,
//! as if untimed (esmini's FollowTrajectoryAction::Move: `IsControllerModeOnDomains(
//! MODE_OVERRIDE, DOMAIN_MASK_LONG)` takes the untimed branch, its clock stands still, so the
//! time stamps never end it), while the ACC moves the entity along the road on top each step
//! and takes the trajectory's start speed as its new set speed. Fixture
//! `acc_override_timed_trajectory.xosc` (straight road): Ego's ACC (override, 20 m/s); at
//! t > 1 a polyline timed at 5 m/s (relative timing), straight for 50 m, then 3.5 m to the
//! right over 50 m. Expected values: esmini 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn a_timed_trajectory_is_followed_at_the_overriding_acc_speed() {
    let run = run_straight_fixture("acc_override_timed_trajectory.xosc", 13.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini's rows (x, y, speed): the ACC slows from 20 to the trajectory's 5 m/s at its 5 m/s²
    // while the entity advances along the path at that speed.
    assert_esmini_rows(
        &run,
        "Ego",
        &[
            (1.02, 30.2495, -1.75, 19.95),
            (1.03, 30.4485, -1.75, 19.9),
            (2.0, 47.375, -1.75, 15.05),
            (5.0, 72.617816, -1.75, 5.015174),
            (8.0, 87.603516, -2.278746, 5.0),
            (12.0, 107.554696, -3.675329, 5.0),
        ],
        1e-3,
    );
    // Timed at 5 m/s the path would be over at 21 s; esmini's clock never moves, so it runs on.
    assert!(run.trace.events.iter().all(|ev| ev.element != "Along" || ev.to != "complete" || ev.time > 12.0));
}
