//! A closed-loop session converts as a batch does: stepped to the end with nobody driving from
//! outside it writes the bytes `convert` writes; with the ego driven from outside and fed the
//! states it had, replacing the scripted motion, it writes them again, every obstacle state
//! within 1e-8 of the open-loop conversion's (`REPLAYED`; 0.1 mm where the open-loop ego's s
//! came from a lane change's OSI-segment attachment, `REPLAYED_FROM_SEGMENT_S`); the same inputs give the same bytes. Inputs held
//! over several engine steps (`step_held`): driver input is the same input at every step, a
//! state is reached at the end (fed its states every 0.1 s, cut-in's ego drives as in the
//! batch), an entity taken over in between dead-reckons; `open_loop` is the batch conversion.

use convert::{convert, ClosedLoop, ConvertOptions, Model, Request};
use engine::{External, ExternalState, Input, ScriptedMotion};

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

/// How close a replayed ego leaves the obstacles: the ego put where its states say is located
/// from its pose, which (as esmini's Position::XYZ2TrackPos, dividing by cos(1e-6)) puts it
/// 5e-13 of its t further from the reference line than moving along its lane did, and what
/// reacts to the ego carries that hair on to a few nanometres.
const REPLAYED: f64 = 1e-8;

/// Where the open-loop ego's road s came from a lane change's OSI-segment attachment (esmini's
/// XYZ2TrackPos, millimetres from the exact projection on a curve) while a pose fed from
/// outside is located by the exact projection, what measures from the ego's s follows it by
/// micrometres (keep_lateral_distance: 2.9e-6), and the written bytes may differ.
const REPLAYED_FROM_SEGMENT_S: f64 = 1e-4;

/// Whether the ego stands where it stood in the open loop but at another road s.
fn ego_s_differs(open: Option<engine::Sample>, closed: Option<engine::Sample>) -> bool {
    match (open, closed) {
        (Some(a), Some(b)) => {
            (a.x - b.x).abs() < 1e-8 && (a.y - b.y).abs() < 1e-8 && matches!((a.road, b.road), (Some(p), Some(q)) if (p.s - q.s).abs() > 1e-8)
        }
        _ => false,
    }
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
    let files = testkit::compared_scenarios(&shared);
    assert!(files.len() > 100);
    for path in &files {
        let (batch, batch_model) = convert(&Request::file(path).keeping_model(), &options);
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
        let mut segment_s = false;
        let mut k = 0;
        while !closed.is_over() {
            k += 1;
            let input = match recorded.get(k - 1).copied().flatten() {
                Some(s) => Input::State(ExternalState { z: Some(s.z), yaw_rate: Some(s.yaw_rate), ..ExternalState::new(s.x, s.y, s.h, s.speed) }),
                None => Input::Hold,
            };
            closed.step_with(&[(ego, input)]).expect("steps");
            segment_s |= ego_s_differs(recorded.get(k - 1).copied().flatten(), closed.state(ego));
        }
        let (replayed, model) = closed.finish();
        let worst = model.as_ref().map_or(f64::INFINITY, |m| worst_state_difference(&batch_model, m));
        let bound = if segment_s { REPLAYED_FROM_SEGMENT_S } else { REPLAYED };
        if worst > bound {
            failures.push(format!("{}: replayed, an obstacle state is {worst:.3e} off", path.display()));
        } else if !segment_s && replayed.result.as_ref().ok() != Some(&bytes) {
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
            vec![(
                ego,
                Input::Driver(engine::DriverInput {
                    throttle: 0.3 * (t * 0.5).sin().abs(),
                    brake: if t > 6.0 { 0.4 } else { 0.0 },
                    steering: 0.01 * (t * 2.0).sin(),
                }),
            )]
        });
        let (c, _) = session.finish();
        c.result.expect("converts")
    };
    let (a, b) = (drive(), drive());
    assert_eq!(a, b);
    // and it is not the open-loop conversion: the ego drove itself
    let open = convert(&Request::file(&path), &ConvertOptions::default()).0.result.expect("converts");
    assert_ne!(a, open);
}

#[test]
fn a_session_can_move_between_threads() {
    fn send<T: Send>() {}
    send::<ClosedLoop>();
}

#[test]
fn the_open_loop_conversion_of_a_session_is_the_batch_conversion() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let options = ConvertOptions::default();
    let batch = convert(&Request::file(&path), &options).0.result.expect("converts");
    for external in [External::none(), External::named(["Ego"])] {
        let mut session = ClosedLoop::start(&path, &options, &external).expect("starts");
        let (open, model) = session.open_loop();
        assert_eq!(open.result.as_ref().ok(), Some(&batch), "{external:?}");
        assert_eq!(open.facts.ego.as_deref(), Some("Ego"));
        assert!(model.is_some_and(|m| m.names.iter().any(|(_, n)| n == "OverTaker")));
        // whatever the session has done since
        let hold: Vec<_> = session.external().iter().map(|x| (x.index, Input::Hold)).collect();
        assert!(session.step_held(&hold, 10).expect("steps"));
        assert_eq!(session.open_loop().0.result.ok(), Some(batch.clone()));
    }
}

/// Cut-in with Ego driven by `input` through `step`, to the end; the bytes.
fn drive_cut_in(mut step: impl FnMut(&mut ClosedLoop, usize) -> bool) -> Vec<u8> {
    let Some(shared) = testkit::shared_dir() else { return Vec::new() };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let mut session = ClosedLoop::start(&path, &ConvertOptions::default(), &External::named(["Ego"])).expect("starts");
    let ego = session.entity_names().iter().position(|n| n == "Ego").expect("Ego");
    while step(&mut session, ego) {}
    session.finish().0.result.expect("converts").xml().expect("2020a XML").to_vec()
}

