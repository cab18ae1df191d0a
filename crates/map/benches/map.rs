//! Times load + convert + write of every corpus map (release: `cargo bench -p osc2cr-map`).
//! Prints per-map medians over several runs, then the median and maximum over all maps.

use std::path::Path;
use std::time::{Duration, Instant};

const RUNS: usize = 7;

fn median(v: &mut [Duration]) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

fn main() {
    let shared =
        std::env::var_os("OSC2CR_SHARED").map(std::path::PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let files = testkit::files_with_ext(&shared.join("corpus"), "xodr");
    if files.is_empty() {
        eprintln!("notice: no corpus maps under {}; nothing to time", shared.display());
        return;
    }
    let out_dir = std::env::temp_dir().join(format!("osc2cr-map-bench-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&out_dir);
    let date = commonroad::Date::new(2026, 1, 1).ok();
    let mut medians = Vec::new();
    for f in &files {
        let mut times = Vec::new();
        let mut convert_times = Vec::new();
        let mut lanelets = 0;
        for _ in 0..RUNS {
            let t0 = Instant::now();
            let Ok(loaded) = opendrive::load(f) else {
                eprintln!("{}: does not load", f.display());
                break;
            };
            let t1 = Instant::now();
            let r = map::convert(&loaded.network, &map::MapOptions::default());
            convert_times.push(t1.elapsed());
            lanelets = r.network.lanelets.len();
            let stem = f.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            let (Some(date), Ok(out)) = (date, Ok::<_, ()>(out_dir.join(format!("{stem}.xml")))) else { break };
            let Ok(sc) = map::map_scenario(&loaded.network, r, &stem, date) else { break };
            let Ok(bytes) = commonroad::xml::write_map(&sc) else { break };
            if commonroad::xml::write_atomic(&out, &bytes).is_err() {
                break;
            }
            times.push(t0.elapsed());
        }
        let m = median(&mut times);
        let rel = f.strip_prefix(shared.join("corpus")).unwrap_or(f);
        let c = median(&mut convert_times);
        println!("{:>9.3} ms (convert {:>8.3} ms)  {:>5} lanelets  {}", m.as_secs_f64() * 1e3, c.as_secs_f64() * 1e3, lanelets, rel.display());
        medians.push(m);
    }
    let max = medians.iter().max().copied().unwrap_or_default();
    let med = median(&mut medians);
    println!("{} maps: median {:.3} ms, max {:.3} ms per map (load + convert + write)", files.len(), med.as_secs_f64() * 1e3, max.as_secs_f64() * 1e3);
    let _ = std::fs::remove_dir_all(&out_dir);
}
