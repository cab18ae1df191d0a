//! While a FollowGhost ghost runs its head start, only the ghost's actions step: esmini's
//! `StoryBoard::Step` and `Event::Step` skip every other object's actions while the ghost mode
//! is RESTARTING (the head start is run as a restart). An Init action of another entity starts
//! (a SpeedAction sets its start speed) but first steps at time 0. Figures from esmini 3.6.0 on
//! this scenario (the corpus' init_actions_reorder and trail_test turn on the same rule).

use crate::common::*;

fn scenario() -> String {
    // Target accelerates at 2 m/s² from standstill: not before time 0.
    let init = ghost_ego_init(&format!("{}{}", teleport("Target", 100.0, -2), init_speed("Target", "linear", "rate", 2.0, 10.0)));
    let stop = stop_at(4.0);
    with_follow_ghost(&xosc(&init, "", &stop), 2.0)
}

#[test]
fn another_entitys_init_speed_action_steps_from_time_zero() {
    let run = run(&scenario());
    assert!(close(run.trace.start, -2.0, 1e-12), "{}", run.trace.start);
    // esmini: Target stands at x = 100 with speed 0 from −2 s to 0 s ...
    for t in [-2.0, -1.0, 0.0] {
        let s = at(&run, "Target", t);
        assert!(close(s.x, 100.0, 1e-9) && close(s.speed, 0.0, 1e-9), "t = {t}: x {} speed {}", s.x, s.speed);
    }
    // ... then speeds up by 0.02 m/s a step: x 100.0002 / 101.0100 / 104.0200 at 0.01 / 1 / 2 s.
    for (t, x, v) in [(0.01, 100.0002, 0.02), (1.0, 101.01, 2.0), (2.0, 104.02, 4.0)] {
        let s = at(&run, "Target", t);
        assert!(close(s.x, x, 1e-4) && close(s.speed, v, 1e-9), "t = {t}: x {} speed {}", s.x, s.speed);
    }
}

#[test]
fn the_ghost_alone_moves_during_the_head_start() {
    let run = run(&scenario());
    // esmini: the ghost 60 m at −1 s, 70 m at 0 s; the Ego waits at 50 m until time 0.
    assert!(close(at(&run, "Ego_ghost", -1.0).x, 60.0, 1e-9));
    assert!(close(at(&run, "Ego_ghost", 0.0).x, 70.0, 1e-9));
    assert!(close(at(&run, "Ego", 0.0).x, 50.0, 1e-9));
    assert!(close(at(&run, "Ego", 1.0).x, 60.0, 1e-4));
}
