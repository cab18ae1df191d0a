//! Closed loop reacts: in esmini's cut-in (the OverTaker keeps 1.2 times the ego's speed,
//! cuts in once the ego's time headway to it exceeds 0.4 s and brakes once it exceeds 0.7 s),
//! an ego that brakes hard from 2 s on instead of cruising at 30 m/s makes the cut-in and the
//! braking come at other times, and the OverTaker drives another trajectory.

use engine::{External, ExternalState, Input, RunControl, Settings, Simulation, StoryboardEvent};

/// When `event` started.
fn start_of(events: &[StoryboardEvent], event: &str) -> Option<f64> {
    events.iter().find(|e| e.element == event && e.transition == "start").map(|e| e.time)
}

#[test]
fn an_ego_that_brakes_moves_the_cut_in() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("corpus/esmini/xosc/cut-in.xosc");
    let (scenario, _) = openscenario::load_scenario(&path, &Default::default()).expect("loads");
    let net = scenario.road_network.logic_file.as_ref().map(|p| opendrive::load(p).expect("map").network);
    let (settings, control) = (Settings::default(), RunControl::default());
    let open = engine::simulate_with(&scenario, net.as_ref(), &settings, &control).expect("runs");
    let ego = open.trace.entities.iter().position(|e| e.name == "Ego").expect("Ego");
    let overtaker = open.trace.entities.iter().position(|e| e.name == "OverTaker").expect("OverTaker");

    // The ego's open-loop path by distance travelled: the closed-loop ego drives the same
    // path, braking at 6 m/s² from 2 s on.
    let path_pts: Vec<_> = open.trace.entities[ego].samples.iter().flatten().copied().collect();
    let mut along = vec![0.0];
    for w in path_pts.windows(2) {
        along.push(along[along.len() - 1] + (w[1].x - w[0].x).hypot(w[1].y - w[0].y));
    }
    let at = |d: f64| {
        let k = along.partition_point(|&a| a <= d).clamp(1, along.len() - 1);
        let (a, b) = (path_pts[k - 1], path_pts[k]);
        let f = ((d - along[k - 1]) / (along[k] - along[k - 1]).max(1e-12)).clamp(0.0, 1.0);
        (a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.h + f * engine_wrap(b.h - a.h))
    };
    let dt = settings.step;
    let v0 = path_pts[0].speed;
    let mut sim = Simulation::new(&scenario, net.as_ref(), &settings, &control, &External::named(["Ego"])).expect("starts");
    let (mut d, mut v) = (0.0, v0);
    while !sim.is_over() {
        let t = sim.time() + dt;
        if t > 2.0 {
            v = (v - 6.0 * dt).max(0.0);
        }
        d += v * dt;
        let (x, y, h) = at(d);
        sim.step_with(&[(ego, Input::State(ExternalState::new(x, y, h, v)))]).expect("steps");
    }
    let closed = sim.finish();

    let open_cut_in = start_of(&open.trace.events, "CutInEvent").expect("the open-loop run cuts in");
    let closed_cut_in = start_of(&closed.trace.events, "CutInEvent").expect("the closed-loop run cuts in");
    let open_brake = start_of(&open.trace.events, "OvertakerBrakeEvent").expect("the open-loop OverTaker brakes");
    let closed_brake = start_of(&closed.trace.events, "OvertakerBrakeEvent").expect("the closed-loop OverTaker brakes");
    eprintln!("cut-in: open loop {open_cut_in:.2} s, ego braking {closed_cut_in:.2} s; brake: {open_brake:.2} s, {closed_brake:.2} s");
    // The OverTaker slows with the ego, so it passes it no sooner and the cut-in comes a
    // little later; but the ego, braking, falls back fast: the 0.7 s headway that makes the
    // OverTaker brake comes over a second sooner.
    assert!(closed_cut_in > open_cut_in + 0.05, "cut-in at {closed_cut_in} s, open loop {open_cut_in} s");
    assert!(closed_brake < open_brake - 1.0, "braking at {closed_brake} s, open loop {open_brake} s");
    assert!(closed_brake > closed_cut_in, "the OverTaker brakes after it cut in");
    // and the OverTaker, whose speed follows the ego's, drives elsewhere
    let gap = |row: usize| {
        let (a, b) = (open.trace.entities[overtaker].samples[row], closed.trace.entities[overtaker].samples[row]);
        a.zip(b).map_or(0.0, |(a, b)| (a.x - b.x).hypot(a.y - b.y))
    };
    let row = ((open_cut_in + 1.0) / dt) as usize;
    assert!(gap(row) > 10.0, "the OverTaker is {} m from its open-loop position at {} s", gap(row), open_cut_in + 1.0);
}

fn engine_wrap(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    (a + std::f64::consts::PI).rem_euclid(two_pi) - std::f64::consts::PI
}
