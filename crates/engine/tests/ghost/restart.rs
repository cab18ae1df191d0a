//! esmini's ghost restart (`ghost_restart.rs`): an event handed to the ghost whose start trigger
//! watches something other than the simulation time or the ghost gets an `AddedGhostTeleport`
//! (esmini's `ScenarioEngine::ReplaceObjectInTrigger` / `CreateGhostTeleport`). Started during
//! the head start it puts the ghost back onto its entity; started after time 0 it restarts the
//! ghost (`TeleportAction::Start`): the ghost takes the entity's place and speed, then time
//! rewinds by the head start and runs again with only the ghost moving, the entity frozen.
//! Figures from esmini 3.6.0 on these scenarios (the corpus' ghost_restart and
//! driver_lane_bouncing_scenario match esmini's log row by row the same way).

use crate::common::*;

/// Ego at s = 50 (10 m/s, head start 2 s), Target standing at s = 300; the story's event
/// `Drift` moves the ghost 0.5 m left when its start trigger (`groups`) fires.
fn ghost_scenario(groups: &str) -> String {
    let init = ghost_ego_init(&teleport("Target", 300.0, -1));
    let offset = r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="0.5"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Drift", "overwrite", offset, &format!("<StartTrigger>{groups}</StartTrigger>")));
    with_follow_ghost(&xosc(&init, &stories, &stop_at(5.0)), 2.0)
}

fn group(condition: &str) -> String {
    format!("<ConditionGroup>{condition}</ConditionGroup>")
}

/// Ego within `metres` of s = 300 along the road (a condition on the entity that is not handed
/// to the ghost: the event gets an added teleport).
fn near(metres: f64) -> String {
    format!(
        r#"<Condition name="near" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><DistanceCondition value="{metres}" freespace="false" rule="lessThan" relativeDistanceType="longitudinal" coordinateSystem="road"><Position><LanePosition roadId="1" laneId="-1" s="300" offset="0"/></Position></DistanceCondition></EntityCondition></ByEntityCondition></Condition>"#
    )
}

/// Ego (handed to the ghost) within 1 m of s = 60.
fn reach() -> String {
    r#"<Condition name="reach" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><ReachPositionCondition tolerance="1.0"><Position><LanePosition roadId="1" laneId="-1" s="60" offset="0"/></Position></ReachPositionCondition></EntityCondition></ByEntityCondition></Condition>"#.to_string()
}

/// The ghost scenario with `Drift` started when the Ego is within 240 m of s = 300 and a second
/// event, `Drift2` (the ghost 0.5 m right), when it is within 215 m: both restart the ghost.
fn two_restarts() -> String {
    let drift2 = event(
        "Drift2",
        "parallel",
        r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="-0.5"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#,
        &format!("<StartTrigger>{}</StartTrigger>", group(&near(215.0).replace("name=\"near\"", "name=\"near2\""))),
    );
    ghost_scenario(&group(&near(240.0))).replacen("</Event></Maneuver>", &format!("</Event>{drift2}</Maneuver>"), 1)
}

fn restart_notes(run: &engine::Run) -> Vec<String> {
    run.warnings.iter().map(|w| w.to_string()).filter(|w| w.contains("started after time 0, where esmini restarts the ghost")).collect()
}

/// Sample of `entity` at time `t` of the (only) replay.
fn replayed(run: &engine::Run, entity: &str, t: f64) -> engine::Sample {
    let i = run.trace.entities.iter().position(|e| e.name == entity).expect("entity in trace");
    let r = run.trace.replays.first().expect("a replay");
    let j = ((t - r.start) / run.trace.step).round() as usize;
    r.rows.get(j).and_then(|row| row.get(i)).copied().flatten().expect("replayed sample exists")
}

fn xy(s: engine::Sample) -> (f64, f64) {
    (s.x, s.y)
}

fn near_xy(s: engine::Sample, x: f64, y: f64) -> bool {
    close(s.x, x, 1e-4) && close(s.y, y, 1e-4)
}

