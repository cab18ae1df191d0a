//! Write the engine's trace of every corpus scenario that has a reference trace:
//! `cargo run --release -p osc2cr-engine --example corpus_traces -- SHARED_DIR OUT_DIR`
//! (OUT_DIR/<path under corpus without .xosc>.csv), and print the engine's speed.

use std::path::PathBuf;
use std::time::Instant;

/// CPU time this thread has run, in seconds (Linux schedstat; `None` elsewhere): on a loaded
/// machine wall time overstates the engine's cost.
fn thread_cpu_s() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    text.split_whitespace().next()?.parse::<f64>().ok().map(|ns| ns * 1e-9)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let shared = PathBuf::from(args.get(1).map_or("../shared", |s| s.as_str()));
    let out_dir = PathBuf::from(args.get(2).map_or("TRACES", |s| s.as_str()));
    let filter = args.get(3).cloned();
    let corpus = shared.join("corpus");
    let reference = shared.join("reference/esmini-3.6.0");
    let files = testkit::files_with_ext(&corpus, "xosc");
    let (mut sim_time, mut wall, mut cpu) = (0.0, 0.0, 0.0);
    for f in files {
        let rel = f.strip_prefix(&corpus).unwrap_or(&f).with_extension("");
        if !reference.join(rel.with_extension("json")).exists() {
            continue;
        }
        if let Some(flt) = &filter {
            if !rel.to_string_lossy().contains(flt.as_str()) {
                continue;
            }
        }
        let (scenario, _) = match openscenario::load_scenario(&f, &Default::default()) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("{}: load failed: {e}", rel.display());
                continue;
            }
        };
        let net = scenario.road_network.logic_file.as_ref().and_then(|p| match opendrive::load(p) {
            Ok(l) => Some(l.network),
            Err(e) => {
                eprintln!("{}: road network: {e}", rel.display());
                None
            }
        });
        let c0 = thread_cpu_s();
        let t0 = Instant::now();
        let run = match engine::simulate(&scenario, net.as_ref(), &engine::Settings::default()) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("{}: {e}", rel.display());
                continue;
            }
        };
        let el = t0.elapsed().as_secs_f64();
        wall += el;
        if let (Some(a), Some(b)) = (c0, thread_cpu_s()) {
            cpu += b - a;
        }
        sim_time += run.trace.duration();
        eprintln!("{}: {:.2} s simulated in {:.2} ms, {} warnings", rel.display(), run.trace.duration(), el * 1e3, run.warnings.len());
        if std::env::var("WARN").is_ok() {
            for w in &run.warnings {
                eprintln!("   {w}");
            }
        }
        let path = out_dir.join(rel.with_extension("csv"));
        if let Some(p) = path.parent() {
            let _ = std::fs::create_dir_all(p);
        }
        let _ = std::fs::write(&path, run.trace.to_csv(&engine::bounding_boxes(&scenario)));
        if std::env::var("EVENTS").is_ok() {
            let mut ev = String::from("time,element,from,transition,to\n");
            for e in &run.trace.events {
                ev.push_str(&format!("{:.3},{},{},{},{}\n", e.time, e.element, e.from, e.transition, e.to));
            }
            let _ = std::fs::write(out_dir.join(rel.with_extension("events.csv")), ev);
        }
    }
    println!("simulated {sim_time:.1} s in {:.1} ms of engine time: {:.0}x real time", wall * 1e3, sim_time / wall.max(1e-12));
    if cpu > 0.0 {
        println!("engine CPU time {:.1} ms: {:.0}x real time per CPU second", cpu * 1e3, sim_time / cpu);
    }
}
