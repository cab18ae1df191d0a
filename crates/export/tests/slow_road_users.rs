//! Slow, stopping and starting road users come back exactly: esmini merges trajectory vertices
//! closer than 0.1 m (its `--traj_filter`, on by default) and osc2cr's engine does as esmini
//! does, so the export cuts such a trajectory into pieces the filter leaves whole. A car that
//! brakes to a stop, stands half a second and creeps away, a truck that stands 2.4 s and
//! creeps at 0.3 m/s, and a pedestrian walking a wavy line at 0.8 m/s: every state within
//! 0.01 m in esmini (filter on, as users run it) and in `convert(export(S))`.

use std::path::Path;

use commonroad::{Scenario, State};

use crate::common::fresh_dir;
use crate::esmini_round_trip::{compare, expectations, run_esmini};

const POSITION: f64 = 0.01;

fn state(t: u64, x: f64, y: f64, orientation: f64, velocity: f64) -> State {
    State { time_step: t, x, y, orientation, velocity, acceleration: 0.0, yaw_rate: 0.0 }
}

/// The car: 8 m/s for 2 s, braking at 2 m/s² to a stop at 6 s, standing to 6.5 s, then
/// speeding up at 0.6 m/s² to 10 s.
fn stop_and_go(k: u64) -> State {
    let t = k as f64 * 0.1;
    let (x, v) = if t <= 2.0 {
        (8.0 * t, 8.0)
    } else if t <= 6.0 {
        let u = t - 2.0;
        (16.0 + 8.0 * u - u * u, 8.0 - 2.0 * u)
    } else if t <= 6.5 {
        (32.0, 0.0)
    } else {
        let u = t - 6.5;
        (32.0 + 0.3 * u * u, 0.6 * u)
    };
    state(k, 20.0 + x, 1.75, 0.0, v)
}

/// The truck: standing from step 1 to 25, then creeping at 0.3 m/s.
fn creep(k: u64) -> State {
    state(k, 5.0 + 0.03 * k.saturating_sub(25) as f64, 5.25, 0.0, if k > 25 { 0.3 } else { 0.0 })
}

/// The pedestrian (from step 5): walking east at 0.8 m/s, waving 0.5 m north and south.
fn walk(k: u64) -> State {
    let u = k.saturating_sub(5) as f64 * 0.1;
    let (y, dy) = (8.0 + 0.5 * (0.8 * u).sin(), 0.4 * (0.8 * u).cos());
    state(k, 100.0 + 0.8 * u, y, dy.atan2(0.8), 0.8f64.hypot(dy))
}

/// The synthetic scenario with slow road users in place of its car, truck and pedestrian.
fn slow_scenario() -> crate::synthetic::Built {
    let mut built = crate::synthetic::scenario(crate::synthetic::circle(60.0, 1.75, 3.0));
    let [car, truck, pedestrian] = &mut built.scenario.dynamic_obstacles[..] else { panic!("three road users") };
    car.initial_state = stop_and_go(0);
    car.trajectory = (1..=100).map(stop_and_go).collect();
    truck.initial_state = creep(1);
    truck.trajectory = (2..=60).map(creep).collect();
    pedestrian.initial_state = walk(5);
    pedestrian.trajectory = (6..=40).map(walk).collect();
    built
}

/// Exports the slow scenario into `dir` (`--play-to-end`): the `.xosc`, the scenario and the
/// document's text.
fn export_slow(dir: &Path) -> (std::path::PathBuf, Scenario, String) {
    let built = slow_scenario();
    let scenario = built.scenario.clone();
    let options = export::ExportOptions { play_to_end: true, ..Default::default() };
    let e = export::export(&crate::synthetic::source(built), "", &options).expect("exports");
    let xosc = dir.join("slow.xosc");
    std::fs::write(&xosc, &e.xosc).expect("write");
    if let Some(m) = &e.map {
        std::fs::write(dir.join(&m.file_name), &m.xodr).expect("write");
    }
    (xosc, scenario, e.xosc)
}

#[test]
fn stopping_and_creeping_road_users_are_cut_into_pieces_the_filter_keeps() {
    let dir = fresh_dir("slow-pieces");
    let (xosc, scenario, text) = export_slow(&dir);
    // the stop-and-go car and the standing truck are followed piece by piece
    for o in &scenario.dynamic_obstacles[..2] {
        let piece = format!("{}_{}_moves_2", o.obstacle_type.as_str(), o.id);
        assert!(text.contains(&piece), "no {piece}: one piece");
    }
    // forward again: every state within 0.01 m
    let request = convert::Request { source: "slow road users".into(), ..convert::Request::named(&xosc, "slow") }.keeping_model();
    let options = convert::ConvertOptions { dt: 0.1, ..Default::default() };
    let (conversion, model) = convert::convert(&request, &options);
    assert!(conversion.result.is_ok(), "convert: {:?}", conversion.result.err().map(|f| f.message));
    let model = model.expect("the model");
    let by_id: std::collections::HashMap<u64, &str> = model.names.iter().map(|(id, n)| (*id, n.as_str())).collect();
    for o in &scenario.dynamic_obstacles {
        let name = format!("{}_{}", o.obstacle_type.as_str(), o.id);
        let back = model.scenario.dynamic_obstacles.iter().find(|b| by_id.get(&b.id.get()) == Some(&name.as_str())).expect("converted back");
        let got: std::collections::HashMap<u64, (f64, f64)> =
            std::iter::once(&back.initial_state).chain(&back.trajectory).map(|s| (s.time_step, (s.x, s.y))).collect();
        for s in std::iter::once(&o.initial_state).chain(&o.trajectory) {
            let (x, y) = got.get(&s.time_step).copied().unwrap_or_else(|| panic!("{name}: no state at step {}", s.time_step));
            let d = (x - s.x).hypot(y - s.y);
            assert!(d <= POSITION, "{name} at step {}: {d} m off", s.time_step);
        }
        assert_eq!(got.len(), 1 + o.trajectory.len(), "{name}: states at steps it does not have");
    }
}

#[test]
fn stopping_and_creeping_road_users_replay_within_a_centimetre_in_esmini() {
    let Some(esmini) = testkit::esmini(false) else { return };
    let dir = fresh_dir("slow-esmini");
    let (xosc, scenario, _) = export_slow(&dir);
    let (log, problems) = run_esmini(&esmini, &xosc, 0.05, &[]);
    assert!(problems.is_empty(), "{problems:?}");
    let (worst, missing) = compare(&log.expect("a log"), &expectations(&scenario, 2));
    assert!(worst <= POSITION && missing == 0, "worst {worst} m, {missing} states missing");
}