#[test]
fn an_event_after_time_zero_restarts_the_ghost_and_time_runs_again() {
    // Ego comes within 240 m of s = 300 at 1.01 s; esmini restarts the ghost in that step.
    let run = run(&ghost_scenario(&group(&near(240.0))));
    // The ghost takes the Ego's place of 1.01 s (60.1 m) and does not move in that step; the
    // Ego, following an empty trail, slows to 9.9 m/s.
    assert!(near_xy(at(&run, "Ego_ghost", 1.02), 60.1, -1.75), "{:?}", xy(at(&run, "Ego_ghost", 1.02)));
    assert!(near_xy(at(&run, "Ego", 1.02), 60.199, -1.75), "{:?}", xy(at(&run, "Ego", 1.02)));
    // Then time goes back 2 s: steps -0.97 .. 1.02 run again, logged after the row of 1.02.
    assert_eq!(run.trace.replays.len(), 1);
    let r = &run.trace.replays[0];
    let k102 = ((1.02 - run.trace.start) / run.trace.step).round() as usize;
    assert_eq!(r.after, k102);
    assert!(close(r.start, -0.97, 1e-9), "{}", r.start);
    assert_eq!(r.rows.len(), 200);
    // Only the ghost moves (lane offset 0.5 m done): 74.9 m at 0.5 s, 80.1 m at 1.02 s.
    assert!(near_xy(replayed(&run, "Ego_ghost", 0.5), 74.9, -1.25), "{:?}", xy(replayed(&run, "Ego_ghost", 0.5)));
    assert!(near_xy(replayed(&run, "Ego_ghost", 1.02), 80.1, -1.25), "{:?}", xy(replayed(&run, "Ego_ghost", 1.02)));
    for t in [-0.97, 0.5, 1.02] {
        let e = replayed(&run, "Ego", t);
        assert!(near_xy(e, 60.199, -1.75) && close(e.speed, 9.9, 1e-9), "t = {t}: {:?}", xy(e));
    }
    // Afterwards the Ego follows the new trail: esmini has (79.9842, -1.2931) at 3 s.
    assert!(near_xy(at(&run, "Ego", 3.0), 79.9842, -1.2931), "{:?}", xy(at(&run, "Ego", 3.0)));
    assert!(near_xy(at(&run, "Ego_ghost", 3.0), 99.9, -1.25), "{:?}", xy(at(&run, "Ego_ghost", 3.0)));
    // The CSV lists the replayed rows where esmini's log has them.
    let csv = run.trace.to_csv(&[]);
    let a = csv.find("1.020,Ego_ghost,60.1000").expect("restart row");
    let b = a + csv[a..].find("-0.970,Ego_ghost,60.2000").expect("replayed row after it");
    assert!(csv[a..b].lines().count() == 3, "the replay follows the row of 1.02 s (ghost 1.02, Ego and Target −0.97)");
    // And the run says so, at the condition.
    let w = restart_notes(&run);
    assert_eq!(w.len(), 1, "{:?}", run.warnings);
    assert!(w[0].contains("condition `near`") && w[0].contains("event `Drift`") && w[0].contains("test.xosc:"), "{}", w[0]);
}

#[test]
fn an_added_teleport_during_the_head_start_puts_the_ghost_back_on_its_entity() {
    // The ghost reaches s = 59 at −1.10 s; the event starts (its other group, `near`, gives it
    // the added teleport) and esmini puts the ghost back at the Ego (50 m): no restart.
    let run = run(&ghost_scenario(&format!("{}{}", group(&reach()), group(&near(1.0)))));
    assert!(near_xy(at(&run, "Ego_ghost", -1.10), 59.0, -1.75), "{:?}", xy(at(&run, "Ego_ghost", -1.10)));
    assert!(near_xy(at(&run, "Ego_ghost", -1.09), 50.0, -1.75), "{:?}", xy(at(&run, "Ego_ghost", -1.09)));
    assert!(near_xy(at(&run, "Ego_ghost", -1.0), 50.9, -1.7423), "{:?}", xy(at(&run, "Ego_ghost", -1.0)));
    assert!(run.trace.replays.is_empty());
    assert!(restart_notes(&run).is_empty(), "{:?}", run.warnings);
}

#[test]
fn a_simulation_time_trigger_moves_earlier_without_a_restart() {
    let run = run(&ghost_scenario(&group(&sim_time(1.0, "greaterThan", "none", 0.0))));
    assert!(run.trace.replays.is_empty());
    assert!(restart_notes(&run).is_empty(), "{:?}", run.warnings);
}

