//! Load time of every corpus map and the cost of 10k world → road queries per map.
//! Run: cargo bench -p osc2cr-opendrive --bench load [-- SHARED_DIR]

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};
use std::time::Instant;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

fn main() {
    let shared = std::env::args()
        .skip(1)
        .find(|a| !a.starts_with('-'))
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let files = testkit::files_with_ext(&shared.join("corpus"), "xodr");
    if files.is_empty() {
        eprintln!("no corpus under {}", shared.display());
        return;
    }
    let mut loads = Vec::new();
    let mut queries = Vec::new();
    println!("{:>9} {:>11} {:>11} {:>11}  map", "load ms", "query µs", "hint µs", "max q µs");
    for f in &files {
        let mut times = Vec::new();
        let mut net = None;
        for _ in 0..5 {
            let t0 = Instant::now();
            let l = opendrive::load(f).expect("corpus map loads");
            times.push(t0.elapsed().as_secs_f64() * 1e3);
            net = Some(l.network);
        }
        let Some(net) = net else { continue };
        let load_ms = median(&mut times);
        // 10k points on lanes, seeded.
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut pts = Vec::with_capacity(10_000);
        while pts.len() < 10_000 {
            let ri = rng.gen_range(0..net.roads.len());
            let r = &net.roads[ri];
            let s = rng.gen_range(0.0..r.length.max(1e-9));
            let sec = r.section_index_at(s);
            let lanes = r.side_borders(sec, rng.gen_bool(0.5), s);
            if lanes.is_empty() {
                continue;
            }
            let (id, _) = lanes[rng.gen_range(0..lanes.len())];
            if let Some(p) = net.lane_to_world(ri, id, s, 0.0) {
                pts.push((p.x, p.y, ri));
            }
        }
        let mut per = Vec::with_capacity(pts.len());
        let t0 = Instant::now();
        let mut found = 0usize;
        for &(x, y, _) in &pts {
            let q0 = Instant::now();
            found += usize::from(net.world_to_lane(x, y, None).is_some());
            per.push(q0.elapsed().as_secs_f64() * 1e6);
        }
        let mean_q = t0.elapsed().as_secs_f64() * 1e6 / pts.len() as f64;
        let t1 = Instant::now();
        for &(x, y, ri) in &pts {
            found += usize::from(net.world_to_lane(x, y, Some(ri)).is_some());
        }
        let mean_h = t1.elapsed().as_secs_f64() * 1e6 / pts.len() as f64;
        let maxq = per.iter().copied().fold(0.0, f64::max);
        assert_eq!(found, 2 * pts.len());
        println!("{load_ms:>9.3} {mean_q:>11.3} {mean_h:>11.3} {maxq:>11.1}  {}", f.strip_prefix(&shared).unwrap_or(f).display());
        loads.push(load_ms);
        queries.push(mean_q);
    }
    let lmax = loads.iter().copied().fold(0.0, f64::max);
    let qmax = queries.iter().copied().fold(0.0, f64::max);
    println!(
        "SUMMARY load: median {:.3} ms, max {lmax:.3} ms; world->road query (mean per map): median {:.3} µs, max {qmax:.3} µs",
        median(&mut loads),
        median(&mut queries)
    );
}
