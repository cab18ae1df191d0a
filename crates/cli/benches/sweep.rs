//! The parameter-sweep benchmark: `examples/sweep/motorway_sweep.xosc` (a cut-in on a 10 km
//! motorway, 100,000 variations) converted by `osc2cr convert -j 2`, in the 2024 format and in
//! 2020a; and an ALKS-like sweep, `benches/data/alks_like_cut_in_sweep.xosc` (a cut-in in the
//! manner of the UN R157 templates — speeds in km/h through expressions, constraints whose
//! bounds are expressions, a vehicle catalog — on the ASAM examples' motorway from
//! `../shared/corpus`, 20,480 variations), converted in full in the 2024 format. For each run:
//! wall time, variations per second, the converting process's peak memory (its maximum resident
//! set, from `wait4`, as `/usr/bin/time -v` reports it), the disk its outputs take (allocated
//! blocks and bytes), and where the time goes (the stages' sums from the JSON report). Figures,
//! not assertions: it prints them and checks only that everything converted.
//!
//!     cargo bench -p osc2cr --bench sweep
//!     OSC2CR_SWEEP_SIZES= OSC2CR_SWEEP_2020A_SIZES= cargo bench -p osc2cr --bench sweep   # the ALKS-like sweep alone
//!
//! Environment: `OSC2CR_SWEEP_SIZES` (2024 runs, default `1000,10000,100000`),
//! `OSC2CR_SWEEP_2020A_SIZES` (default `1000`: each 2020a file repeats the map, 0.8 MB, so the
//! whole sweep would need ~80 GB; its disk and time are extrapolated from this subset, and said
//! so), `OSC2CR_SWEEP_ALKS_LIKE` (`0` skips the ALKS-like sweep; it also needs `../shared`),
//! `OSC2CR_SWEEP_JOBS` (default 2), `OSC2CR_SWEEP_OUT` (default `target/sweep-bench`;
//! outputs are removed after each run unless `OSC2CR_SWEEP_KEEP=1`).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

fn sizes(var: &str, default: &str) -> Vec<u64> {
    std::env::var(var).unwrap_or_else(|_| default.to_string()).split(',').filter_map(|s| s.trim().parse().ok()).collect()
}

/// Files, bytes and allocated bytes below `dir`.
fn disk_use(dir: &Path) -> (u64, u64, u64) {
    use std::os::unix::fs::MetadataExt;
    let (mut files, mut bytes, mut allocated) = (0, 0, 0);
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let Ok(m) = e.metadata() else { continue };
            if m.is_dir() {
                stack.push(e.path());
            } else {
                files += 1;
                bytes += m.len();
                allocated += m.blocks() * 512;
            }
        }
    }
    (files, bytes, allocated)
}

struct Run {
    sweep: &'static str,
    format: &'static str,
    variations: u64,
    wall_s: f64,
    peak_rss_mb: f64,
    files: u64,
    bytes: u64,
    allocated: u64,
    maps: usize,
    /// Milliseconds summed over the variations, per stage of the JSON report (load, …, write).
    stages: Vec<(String, f64)>,
}

/// Runs the conversion of `variations` of `sweep` (all of them: `None`, as a limit above any
/// sweep's size) as a child process and waits for it with `wait4`, which reports the child's own
/// peak resident set.
#[allow(clippy::zombie_processes)] // the child is reaped by `wait4`, which clippy does not see
fn run(name: &'static str, sweep: &Path, format: &'static str, variations: Option<u64>, jobs: &str, out: &Path) -> Run {
    let _ = std::fs::remove_dir_all(out);
    let table = out.with_extension("tsv");
    let report = out.with_extension("json");
    let limit = ["--max-variations".to_string(), variations.unwrap_or(u64::MAX).to_string()];
    let start = Instant::now();
    // waited for below with wait4, which std's Child cannot do (it gives no rusage)
    #[allow(clippy::zombie_processes)]
    let child = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .arg("convert")
        .arg(sweep)
        .arg("-o")
        .arg(out)
        .args(["--format", format, "-j", jobs])
        .args(&limit)
        .arg("--report")
        .arg(&report)
        .arg("--table")
        .arg(&table)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("osc2cr starts");
    let pid = child.id() as libc::pid_t;
    let mut status = 0;
    // SAFETY: an all-zero rusage is a valid value for wait4 to fill
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: pid is our child, the pointers are valid for the call
    let waited = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let wall_s = start.elapsed().as_secs_f64();
    assert_eq!(waited, pid, "wait4: {}", std::io::Error::last_os_error());
    assert!(libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0, "osc2cr {name} {format} {variations:?} failed ({status})");
    let rows = std::fs::read_to_string(&table).expect("table");
    let planned = rows.lines().skip(1).count() as u64;
    let converted = rows.lines().skip(1).filter(|l| l.split('\t').nth(3) == Some("converted")).count() as u64;
    assert_eq!(converted, planned, "every variation converted");
    let (files, bytes, allocated) = disk_use(out);
    let maps = std::fs::read_dir(out).map(|rd| rd.flatten().filter(|e| e.file_name().to_string_lossy().starts_with("ZAM_")).count()).unwrap_or(0);
    let stages = stage_sums(&report);
    let _ = std::fs::remove_file(&report);
    Run { sweep: name, format, variations: converted, wall_s, peak_rss_mb: usage.ru_maxrss as f64 / 1024.0, files, bytes, allocated, maps, stages }
}