#[test]
fn a_later_restart_makes_completed_restart_events_ready_again() {
    // `Drift` restarts the ghost at 1.01 s and completes; `Drift2` restarts it again at 3.51 s.
    // esmini's ResetEvents then puts `Drift` back to standby ("Reset event Drift"), it fires in
    // the first rewound step (1.52 s) and restarts the ghost once more, which resets `Drift2`:
    // time goes back from 1.02 s to -0.97 s, from 3.52 s to 1.53 s and at once from 1.53 s to
    // -0.46 s, and each event's action runs three times.
    let text = two_restarts();
    let run = run(&text);
    let replays: Vec<(f64, usize)> = run.trace.replays.iter().map(|r| (r.start, r.rows.len())).collect();
    assert_eq!(replays.len(), 3, "{replays:?}");
    for ((start, rows), (s, n)) in replays.iter().zip([(-0.97, 200), (1.53, 1), (-0.46, 399)]) {
        assert!(close(*start, s, 1e-9) && *rows == n, "{replays:?}");
    }
    let starts = |name: &str| run.trace.events.iter().filter(|e| e.element == name && e.transition == "start").count();
    assert_eq!((starts("DriftAction"), starts("Drift2Action")), (3, 3));
    // esmini: in the last rewound run the Ego waits at (85.2811, -1.2556) while the ghost
    // drives (102.4081, -2.25 at 1.27 s); at 5 s the Ego is at (99.9204, -1.5669).
    let i = run.trace.entities.iter().position(|e| e.name == "Ego_ghost").expect("ghost");
    let r = &run.trace.replays[2];
    let replayed = |t: f64, e: usize| r.rows[((t - r.start) / run.trace.step).round() as usize][e].expect("sample");
    assert!(near_xy(replayed(1.27, i), 102.4081, -2.25), "{:?}", xy(replayed(1.27, i)));
    assert!(near_xy(replayed(1.27, 0), 85.2811, -1.2556), "{:?}", xy(replayed(1.27, 0)));
    assert!(near_xy(at(&run, "Ego", 5.0), 99.9204, -1.5669), "{:?}", xy(at(&run, "Ego", 5.0)));
}

#[test]
fn the_actions_of_a_restarting_event_start_and_run_on_the_rewound_clock() {
    // A SpeedProfileAction (15 m/s in 2 s, then 5 m/s in 2 s) in the restarting event: esmini
    // starts it at the time less the head start (Event::Start's adjusted time), so in the
    // rewound run the ghost speeds up from -0.97 s: 12.475 m/s at 0 s (71.1372 m), 14.975 m/s
    // at 1 s (84.8748 m); the Ego is at 97.4375 m at 4 s.
    let profile = r#"<PrivateAction><LongitudinalAction><SpeedProfileAction followingMode="follow"><SpeedProfileEntry speed="15" time="2"/><SpeedProfileEntry speed="5" time="2"/></SpeedProfileAction></LongitudinalAction></PrivateAction>"#;
    let offset = r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="0.5"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#;
    let text = ghost_scenario(&group(&near(240.0))).replacen(offset, profile, 1);
    let run = run(&text);
    let ghost = replayed(&run, "Ego_ghost", 0.0);
    assert!(near_xy(ghost, 71.1372, -1.75) && close(ghost.speed, 12.475, 1e-9), "{:?} {}", xy(ghost), ghost.speed);
    let ghost = replayed(&run, "Ego_ghost", 1.0);
    assert!(near_xy(ghost, 84.8748, -1.75) && close(ghost.speed, 14.975, 1e-9), "{:?} {}", xy(ghost), ghost.speed);
    assert!(near_xy(at(&run, "Ego", 4.0), 97.4375, -1.75), "{:?}", xy(at(&run, "Ego", 4.0)));
}