#[test]
fn held_driver_input_is_the_same_input_at_every_engine_step() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let pedals = |k: usize| {
        Input::Driver(engine::DriverInput {
            throttle: if k < 40 { 0.4 } else { 0.0 },
            brake: if k >= 60 { 0.3 } else { 0.0 },
            steering: 0.002 * (k as f64 * 0.3).sin(),
        })
    };
    // ten engine steps per call, the input of CommonRoad step k held over them
    let mut k = 0;
    let held = drive_cut_in(|s, ego| {
        k += 1;
        s.step_held(&[(ego, pedals(k))], 10).expect("steps")
    });
    let mut j: usize = 0;
    let stepped = drive_cut_in(|s, ego| {
        j += 1;
        s.step_with(&[(ego, pedals(j.div_ceil(10)))]).expect("steps")
    });
    assert_eq!(held, stepped);
}

#[test]
fn the_ego_fed_its_own_states_every_tenth_engine_step_drives_almost_as_in_the_batch() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let options = ConvertOptions::default();
    // the ego's states at every CommonRoad step (every tenth engine step) of the open loop
    let mut open = ClosedLoop::start(&path, &options, &External::none()).expect("starts");
    let ego = open.entity_names().iter().position(|n| n == "Ego").expect("Ego");
    let mut recorded = Vec::new();
    while open.step_held(&[], 10).expect("steps") {
        recorded.push(open.state(ego));
    }
    recorded.push(open.state(ego));
    let batch_model = open.open_loop().1.expect("converts");
    // fed back, one held for ten engine steps each, the poses in between interpolated: the
    // ego drives its open-loop path at 30 m/s on e6mini's curves
    let external = External { motion: ScriptedMotion::Replaced, ..External::named(["Ego"]) };
    let mut closed = ClosedLoop::start(&path, &options, &external).expect("starts");
    let mut k = 0;
    while !closed.is_over() {
        let input = match recorded.get(k).copied().flatten() {
            Some(s) => Input::State(ExternalState::new(s.x, s.y, s.h, s.speed)),
            None => Input::Hold,
        };
        k += 1;
        closed.step_held(&[(ego, input)], 10).expect("steps");
    }
    let model = closed.finish().1.expect("converts");
    let starts = |m: &Model| m.events.iter().map(|(t, e)| format!("{t:.2} {e}")).collect::<Vec<_>>();
    assert_eq!(starts(&model), starts(&batch_model), "the storyboard's events start at the same engine steps");
    // every obstacle state (positions, headings, speeds, accelerations, yaw rates) within
    // 1e-3 (measured: 5.4e-5)
    let worst = worst_state_difference(&batch_model, &model);
    assert!(worst < 1e-3, "an obstacle state is {worst:e} off");
}

#[test]
fn a_held_state_is_reached_at_the_end_of_the_steps() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let mut session = ClosedLoop::start(&path, &ConvertOptions::default(), &External::named(["Ego"])).expect("starts");
    let ego = session.entity_names().iter().position(|n| n == "Ego").expect("Ego");
    for (steps, turn) in [(1, 0.0), (10, 0.01), (7, -0.02)] {
        let s0 = session.state(ego).expect("Ego exists");
        let d = s0.speed * 0.01 * steps as f64;
        let target = ExternalState::new(s0.x + d * s0.h.cos(), s0.y + d * s0.h.sin(), s0.h + turn, s0.speed + 0.5);
        assert!(session.step_held(&[(ego, Input::State(target))], steps).expect("steps"));
        let end = session.state(ego).expect("exists");
        assert!((end.x - target.x).abs() < 1e-9 && (end.y - target.y).abs() < 1e-9, "{steps} steps: {end:?} vs {target:?}");
        assert!((end.h - target.h).abs() < 1e-12 && end.speed == target.speed, "{steps} steps: {end:?} vs {target:?}");
    }
    assert!((session.time() - 0.18).abs() < 1e-9, "{}", session.time());
}

#[test]
fn an_entity_that_becomes_external_within_held_steps_dead_reckons_until_the_next_call() {
    let Some(shared) = testkit::shared_dir() else { return };
    // the InteractiveController takes Ego over once the time exceeds 10 s: at 10.01 s, inside
    // the CommonRoad step from 10.0 to 10.1 s
    let path = shared.join("corpus/esmini/xosc/controller_test.xosc");
    let mut session = ClosedLoop::start(&path, &ConvertOptions::default(), &External::controllers()).expect("starts");
    assert!(session.external().iter().all(|x| !x.active));
    while session.time() < 10.0 - 1e-9 {
        assert!(session.step_held(&[], 10).expect("nobody is external yet"));
    }
    assert!(session.step_held(&[], 10).expect("the takeover inside the steps is no error"));
    let ego = session.external().into_iter().find(|x| x.active).expect("Ego external now");
    assert_eq!(ego.name, "Ego");
    let before = session.time();
    let err = session.step_held(&[], 10).expect_err("now Ego needs an input");
    assert!(err.message.contains("no input for `Ego`"), "{}", err.message);
    assert_eq!(session.time(), before, "the failed call ran no step");
    assert!(session.step_held(&[(ego.index, Input::Hold)], 10).expect("steps"));
}
