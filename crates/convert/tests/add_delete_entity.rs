//! An entity that DeleteEntityAction removes and AddEntityAction brings back becomes one
//! dynamic obstacle per appearance, each spanning exactly the CommonRoad time steps (0.1 s) at
//! which it exists. The scenario runs on the engine's straight fixture road (along +x; lane -1's
//! centre at y = -1.75, lane -2's at y = -5.25); times and positions are worked out by hand.

use std::path::PathBuf;

use crate::common::{convert_and_clean, fresh_dir, global_event_at, one_maneuver_scenario, place, CAR};

fn at_time(name: &str, t: f64, action: &str) -> String {
    global_event_at(name, &format!("{name}A"), t, &format!(r#"<EntityAction entityRef="Target">{action}</EntityAction>"#))
}

/// Ego (lane -1, s = 100) and Target (lane -1, s = 20) at 10 m/s; Target deleted at 2 s and
/// added at 5 s in lane -2 at s = 300; the run stops after 7 s.
fn scenario() -> String {
    let events = format!(
        "{}{}",
        at_time("Delete", 2.0, "<DeleteEntityAction/>"),
        at_time("Add", 5.0, r#"<AddEntityAction><Position><LanePosition roadId="1" laneId="-2" offset="0" s="300"/></Position></AddEntityAction>"#)
    );
    let entities = format!(r#"<ScenarioObject name="Ego">{CAR}</ScenarioObject><ScenarioObject name="Target">{CAR}</ScenarioObject>"#);
    let init = format!("{}{}", place("Ego", 100.0, -1, 10.0), place("Target", 20.0, -1, 10.0));
    one_maneuver_scenario("delete and add", "straight.xodr", &entities, &init, &events, "greaterThan", 7.0)
}

/// A fresh directory holding the scenario and the fixture road.
fn workdir(tag: &str) -> PathBuf {
    let dir = fresh_dir(tag);
    let road = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../engine/tests/fixtures/straight.xodr");
    std::fs::copy(&road, dir.join("straight.xodr")).expect("fixture road copied");
    std::fs::write(dir.join("delete_add.xosc"), scenario()).expect("scenario written");
    dir
}

#[test]
fn an_entity_deleted_and_added_back_is_one_obstacle_per_appearance() {
    let (conversion, model) = convert_and_clean(&workdir("part3-entities-obstacles"), "delete_add");
    // Box centres are 1.5 m ahead of the reference point. Ego starts at x = 101.5; Target's
    // two appearances: from step 0 at x = 21.5 (lane -1), and from step 51 (5.1 s, its first
    // CommonRoad step after the add at 5.01 s) at x = 300 + 10 · 0.10 + 1.5 = 302.5 (lane -2): esmini
    // drives an added entity on in the step it is added.
    let obstacles = &model.scenario.dynamic_obstacles;
    let first: Vec<_> = obstacles.iter().filter(|o| (o.initial_state.x - 21.5).abs() < 1e-6).collect();
    let second: Vec<_> = obstacles.iter().filter(|o| (o.initial_state.y + 5.25).abs() < 1e-6).collect();
    assert_eq!((first.len(), second.len()), (1, 1), "{obstacles:#?}");
    let (a, b) = (first[0], second[0]);
    assert_ne!(a.id, b.id);
    // First appearance: rows 0.00 … 2.00 s exist, so steps 0 … 20 (x = 21.5 + 10 · 0.1 · n).
    assert_eq!(a.initial_state.time_step, 0);
    assert_eq!(a.trajectory.first().map(|s| s.time_step), Some(1));
    assert_eq!(a.trajectory.last().map(|s| s.time_step), Some(20));
    let end = a.trajectory.last().expect("states");
    assert!((end.x - 41.5).abs() < 1e-6 && (end.y + 1.75).abs() < 1e-6, "{end:?}");
    // Second appearance: steps 51 … 70 (the last row is 7.01 s: the stop trigger "> 7" holds at
    // the storyboard time 7.01 s and that frame records nothing).
    assert_eq!(b.initial_state.time_step, 51);
    assert!((b.initial_state.x - 302.5).abs() < 1e-6, "{:?}", b.initial_state);
    assert_eq!(b.trajectory.last().map(|s| s.time_step), Some(70));
    let end = b.trajectory.last().expect("states");
    assert!((end.x - (300.0 + 10.0 * (7.0 - 5.0) + 1.5)).abs() < 1e-6, "{end:?}");
    assert!(conversion.warnings.iter().any(|w| w.message.contains("one per appearance")), "{:?}", conversion.warnings);
}

#[test]
fn a_passed_deadline_is_a_timeout_failure_not_an_engine_failure() {
    let dir = workdir("part3-entities-deadline");
    let path = dir.join("delete_add.xosc");
    let request = convert::Request::named(&path, "delete_add");
    // The 7 s run takes 700 steps; the engine looks at the clock at step 256 and stops there.
    let options = convert::ConvertOptions { deadline: Some(std::time::Instant::now()), ..Default::default() };
    let (conversion, _) = convert::convert(&request, &options);
    let _ = std::fs::remove_dir_all(&dir);
    match conversion.result {
        Err(f) => {
            assert_eq!(f.stage, convert::Stage::Timeout, "{}", f.message);
            assert!(f.message.contains("--timeout") && f.message.contains("2.55 s"), "{}", f.message);
        }
        Ok(_) => panic!("expected a timeout"),
    }
}
