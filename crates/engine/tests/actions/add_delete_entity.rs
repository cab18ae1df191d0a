//! AddEntityAction / DeleteEntityAction on the straight fixture road (along +x; lane -1's
//! centre at y = -1.75, lane -2's at y = -5.25). Expected samples follow the frame order: a
//! trigger true at storyboard time t acts in the frame that records the row t + 0.01 s; an
//! entity moves by speed · 0.01 s per step. The rules were checked against esmini 3.6.0 on the
//! same situations on its straight_500m road (an added entity is driven on in the step it is
//! added; its actions go on while it is away; an Init teleport while away holds it one step).

use crate::common::*;
use engine::Run;

fn delete(entity: &str) -> String {
    format!(r#"<GlobalAction><EntityAction entityRef="{entity}"><DeleteEntityAction/></EntityAction></GlobalAction>"#)
}

fn add(entity: &str, s: f64, lane: i32) -> String {
    format!(r#"<GlobalAction><EntityAction entityRef="{entity}"><AddEntityAction>{}</AddEntityAction></EntityAction></GlobalAction>"#, lane_pos(s, lane))
}

fn at_time(t: f64) -> String {
    trigger(&sim_time(t, "greaterOrEqual", "none", 0.0))
}

/// Ego in lane -1 at s = 100, Target in lane -1 at s = 20, both at 10 m/s.
fn init() -> String {
    format!("{}{}", placed("Ego", 100.0, -1, 10.0), placed("Target", 20.0, -1, 10.0))
}

/// Target's sample at step k (None while it does not exist).
fn sample(run: &Run, entity: &str, k: usize) -> Option<engine::Sample> {
    run.trace.entities.iter().find(|e| e.name == entity).and_then(|e| e.samples.get(k).copied().flatten())
}

fn warned(run: &Run, text: &str) -> bool {
    run.warnings.iter().any(|w| w.message.contains(text))
}

/// Delete Target at 2 s, add it back at 5 s in lane -2 at s = 300.
fn delete_and_add(extra_events: &str) -> Run {
    let events = format!(
        "{}{}{extra_events}",
        event("Delete", "parallel", &delete("Target"), &at_time(2.0)),
        event("Add", "parallel", &add("Target", 300.0, -2), &at_time(5.0)),
    );
    run(&xosc(&init(), &story("Ego", &events), &stop_at(7.0)))
}

#[test]
fn a_deleted_entity_has_no_rows_until_it_is_added_back_at_the_position() {
    let r = delete_and_add("");
    // Last row before the delete: 20 + 10 · 2.00 = 40 m.
    let last = sample(&r, "Target", 200).expect("Target exists at 2.00 s");
    assert!(close(last.x, 40.0, 1e-9) && close(last.y, -1.75, 1e-9), "{last:?}");
    // Gone from 2.01 s to 5.00 s.
    for k in 201..=500 {
        assert!(sample(&r, "Target", k).is_none(), "Target has a row at step {k}");
    }
    // Back at 5.01 s: put where the action says and driven on in the same step with the
    // speed it had (10 m/s): 300.1 m, without a velocity or yaw-rate spike from the jump.
    let back = sample(&r, "Target", 501).expect("Target exists at 5.01 s");
    assert!(close(back.x, 300.1, 1e-9) && close(back.y, -5.25, 1e-9), "{back:?}");
    assert!(close(back.speed, 10.0, 1e-12) && back.yaw_rate == 0.0 && back.acceleration == 0.0, "{back:?}");
    // Then it drives on: 300.1 + 10 · (6.01 − 5.01) = 310.1 m.
    let later = sample(&r, "Target", 601).expect("Target exists at 6.01 s");
    assert!(close(later.x, 310.1, 1e-9), "{later:?}");
    // Ego is unaffected: 100 + 10 · 6 = 160 m.
    assert!(close(at(&r, "Ego", 6.0).x, 160.0, 1e-9));
    // The CSV has no Target rows while it is deleted.
    let csv = r.trace.to_csv(&[[0.0; 6], [0.0; 6]]);
    assert!(csv.contains("\n2.000,Target,") && !csv.contains("\n2.010,Target,") && !csv.contains("\n5.000,Target,"));
    assert!(csv.contains("\n5.010,Target,"));
    assert!(r.warnings.iter().all(|w| !w.message.contains("not supported")), "{:?}", r.warnings);
}

#[test]
fn entity_conditions_skip_a_deleted_entity() {
    // Both fire at 3 s if Target existed. "Any" over [Target] cannot hold while Target is
    // deleted: it fires when Target is back (5.00 s, in the frame of the add, which comes
    // first in the document). "All" over [Ego, Target] ignores the deleted Target (esmini) and
    // holds on Ego alone at 3.00 s.
    let speed_cond = |rule: &str, entities: &[&str]| {
        let refs: String = entities.iter().map(|e| format!(r#"<EntityRef entityRef="{e}"/>"#)).collect();
        format!(
            r#"<Condition name="v" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="{rule}">{refs}</TriggeringEntities><EntityCondition><SpeedCondition value="5" rule="greaterThan"/></EntityCondition></ByEntityCondition></Condition>"#
        )
    };
    let noop = r#"<GlobalAction><ParameterAction parameterRef="X"><SetAction value="1"/></ParameterAction></GlobalAction>"#;
    let watch_any =
        event("WatchAny", "parallel", noop, &trigger(&format!("{}{}", sim_time(3.0, "greaterOrEqual", "none", 0.0), speed_cond("any", &["Target"]))));
    let watch_all =
        event("WatchAll", "parallel", noop, &trigger(&format!("{}{}", sim_time(3.0, "greaterOrEqual", "none", 0.0), speed_cond("all", &["Ego", "Target"]))));
    let r = delete_and_add(&format!("{watch_any}{watch_all}"));
    let any = event_time(&r, "WatchAny", "start").expect("WatchAny starts");
    let all = event_time(&r, "WatchAll", "start").expect("WatchAll starts");
    assert!(close(any, 5.0, 1e-9), "WatchAny started at {any}");
    assert!(close(all, 3.0, 1e-9), "WatchAll started at {all}");
}

#[test]
fn adding_an_existing_or_deleting_a_deleted_entity_is_skipped_with_a_warning() {
    let events = format!(
        "{}{}{}",
        event("AddTwice", "parallel", &add("Target", 500.0, -2), &at_time(1.0)),
        event("Delete", "parallel", &delete("Target"), &at_time(2.0)),
        event("DeleteTwice", "parallel", &delete("Target"), &at_time(3.0)),
    );
    let r = run(&xosc(&init(), &story("Ego", &events), &stop_at(4.0)));
    assert!(warned(&r, "already exists"), "{:?}", r.warnings);
    assert!(warned(&r, "already deleted"), "{:?}", r.warnings);
    // esmini's Start returns early: the refused actions never start, their events run on
    // until the storyboard stops them.
    assert_eq!(event_time(&r, "AddTwiceAction", "start"), None);
    assert_eq!(event_time(&r, "DeleteTwiceAction", "start"), None);
    assert!(event_time(&r, "AddTwice", "start").is_some_and(|t| close(t, 1.0, 1e-9)));
    assert!(event_time(&r, "AddTwice", "end").is_none());
    assert!(event_time(&r, "AddTwice", "stop").is_some_and(|t| close(t, 4.01, 1e-9)), "{:?}", event_time(&r, "AddTwice", "stop"));
    // Not moved by the skipped add: 20 + 10 · 1.5 = 35 m, still in lane -1.
    let s = at(&r, "Target", 1.5);
    assert!(close(s.x, 35.0, 1e-9) && close(s.y, -1.75, 1e-9), "{s:?}");
    assert!(sample(&r, "Target", 350).is_none());
}

/// Target's own story: `events` for Target, started at 0 s; Ego's story deletes Target at
/// 2 s and adds it back at 5 s at s = 300 in lane -2.
fn target_story_while_away(events: &str) -> Run {
    let target_story = format!(
        r#"<Story name="T"><Act name="TA"><ManeuverGroup maximumExecutionCount="1" name="TG"><Actors selectTriggeringEntities="false"><EntityRef entityRef="Target"/></Actors><Maneuver name="TM">{events}</Maneuver></ManeuverGroup>{}</Act></Story>"#,
        at_time(0.0)
    );
    let globals = story(
        "Ego",
        &format!("{}{}", event("Delete", "parallel", &delete("Target"), &at_time(2.0)), event("Add", "parallel", &add("Target", 300.0, -2), &at_time(5.0))),
    );
    run(&xosc(&init(), &format!("{target_story}{globals}"), &stop_at(7.0)))
}

#[test]
fn the_actions_of_a_deleted_entity_go_on_while_it_is_away() {
    // Target accelerates at 1 m/s² from 10 towards 20 m/s from 0 s (12 m/s when deleted at
    // 2 s). The speed action goes on while Target is away (esmini steps it on the pooled
    // object): 10 + 5.01 = 15.01 m/s at 5.01 s, and Target is driven 0.1501 m in the add step.
    let r = target_story_while_away(&event("Accelerate", "parallel", &speed_action("linear", "rate", 1.0, 20.0), &at_time(0.0)));
    let before = sample(&r, "Target", 200).expect("exists at 2.00 s");
    assert!(close(before.speed, 12.0, 1e-9), "{before:?}");
    let back = sample(&r, "Target", 501).expect("exists at 5.01 s");
    assert!(close(back.speed, 15.01, 1e-9) && close(back.x, 300.1501, 1e-9), "{back:?}");
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn an_action_started_while_the_entity_is_away_acts_on_it() {
    // Halted (step to 0 m/s) at 3 s while deleted: back at 5.01 s it stands at s = 300.
    let r = target_story_while_away(&event("Halt", "parallel", &speed_action("step", "time", 0.0, 0.0), &at_time(3.0)));
    let back = sample(&r, "Target", 501).expect("exists at 5.01 s");
    assert!(close(back.x, 300.0, 1e-9) && back.speed == 0.0, "{back:?}");
    let later = sample(&r, "Target", 601).expect("exists at 6.01 s");
    assert!(close(later.x, 300.0, 1e-9), "{later:?}");
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn an_entity_without_an_init_private_exists_only_once_added() {
    // ScenarioReader::parseInit activates only the entities the Init names: Target, never in
    // the Init, has no rows until added at 1 s at s = 50 (speed 0: it stays there).
    let init = format!("{}{}", teleport("Ego", 100.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let events = event("Add", "parallel", &add("Target", 50.0, -2), &at_time(1.0));
    let r = run(&xosc(&init, &story("Ego", &events), &stop_at(2.0)));
    for k in 0..=100 {
        assert!(sample(&r, "Target", k).is_none(), "Target has a row at step {k}");
    }
    let s = sample(&r, "Target", 101).expect("exists at 1.01 s");
    assert!(close(s.x, 50.0, 1e-9) && close(s.y, -5.25, 1e-9) && s.speed == 0.0, "{s:?}");
    assert_eq!(event_time(&r, "AddAction", "start"), Some(1.0));
}

#[test]
fn an_entity_deleted_in_init_first_exists_when_added() {
    // Init deletes Target before anything (global Init actions come first), so it has no row
    // at 0 s; its Init teleport and speed still apply to it while it is away. Added at 1 s in
    // lane -2 at s = 50 with its Init speed (10 m/s); the teleport's "moved" mark, never
    // cleared while it was away (ScenarioEngine::SwapAndClearDirtyBits clears active
    // entities only), keeps it at 50 m in the add step: 50 + 10 · 0.49 = 54.9 m at 1.50 s.
    let init = format!(r#"<GlobalAction><EntityAction entityRef="Target"><DeleteEntityAction/></EntityAction></GlobalAction>{}"#, init());
    let events = event("Add", "parallel", &add("Target", 50.0, -2), &at_time(1.0));
    let r = run(&xosc(&init, &story("Ego", &events), &stop_at(2.0)));
    for k in 0..=100 {
        assert!(sample(&r, "Target", k).is_none(), "Target has a row at step {k}");
    }
    let s = sample(&r, "Target", 101).expect("exists at 1.01 s");
    assert!(close(s.x, 50.0, 1e-9) && close(s.y, -5.25, 1e-9) && close(s.speed, 10.0, 1e-12), "{s:?}");
    let s = sample(&r, "Target", 150).expect("exists at 1.50 s");
    assert!(close(s.x, 54.9, 1e-9), "{s:?}");
    assert!(close(at(&r, "Ego", 1.5).x, 115.0, 1e-9));
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn a_position_that_cannot_be_resolved_is_warned_about_under_the_action_that_gave_it() {
    // Add Target back on a road the map does not have: it stays where it was, and the warning
    // names AddEntityAction (not TeleportAction, whose placement it shares).
    let nowhere = r#"<GlobalAction><EntityAction entityRef="Target"><AddEntityAction><Position><LanePosition roadId="99" laneId="-1" offset="0" s="10"/></Position></AddEntityAction></EntityAction></GlobalAction>"#;
    let events = format!("{}{}", event("Delete", "parallel", &delete("Target"), &at_time(2.0)), event("Add", "parallel", nowhere, &at_time(3.0)));
    let r = run(&xosc(&init(), &story("Ego", &events), &stop_at(4.0)));
    let msgs: Vec<&str> = r.warnings.iter().map(|w| w.message.as_str()).collect();
    assert!(msgs.iter().any(|m| m.starts_with("AddEntityAction: ") && m.contains("stays where it is")), "{msgs:?}");
    assert!(!msgs.iter().any(|m| m.starts_with("TeleportAction")), "{msgs:?}");
}

#[test]
fn an_entity_added_back_is_measured_from_where_it_was_last_active() {
    // esmini stores the old state of active entities only and AddEntityAction sets no teleport
    // mark (ScenarioEngine::prepareGroundTruth): Back, standing at s = 20 in lane 1 when deleted
    // at 1 s, is added at s = 60 at 2 s and takes 40 m / 0.01 s as its speed, then drives off
    // at 4000 m/s against s and stops at the road's start. Late, never active before, still
    // has the mark Entities::addObject gave it and stays standing; Moving keeps its 5 m/s
    // (the default controller sets it). Fixture added_entity_measured_from_last_state.xosc
    // (numbers from esmini 3.6.0's run of it).
    let name = "added_entity_measured_from_last_state.xosc";
    let run = crate::common::oracle::run_fixture_scenario(name, 10.0);
    let back = at(&run, "Back", 2.02);
    assert!(close(back.x, 60.0, 1e-9) && close(back.speed, 4000.0, 1e-6), "{back:?}");
    crate::common::oracle::assert_esmini_pose_at(&run, "Back", 2.03, 20.0, 1.75, std::f64::consts::PI);
    let gone = at(&run, "Back", 2.5);
    assert!(close(gone.x, 0.0, 1e-9) && gone.speed == 0.0, "{gone:?}");
    let late = at(&run, "Late", 2.0);
    assert!(close(late.x, 50.0, 1e-9) && late.speed == 0.0, "{late:?}");
    assert!(close(at(&run, "Moving", 2.52).x, 200.05, 1e-9));
    crate::common::oracle::assert_matches_esmini(name, &run, 1e-3);
}

#[test]
fn an_acc_steps_on_while_its_entity_is_away() {
    // esmini's ScenarioEngine::step steps every active controller whether or not its entity is
    // in the simulation. Add (ACC, additive) accelerates from 13.5 m/s at its deletion at
    // 1.51 s towards 30 m/s at 7 m/s² while away: 24.07 m/s when added back at 3.02 s, where
    // it stays in that step (Controller::Step's longitudinal mark is never cleared while it is
    // away, so the default controller leaves it). Over (override) keeps its 10 m/s and moves
    // itself; Ego only stands far away. Fixture acc_steps_while_away.xosc (numbers from esmini
    // 3.6.0's run of it).
    let run = crate::common::oracle::run_fixture_scenario("acc_steps_while_away.xosc", 10.0);
    let add = at(&run, "Add", 3.02);
    assert!(close(add.x, 300.0, 1e-9) && close(add.speed, 24.07, 1e-9), "{add:?}");
    crate::common::oracle::assert_esmini_pose_at(&run, "Add", 4.0, 326.811, -1.75, 0.0);
    crate::common::oracle::assert_esmini_pose_at(&run, "Over", 4.0, 309.9, -5.25, 0.0);
    crate::common::oracle::assert_matches_esmini("acc_steps_while_away.xosc", &run, 1e-3);
}

/// An entity that stood stuck at its road's end when it was deleted keeps that end-of-road
/// status (AddEntityAction::Start teleports with Position::TeleportTo, which copies the
/// location only) and, not moving, is stopped again by ScenarioEngine::step where it is added:
/// its speed stays 0 (Object::SetSpeed marks it applied, so prepareGroundTruth does not take
/// the jump over dt as its speed) and it stays there. Fixture
/// `added_back_after_stopping_at_road_end.xosc` on `bend_r5.xodr`: Ego in lane −1 at s 70,
/// 10 m/s, reaches the end (s 87.853982) and stops; deleted at 3 s, added at 4 s at s 30.
/// Expected values: esmini 3.6.0 on the fixture.
#[test]
fn an_entity_stuck_at_a_road_end_stays_stopped_when_added_back() {
    let run = run_fixture_on("added_back_after_stopping_at_road_end.xosc", "bend_r5.xodr", 5.0);
    let rows = [(2.0, 46.5, 45.0, 0.0), (4.02, 30.0, -1.5, 0.0), (4.5, 30.0, -1.5, 0.0), (5.0, 30.0, -1.5, 0.0)];
    assert_esmini_rows(&run, "Ego", &rows, 1e-4);
}
