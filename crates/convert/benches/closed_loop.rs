//! What driving an entity from outside costs the engine, in Rust (release: `cargo bench -p
//! osc2cr-convert --bench closed_loop`): esmini's cut-in run to the end by the batch engine,
//! stepped by a closed-loop session with nobody outside, and with the ego fed its own
//! open-loop states (the outside replacing the script, and under esmini's override rule),
//! one engine step or one CommonRoad step (ten engine steps) per call. Median of RUNS runs,
//! per engine step. `benches/closed_loop.py` adds what stepping from Python costs on top.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use convert::{ClosedLoop, ConvertOptions};
use engine::{External, ExternalState, Input, Sample, ScriptedMotion};

const RUNS: usize = 15;

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

fn main() {
    let shared = std::env::var_os("OSC2CR_SHARED").map(PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let path = std::env::args().nth(1).filter(|a| a.ends_with(".xosc")).map(PathBuf::from).unwrap_or_else(|| shared.join("corpus/esmini/xosc/cut-in.xosc"));
    if !path.is_file() {
        eprintln!("notice: {} not found; nothing to time", path.display());
        return;
    }
    let options = ConvertOptions::default();
    let start = |external: &External| ClosedLoop::start(&path, &options, external).unwrap_or_else(|f| panic!("{}: {}", path.display(), f.message));

    // the batch engine and the ego's states at every engine step
    let mut open = start(&External::none());
    let ego_name = open.open_loop().0.facts.ego.unwrap_or_else(|| "Ego".into());
    let ego = open.entity_names().iter().position(|n| *n == ego_name).unwrap_or(0);
    let mut recorded: Vec<Option<Sample>> = Vec::new();
    while open.step_with(&[]).unwrap_or(false) {
        recorded.push(open.state(ego));
    }
    recorded.push(open.state(ego));
    let steps = recorded.len();
    let scenario = open.scenario().clone();
    let net = scenario.road_network.logic_file.as_ref().and_then(|p| opendrive::load(p).ok()).map(|l| l.network);
    let settings = engine::Settings { step: options.step, max_time: options.max_time };
    let batch = median(
        (0..RUNS)
            .map(|_| {
                let t = Instant::now();
                let _ = engine::simulate_with(&scenario, net.as_ref(), &settings, &engine::RunControl::default());
                t.elapsed()
            })
            .collect(),
    );

    let input = |k: usize| match recorded.get(k).copied().flatten() {
        Some(s) => Input::State(ExternalState::new(s.x, s.y, s.h, s.speed)),
        None => Input::Hold,
    };
    let time = |external: &External, per_call: usize| {
        median(
            (0..RUNS)
                .map(|_| {
                    let mut run = start(external);
                    let named = !matches!(external.entities, engine::Chosen::None);
                    let t = Instant::now();
                    let mut k = 0;
                    loop {
                        let inputs: Vec<(usize, Input)> = if named { vec![(ego, input(k + per_call - 1))] } else { Vec::new() };
                        k += per_call;
                        if !run.step_held(&inputs, per_call).unwrap_or(false) {
                            break;
                        }
                    }
                    t.elapsed()
                })
                .collect(),
        )
    };
    let per_step = |d: Duration| d.as_secs_f64() * 1e6 / steps as f64;
    let replaced = External { motion: ScriptedMotion::Replaced, ..External::named([ego_name.as_str()]) };
    let overridden = External::named([ego_name.as_str()]);
    println!("{} ({steps} engine steps, median of {RUNS}), µs per engine step:", path.display());
    println!("  batch engine (simulate_with)                 {:>7.3}", per_step(batch));
    for (what, external) in
        [("session, nobody outside", External::none()), ("session, ego replayed, replaced", replaced), ("session, ego replayed, overridden", overridden)]
    {
        for per_call in [1, 10] {
            let d = time(&external, per_call);
            println!("  {what:<36} {per_call:>2}/call {:>7.3}  ({:.2}x)", per_step(d), d.as_secs_f64() / batch.as_secs_f64());
        }
    }
}
