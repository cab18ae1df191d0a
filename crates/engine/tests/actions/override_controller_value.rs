//! OverrideControllerValueAction as esmini 3.6.0 runs it (`OverrideControlAction` in
//! OSCPrivateAction.cpp): the values move nothing, but the action holds the control domains
//! its values leave set (`AddOverrideStatus`, folded in document order), so starting it ends
//! the entity's running actions on them (`Event::Start`); and releasing an active override of
//! an entity that follows a ghost restarts the ghost (`ScenarioEngine::InjectGhostRestart`).
//! Every figure below is esmini 3.6.0's on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

fn fixture_run(name: &str) -> engine::Run {
    let text = std::fs::read_to_string(fixtures().join(name)).expect("fixture readable");
    run(&text)
}

#[test]
fn an_override_ends_the_running_actions_on_the_domains_it_holds() {
    let run = fixture_run("override_domains.xosc");
    let ended = |action: &str| event_time(&run, action, "end");
    // esmini's log: "Stopping object Ego FasterA on conflicting Longitudinal domain(s)" at 2.0
    // (throttle on), ChangeA at 3.0 (steering on), Faster2A at 5.0 (brake off, then throttle
    // on), SlowerA at 7.5 (steering off, then gear on: the gear sets the longitudinal domain).
    for (action, t) in [("FasterA", 2.0), ("ChangeA", 3.0), ("Faster2A", 5.0), ("SlowerA", 7.5)] {
        let got = ended(action).unwrap_or(f64::NAN);
        assert!(close(got, t, 1e-9), "{action} ended at {got}, esmini at {t}");
    }
    // Throttle and steering off at 4.0 hold nothing; throttle on then brake off at 6.5 holds
    // nothing either: SlowerA (6.0 + 2 s) runs on until the gear at 7.5, and the lane change
    // started at 7.0 keeps going through the steering release at 7.5 (3 s long).
    assert!(ended("Change2A").map_or(true, |t| t > 9.9), "{:?}", ended("Change2A"));
    // The speed stays where FasterA left it (10 → 30 m/s over 5 s, cut at 2 s) until Faster2.
    assert!(close(at(&run, "Ego", 2.0).speed, 14.0, 1e-9) && close(at(&run, "Ego", 4.4).speed, 14.0, 1e-9), "{}", at(&run, "Ego", 4.4).speed);
    // The override actions themselves end in the step they start.
    assert!(close(ended("ThrottleOnA").unwrap_or(f64::NAN), 2.0, 1e-9));
    assert!(run.warnings.iter().any(|w| w.to_string().contains("the values are recorded and move nothing")), "{:?}", run.warnings);
}

#[test]
fn releasing_an_override_restarts_the_ghost_from_its_entity() {
    // Ego follows its ghost (head start 2 s); its throttle override goes on at 3.01 and off at
    // 6.01, where esmini logs "Trigging ghost restart on OverrideControllerAction inactivating
    // OVERRIDE_THROTTLE": the ghost takes the Ego's place of 6.01 s and time rewinds to 4.03.
    let run = fixture_run("override_ghost_restart.xosc");
    let ghost = at(&run, "Ego_ghost", 6.02);
    assert!(close(ghost.x, 130.0314, 1e-4) && close(ghost.y, -4.8514, 1e-4), "{ghost:?}");
    let ego = at(&run, "Ego", 6.01);
    assert!(close(ego.x, 130.0314, 1e-4) && close(ego.y, -4.8514, 1e-4), "{ego:?}");
    assert_eq!(run.trace.replays.len(), 1);
    assert!(close(run.trace.replays[0].start, 4.03, 1e-9), "{}", run.trace.replays[0].start);
    // The replay runs 4.03 .. 6.02 again (200 steps); its last row is esmini's second 6.02.
    let replay = &run.trace.replays[0];
    assert_eq!(replay.rows.len(), 200);
    let i = run.trace.entities.iter().position(|e| e.name == "Ego_ghost").expect("ghost in trace");
    let last = replay.rows[199][i].expect("ghost replayed");
    assert!(close(last.x, 160.0314, 1e-4) && close(last.y, -4.8514, 1e-4), "{last:?}");
    let notes: Vec<String> = run.warnings.iter().map(|w| w.to_string()).filter(|w| w.contains("restarts its ghost")).collect();
    assert_eq!(notes.len(), 1, "{:?}", run.warnings);
    assert!(notes[0].contains("releases the active Throttle override of `Ego`") && notes[0].contains("test.xosc:16:"), "{}", notes[0]);
}

#[test]
fn a_release_in_an_event_handed_to_the_ghost_restarts_it_earlier_and_its_other_actions_start_rewound() {
    // The release shares its event with a speed change handed to the ghost, so the event's
    // trigger moves 2 s earlier (6 → 4): the restart comes at 4.01, time rewinds to 2.03, and
    // the speed change (to 5 m/s over 2 s) starts on the rewound clock. Brake (never active)
    // and throttle are released together: one restart per released active value.
    let run = fixture_run("override_ghost_shared_event.xosc");
    let ghost = at(&run, "Ego_ghost", 4.02);
    assert!(close(ghost.x, 100.1682, 1e-4) && close(ghost.y, -2.0847, 1e-4) && close(ghost.speed, 14.95, 1e-4), "{ghost:?}");
    assert_eq!(run.trace.replays.len(), 1);
    assert!(close(run.trace.replays[0].start, 2.03, 1e-9), "{}", run.trace.replays[0].start);
    // At the end of the replay (esmini's second 4.02) the ghost has slowed to 5 m/s at 120.02 m.
    let replay = &run.trace.replays[0];
    let i = run.trace.entities.iter().position(|e| e.name == "Ego_ghost").expect("ghost in trace");
    let last = replay.rows[replay.rows.len() - 1][i].expect("ghost replayed");
    assert!(close(last.x, 120.0187, 1e-4) && close(last.speed, 5.0, 1e-9), "{last:?}");
}
