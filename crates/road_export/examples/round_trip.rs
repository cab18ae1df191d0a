//! The map round trip on CommonRoad files given on the command line: export each lanelet
//! network, read the OpenDRIVE back with osc2cr's map conversion, compare, print one line per
//! map (`-v`: the failing lanelets and the warnings; `--out DIR`: keep the .xodr files).
//!
//! `cargo run --release -p osc2cr-road-export --example round_trip -- FILE.xml...`

use std::path::{Path, PathBuf};
use std::time::Instant;

fn main() {
    let mut verbose = false;
    let mut out: Option<PathBuf> = None;
    let mut files = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "-v" => verbose = true,
            "--out" => out = args.next().map(PathBuf::from),
            _ => files.push(PathBuf::from(a)),
        }
    }
    let (mut pass, mut total, mut worst) = (0, 0, 0.0f64);
    for f in &files {
        // an OpenSCENARIO file: osc2cr's conversion of it, in-process (full precision)
        let network = if f.extension().is_some_and(|e| e == "xosc") {
            let name = stem(f);
            let request = convert::Request::named(f, &name).keeping_model();
            match convert::convert(&request, &convert::ConvertOptions::default()).1 {
                Some(m) => m.scenario.network,
                None => {
                    println!("{}: does not convert", f.display());
                    continue;
                }
            }
        } else {
            match commonroad::xml::read_scenario_file(f) {
                Ok(r) => r.scenario.network,
                Err(e) => {
                    println!("{}: unreadable: {e}", f.display());
                    continue;
                }
            }
        };
        let net = &network;
        if net.lanelets.is_empty() {
            continue;
        }
        total += 1;
        let t0 = Instant::now();
        let opts = road_export::Options { name: stem(f), ..Default::default() };
        let exported = match road_export::export(net, &opts) {
            Ok(e) => e,
            Err(e) => {
                println!("{}: export failed: {e}", f.display());
                continue;
            }
        };
        let dt = t0.elapsed();
        if let Some(dir) = &out {
            let _ = std::fs::create_dir_all(dir);
            let _ = std::fs::write(dir.join(format!("{}.xodr", stem(f))), &exported.xodr);
        }
        let back = match opendrive::parse_str(&exported.xodr, Path::new("export.xodr")) {
            Ok(l) => map::convert(&l.network, &map::MapOptions::default()).network,
            Err(e) => {
                println!("{}: read back failed: {e}", f.display());
                continue;
            }
        };
        let c = road_export::round_trip::compare(net, &back);
        let ok = c.passes(0.05, 0.01);
        pass += usize::from(ok);
        worst = worst.max(c.worst_bound_error());
        println!(
            "{} {:<60} lanelets {:>4} back {:>4} err {:>8.4} rel {}/{} added {:.4}% warn {} {:.1} ms",
            if ok { "PASS" } else { "FAIL" },
            f.file_name().map(|x| x.to_string_lossy().into_owned()).unwrap_or_default(),
            net.lanelets.len(),
            back.lanelets.len(),
            c.worst_bound_error(),
            c.relations_kept,
            c.relations,
            100.0 * c.added_fraction(),
            exported.warnings.len(),
            dt.as_secs_f64() * 1e3
        );
        if verbose {
            for l in c.failures(0.05).iter().take(200) {
                println!("    {l}");
            }
            for w in exported.warnings.iter().take(200) {
                println!("    warning: {w}");
            }
        }
    }
    println!("{pass} of {total} maps pass; worst bound error {worst:.4} m");
}

fn stem(f: &Path) -> String {
    f.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default()
}
