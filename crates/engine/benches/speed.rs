//! The engine's speed over the corpus (release: `cargo bench -p osc2cr-engine --bench speed`): every
//! scenario with an esmini reference is loaded once and simulated RUNS times; the median time
//! of each scenario is summed and compared with the simulated time it covers. A median per
//! scenario, not one pass, because a single pass on a shared machine swings by ±10 %.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

const RUNS: usize = 7;

/// Runs per scenario: RUNS, or `OSC2CR_BENCH_RUNS` (1 is a quick pass for instruction counts
/// under callgrind, where the count does not vary from run to run).
fn runs() -> usize {
    std::env::var("OSC2CR_BENCH_RUNS").ok().and_then(|v| v.parse().ok()).filter(|&n| n > 0).unwrap_or(RUNS)
}

fn median(v: &mut [Duration]) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

fn main() {
    let shared = std::env::var_os("OSC2CR_SHARED").map(PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let corpus = shared.join("corpus");
    let reference = shared.join("reference/esmini-3.6.0");
    let files = testkit::files_with_ext(&corpus, "xosc");
    if files.is_empty() {
        eprintln!("notice: no corpus under {}; nothing to time", shared.display());
        return;
    }
    let settings = engine::Settings::default();
    let (mut simulated, mut total, mut fastest_total) = (0.0, Duration::ZERO, Duration::ZERO);
    let mut rows = Vec::new();
    let runs = runs();
    for f in &files {
        let rel = f.strip_prefix(&corpus).unwrap_or(f).with_extension("");
        if !reference.join(rel.with_extension("json")).exists() {
            continue;
        }
        let Ok((scenario, _)) = openscenario::load_scenario(f, &Default::default()) else { continue };
        let net = scenario.road_network.logic_file.as_ref().and_then(|p| opendrive::load(p).ok()).map(|l| l.network);
        let mut times = Vec::with_capacity(runs);
        let mut duration = 0.0;
        for _ in 0..runs {
            let t0 = Instant::now();
            let Ok(run) = engine::simulate(&scenario, net.as_ref(), &settings) else { break };
            times.push(t0.elapsed());
            duration = run.trace.end_time();
        }
        if times.is_empty() {
            continue;
        }
        let fastest = times.iter().min().copied().unwrap_or_default();
        let m = median(&mut times);
        simulated += duration;
        total += m;
        fastest_total += fastest;
        rows.push((m, rel.display().to_string(), duration));
    }
    rows.sort_by_key(|r| std::cmp::Reverse(r.0));
    // OSC2CR_BENCH_ALL=1 lists every scenario (to compare two builds scenario by scenario)
    let shown = if std::env::var_os("OSC2CR_BENCH_ALL").is_some() { rows.len() } else { 8 };
    println!("slowest scenarios (median of {runs}):");
    for (m, name, d) in rows.iter().take(shown) {
        println!("  {:>8.2} ms  {:>6.2} s  {:>8.0}x  {name}", m.as_secs_f64() * 1e3, d, d / m.as_secs_f64());
    }
    println!(
        "{} scenarios, {:.1} s simulated: medians sum to {:.1} ms = {:.0}x real time (fastest runs: {:.1} ms = {:.0}x)",
        rows.len(),
        simulated,
        total.as_secs_f64() * 1e3,
        simulated / total.as_secs_f64(),
        fastest_total.as_secs_f64() * 1e3,
        simulated / fastest_total.as_secs_f64()
    );
}