/// The report's per-stage times summed over its scenarios, in the report's order.
fn stage_sums(report: &Path) -> Vec<(String, f64)> {
    let Ok(text) = std::fs::read_to_string(report) else { return Vec::new() };
    let Ok(json) = serde_json::from_str::<serde_json::Value>(&text) else { return Vec::new() };
    let mut sums: Vec<(String, f64)> = Vec::new();
    for s in json["scenarios"].as_array().into_iter().flatten() {
        for (stage, ms) in s["timings"].as_object().into_iter().flatten() {
            let ms = ms.as_f64().unwrap_or(0.0);
            match sums.iter_mut().find(|(k, _)| k == stage) {
                Some(slot) => slot.1 += ms,
                None => sums.push((stage.clone(), ms)),
            }
        }
    }
    sums
}

/// The ALKS-like sweep written into `dir` with the corpus map and vehicle catalog at their
/// absolute paths; the distribution's path. None when `../shared` is absent.
fn alks_like_sweep(dir: &Path) -> Option<PathBuf> {
    let examples = testkit::shared_dir()?.join("corpus/osc-examples-1.3");
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/data");
    std::fs::create_dir_all(dir).expect("sweep folder");
    let scenario = std::fs::read_to_string(data.join("alks_like_cut_in.xosc"))
        .expect("scenario")
        .replace("@MAP@", &examples.join("Databases/AB_RQ31_Straight.xodr").display().to_string())
        .replace("@VEHICLES@", &examples.join("Catalogs/Vehicles").display().to_string());
    std::fs::write(dir.join("alks_like_cut_in.xosc"), scenario).expect("write scenario");
    std::fs::copy(data.join("alks_like_cut_in_sweep.xosc"), dir.join("alks_like_cut_in_sweep.xosc")).expect("distribution");
    Some(dir.join("alks_like_cut_in_sweep.xosc"))
}

fn gb(b: u64) -> f64 {
    b as f64 / 1e9
}

/// A run's line of the table (the progress line after each run too): sweep, format,
/// variations, wall s, variations/s, peak RSS MB, files, disk GB, bytes GB, per variation KB,
/// maps.
fn row(r: &Run) -> String {
    format!(
        "{:<9}  {:<6}  {:>10}  {:>7.1}  {:>12.1}  {:>11.1}  {:>6}  {:>8.3}  {:>8.3}  {:>16.1}  {:>4}",
        r.sweep,
        r.format,
        r.variations,
        r.wall_s,
        r.variations as f64 / r.wall_s,
        r.peak_rss_mb,
        r.files,
        gb(r.allocated),
        gb(r.bytes),
        r.allocated as f64 / r.variations as f64 / 1e3,
        r.maps
    )
}

fn main() {
    // `cargo bench` passes --bench; nothing else is read from the command line
    let jobs = std::env::var("OSC2CR_SWEEP_JOBS").unwrap_or_else(|_| "2".into());
    let root: PathBuf = std::env::var_os("OSC2CR_SWEEP_OUT").map(PathBuf::from).unwrap_or_else(|| testkit::workspace_root().join("target/sweep-bench"));
    let keep = std::env::var_os("OSC2CR_SWEEP_KEEP").is_some();
    std::fs::create_dir_all(&root).expect("output folder");
    let motorway = testkit::workspace_root().join("examples/sweep/motorway_sweep.xosc");
    let mut plan: Vec<(&'static str, PathBuf, &'static str, Option<u64>)> = sizes("OSC2CR_SWEEP_SIZES", "1000,10000,100000")
        .into_iter()
        .map(|n| ("motorway", motorway.clone(), "2024", Some(n)))
        .chain(sizes("OSC2CR_SWEEP_2020A_SIZES", "1000").into_iter().map(|n| ("motorway", motorway.clone(), "2020a", Some(n))))
        .collect();
    if std::env::var("OSC2CR_SWEEP_ALKS_LIKE").map_or(true, |v| v != "0") {
        match alks_like_sweep(&root.join("alks-like-input")) {
            Some(sweep) => plan.push(("alks-like", sweep, "2024", None)),
            None => eprintln!("notice: ../shared not found; the ALKS-like sweep is skipped"),
        }
    }
    let mut runs = Vec::new();
    for (name, sweep, format, n) in plan {
        let out = root.join(format!("{name}-{format}-{}", n.map_or("all".to_string(), |n| n.to_string())));
        eprintln!(
            "converting {} variations of {} in {format} with -j {jobs} into {} ...",
            n.map_or("all".to_string(), |n| n.to_string()),
            sweep.display(),
            out.display()
        );
        let r = run(name, &sweep, format, n, &jobs, &out);
        eprintln!("  {}", row(&r));
        if !keep {
            let _ = std::fs::remove_dir_all(&out);
        }
        runs.push(r);
    }
    println!("\nsweeps with -j {jobs}, {} CPUs", std::thread::available_parallelism().map_or(1, |n| n.get()));
    println!("sweep      format  variations   wall s  variations/s  peak RSS MB  files   disk GB  bytes GB  per variation KB  maps");
    for r in &runs {
        println!("{}", row(r));
    }
    println!("\nwhere the time goes (ms per variation, summed over the -j workers' threads):");
    for r in &runs {
        let parts: Vec<String> = r.stages.iter().map(|(k, ms)| format!("{} {:.2}", k.trim_end_matches("_ms"), ms / r.variations as f64)).collect();
        println!("{:<9}  {:<6}  {:>10}  {}", r.sweep, r.format, r.variations, parts.join(", "));
    }
    // the whole sweep in 2020a, extrapolated from the largest 2020a run (per-variation cost)
    if let Some(r) = runs.iter().filter(|r| r.format == "2020a").max_by_key(|r| r.variations) {
        let total = 100_000.0;
        let scale = total / r.variations as f64;
        println!(
            "2020a extrapolated to 100000 variations from {}: {:.0} s, {:.1} GB on disk (not run: it would not fit)",
            r.variations,
            r.wall_s * scale,
            gb((r.allocated as f64 * scale) as u64)
        );
    }
}
