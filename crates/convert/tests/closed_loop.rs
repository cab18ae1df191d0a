//! A closed-loop session converts as a batch does: stepped to the end with nobody driving from
//! outside it writes the bytes `convert` writes; with the ego driven from outside and fed the
//! states it had, replacing the scripted motion, it writes them again, every obstacle state
//! within 1e-9 of the open-loop conversion's; the same inputs give the same bytes.

use std::path::{Path, PathBuf};

use convert::{batch_name, batch_source, convert_scenario_keeping, ClosedLoop, ConvertOptions, Model, Request};
use engine::{External, ExternalState, Input, ScriptedMotion};

/// The scenarios the reference compares (class core or controller-model).
fn compared(shared: &Path) -> Vec<PathBuf> {
    let corpus = shared.join("corpus");
    let reference = shared.join("reference/esmini-3.6.0");
    testkit::files_with_ext(&corpus, "xosc")
        .into_iter()
        .filter(|f| {
            let rel = f.strip_prefix(&corpus).expect("under corpus").with_extension("json");
            let Ok(text) = std::fs::read_to_string(reference.join(rel)) else { return false };
            let json: serde_json::Value = serde_json::from_str(&text).expect("reference json");
            matches!(json["class"].as_str(), Some("core" | "controller-model"))
        })
        .collect()
}

/// The largest difference between two models' obstacle states (infinite when their
/// obstacles or trajectories differ in number or time steps).
fn worst_state_difference(a: &Model, b: &Model) -> f64 {
    let (da, db) = (&a.scenario.dynamic_obstacles, &b.scenario.dynamic_obstacles);
    if da.len() != db.len() || a.scenario.static_obstacles != b.scenario.static_obstacles {
        return f64::INFINITY;
    }
    let mut worst = 0.0f64;
    for (x, y) in da.iter().zip(db) {
        if x.id != y.id || x.trajectory.len() != y.trajectory.len() {
            return f64::INFINITY;
        }
        for (s, t) in std::iter::once((&x.initial_state, &y.initial_state)).chain(x.trajectory.iter().zip(&y.trajectory)) {
            if s.time_step != t.time_step {
                return f64::INFINITY;
            }
            for d in [s.x - t.x, s.y - t.y, s.orientation - t.orientation, s.velocity - t.velocity, s.acceleration - t.acceleration, s.yaw_rate - t.yaw_rate] {
                worst = worst.max(d.abs());
            }
        }
    }
    worst
}

fn step_through(session: &mut ClosedLoop, mut input: impl FnMut(usize) -> Vec<(usize, Input)>) {
    let mut k = 0;
    while !session.is_over() {
        k += 1;
        session.step_with(&input(k)).expect("steps");
    }
}

#[test]
fn a_session_converts_as_the_batch_and_a_replayed_ego_changes_nothing() {
    let Some(shared) = testkit::shared_dir() else { return };
    let options = ConvertOptions::default();
    let mut failures = Vec::new();
    let files = compared(&shared);
    assert!(files.len() > 100);
    for path in &files {
        let name = batch_name(path);
        let request = Request { path, name: &name, config: 1, parameters: &[], source: batch_source(path, None) };
        let (batch, batch_model) = convert_scenario_keeping(&request, &options, true);
        let (Ok(bytes), Some(batch_model)) = (batch.result, batch_model) else { continue };
        let ego_name = batch.facts.ego.clone().expect("an ego");

        // nobody outside: the batch's bytes, and the ego's states on the way
        let mut open = ClosedLoop::start(path, &options, &External::none()).expect("starts");
        let ego = open.entity_names().iter().position(|n| *n == ego_name).expect("the ego is an entity");
        let mut recorded = Vec::new();
        while !open.is_over() {
            open.step_with(&[]).expect("steps");
            recorded.push(open.state(ego));
        }
        let (stepped, _) = open.finish();
        if stepped.result.as_ref().ok() != Some(&bytes) {
            failures.push(format!("{}: stepped to the end, the bytes differ from the batch's", path.display()));
            continue;
        }

        // the ego driven from outside with its own states, the outside replacing the script
        let external = External { motion: ScriptedMotion::Replaced, ..External::named([ego_name.as_str()]) };
        let mut closed = ClosedLoop::start(path, &options, &external).expect("starts");
        step_through(&mut closed, |k| {
            let input = match recorded.get(k - 1).copied().flatten() {
                Some(s) => Input::State(ExternalState { z: Some(s.z), yaw_rate: Some(s.yaw_rate), ..ExternalState::new(s.x, s.y, s.h, s.speed) }),
                None => Input::Hold,
            };
            vec![(ego, input)]
        });
        let (replayed, model) = closed.finish();
        let worst = model.as_ref().map_or(f64::INFINITY, |m| worst_state_difference(&batch_model, m));
        if worst > 1e-9 {
            failures.push(format!("{}: replayed, an obstacle state is {worst:.3e} off", path.display()));
        } else if replayed.result.as_ref().ok() != Some(&bytes) {
            failures.push(format!("{}: replayed, the bytes differ", path.display()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_same_inputs_give_the_same_bytes() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let drive = || {
        let mut session = ClosedLoop::start(&path, &ConvertOptions::default(), &External::named(["Ego"])).expect("starts");
        let ego = session.entity_names().iter().position(|n| n == "Ego").expect("Ego");
        step_through(&mut session, |k| {
            let t = k as f64 * 0.01;
            vec![(ego, Input::Driver(engine::DriverInput { throttle: 0.3 * (t * 0.5).sin().abs(), brake: if t > 6.0 { 0.4 } else { 0.0 }, steering: 0.01 * (t * 2.0).sin() }))]
        });
        let (c, _) = session.finish();
        c.result.expect("converts")
    };
    let (a, b) = (drive(), drive());
    assert_eq!(a, b);
    // and it is not the open-loop conversion: the ego drove itself
    let open = convert::convert_file(&path, &ConvertOptions::default()).result.expect("converts");
    assert_ne!(a, open);
}

#[test]
fn a_session_can_move_between_threads() {
    fn send<T: Send>() {}
    send::<ClosedLoop>();
}