#[test]
fn restarts_that_never_stop_rewinding_end_the_run_with_a_warning() {
    // As above, but both events may run 100000 times: each restart re-arms the other event,
    // which restarts the ghost again before the rewound time catches up. esmini runs on
    // forever (killed after a million frames still at -0.5 s); osc2cr caps the rewound frames
    // at ten per step of the run and ends it, saying so.
    let text = two_restarts()
        .replace(r#"<Event name="Drift" priority="overwrite">"#, r#"<Event name="Drift" priority="overwrite" maximumExecutionCount="100000">"#)
        .replace(r#"<Event name="Drift2" priority="parallel">"#, r#"<Event name="Drift2" priority="parallel" maximumExecutionCount="100000">"#);
    let run = run(&text);
    let rewound: usize = run.trace.replays.iter().map(|r| r.rows.len()).sum();
    assert!(rewound <= 10 * 2200, "{rewound}");
    let ended: Vec<String> = run.warnings.iter().map(|w| w.to_string()).filter(|w| w.contains("kept rewinding time")).collect();
    assert_eq!(ended.len(), 1, "{:?}", run.warnings);
    assert!(ended[0].contains("test.xosc:"), "{}", ended[0]);
}

/// The ghost scenario with a second event, `Faster` (the ghost to 20 m/s at once), started when
/// the ghost has travelled 100 m (a traveled-distance condition handed to the ghost).
fn travelled_after_restart() -> String {
    let faster = event(
        "Faster",
        "parallel",
        &speed_action("step", "time", 0.0, 20.0),
        r#"<StartTrigger><ConditionGroup><Condition name="far" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><TraveledDistanceCondition value="100"/></EntityCondition></ByEntityCondition></Condition></ConditionGroup></StartTrigger>"#,
    );
    ghost_scenario(&group(&near(240.0))).replacen("</Event></Maneuver>", &format!("</Event>{faster}</Maneuver>"), 1).replace(&stop_at(5.0), &stop_at(8.0))
}

#[test]
fn a_restart_counts_the_ghosts_jump_back_as_travel() {
    // esmini's ScenarioEngine::prepareStep measures nothing of the ghost in the step of its
    // restart (RESTART mode) and keeps its old state, so the first rewound step adds the jump
    // from 80.0 m back to the Ego (60.2 m) to the ghost's odometer. esmini 3.6.0 starts
    // `Faster` at 4.03 s (without that jump it would be about 2 s later): the ghost is at
    // 109.9 m at 4 s and at 119.6 m at 4.5 s, at 20 m/s.
    let run = run(&travelled_after_restart());
    let started = event_time(&run, "Faster", "start").expect("Faster starts");
    assert!(close(started, 4.03, 1e-6), "{started}");
    let ghost = at(&run, "Ego_ghost", 4.5);
    assert!(near_xy(ghost, 119.6, -1.25) && close(ghost.speed, 20.0, 1e-9), "{:?} {}", xy(ghost), ghost.speed);
}

/// Ego at s = 985 (10 m/s, head start 2 s) on the 1,000 m road: its ghost is stuck at the
/// road's end from −0.5 s. `Drift` starts when the Ego is within 12 m of the end (0.3 s) and
/// restarts the ghost there.
fn restart_at_road_end() -> String {
    // One Private per entity: esmini 3.6.0 fails to start a scenario with the Ego's in three.
    let ego = placed_in_one_private("Ego", 985.0, -1, 10.0)
        .replace("</Private>", r#"<PrivateAction><ActivateControllerAction longitudinal="true" lateral="true"/></PrivateAction></Private>"#);
    let init = format!("{ego}{}", teleport("Target", 300.0, -1));
    let end = r#"<Condition name="end" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><DistanceCondition value="12" freespace="false" rule="lessThan" relativeDistanceType="longitudinal" coordinateSystem="road"><Position><LanePosition roadId="1" laneId="-1" s="1000" offset="0"/></Position></DistanceCondition></EntityCondition></ByEntityCondition></Condition>"#;
    let offset = r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="0.5"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Drift", "overwrite", offset, &format!("<StartTrigger>{}</StartTrigger>", group(end))));
    with_follow_ghost(&xosc(&init, &stories, &stop_at(2.0)), 2.0)
}

#[test]
fn a_restarted_ghost_takes_its_entity_s_road_status_and_drives_on_from_a_dead_end() {
    // TeleportAction::Start restarts a ghost by Position::Duplicate of its entity's position,
    // status included: the ghost, stuck at the road's end, is not at an end any more and drives
    // on from the Ego's place (988.2 m at −1.7 s). A TeleportTo would keep the ghost's status.
    // esmini 3.6.0 on this scenario: the replayed ghost at (992.9, −1.579799) at −1.2 s and
    // (998.9, −1.2693) at −0.6 s, back at the end (1000, −1.25) from 0 s on.
    let run = run(&restart_at_road_end());
    assert_eq!(run.trace.replays.len(), 1);
    assert!(near_xy(replayed(&run, "Ego_ghost", -1.2), 992.9, -1.579799), "{:?}", xy(replayed(&run, "Ego_ghost", -1.2)));
    assert!(near_xy(replayed(&run, "Ego_ghost", -0.6), 998.9, -1.2693), "{:?}", xy(replayed(&run, "Ego_ghost", -0.6)));
    assert!(near_xy(at(&run, "Ego_ghost", 1.0), 1000.0, -1.25), "{:?}", xy(at(&run, "Ego_ghost", 1.0)));
}
