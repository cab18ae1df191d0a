//! Times load + resolve of every corpus scenario (parsing, parameters, catalogs).
//! `cargo bench -p osc2cr-openscenario --bench load`; prints per-file mean times, the largest file's
//! time and the total.

use openscenario::{load, Content, LoadOptions};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The `.xosc` files below `dir` but those of its `Catalogs` folders, sorted.
fn xosc_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = testkit::files_with_ext(dir, "xosc");
    out.retain(|p| !p.strip_prefix(dir).unwrap_or(p).components().any(|c| c.as_os_str() == "Catalogs"));
    out
}

fn main() {
    let shared = std::env::var_os("OSC2CR_SHARED").map(PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let corpus = shared.join("corpus");
    if !corpus.is_dir() {
        eprintln!("corpus not found at {}", corpus.display());
        return;
    }
    let options = LoadOptions::default();
    let mut rows = Vec::new();
    for f in xosc_files(&corpus) {
        // Scenarios only (distribution files do not load their scenario).
        let Ok(first) = load(&f, &options) else { continue };
        if !matches!(first.content, Content::Scenario(_)) {
            continue;
        }
        let iterations = 50;
        let start = Instant::now();
        for _ in 0..iterations {
            let _ = std::hint::black_box(load(&f, &options));
        }
        let mean = start.elapsed().as_secs_f64() / f64::from(iterations);
        let size = std::fs::metadata(&f).map(|m| m.len()).unwrap_or(0);
        rows.push((f, size, mean));
    }
    rows.sort_by(|a, b| b.2.total_cmp(&a.2));
    println!("{:>10} {:>10}  file", "ms", "bytes");
    for (f, size, mean) in rows.iter().take(10) {
        println!("{:>10.3} {:>10}  {}", mean * 1e3, size, f.strip_prefix(&corpus).unwrap_or(f).display());
    }
    if let Some((f, size, mean)) = rows.iter().max_by_key(|r| r.1) {
        println!("largest scenario: {} ({size} bytes): {:.3} ms", f.strip_prefix(&corpus).unwrap_or(f).display(), mean * 1e3);
    }
    let total: f64 = rows.iter().map(|r| r.2).sum();
    println!("{} scenarios, total {:.1} ms, mean {:.3} ms", rows.len(), total * 1e3, total * 1e3 / rows.len().max(1) as f64);
}
