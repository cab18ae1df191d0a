//! A teleport keeps the position status of the entity's last move (esmini's Position::TeleportTo
//! copies the location only: CopyLocation leaves `status_`), and ScenarioEngine::step, after
//! every object's default move, stops an object whose status says end of road, already flagged
//! there, and whose last velocity is zero. So an entity stuck at a dead end and teleported away
//! in the same step as a speed change stays stopped where it was put. Checked against an esmini
//! 3.6.0 run of the scenario built here (`write_for_esmini`; the asserted numbers are esmini's).

use crate::common::*;

/// Ego at 10 m/s on lane -1 from s = 995 of the 1,000 m dead-end road (stuck at its end from
/// 0.5 s); at 1 s a speed step to 3 m/s and a teleport to s = 500, in that order.
fn stuck_then_teleported() -> String {
    let speed = format!("<PrivateAction><LongitudinalAction>{}</LongitudinalAction></PrivateAction>", speed_action("step", "time", 0.0, 3.0));
    let hop = format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(500.0, -1));
    let start = trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0));
    let events = format!("{}{}", event("Speed", "parallel", &speed, &start), event("Hop", "parallel", &hop, &start));
    xosc(&format!("{}{}", placed_in_one_private("Ego", 995.0, -1, 10.0), teleport("Target", 100.0, -2)), &story("Ego", &events), &stop_at(3.0))
}

#[test]
fn an_entity_stuck_at_a_dead_end_stays_stopped_after_a_teleport() {
    let run = run(&stuck_then_teleported());
    // esmini: x = 500, speed 0 from 1.01 s to the end (without the rule: 3 m/s, x = 502.97 at 2 s)
    for t in [1.01, 2.0, 3.0] {
        let s = at(&run, "Ego", t);
        assert!((s.x - 500.0).abs() < 1e-6 && s.speed.abs() < 1e-9, "{t}: {s:?}");
    }
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("stuck_then_teleported.xosc"), stuck_then_teleported()).expect("write");
}
