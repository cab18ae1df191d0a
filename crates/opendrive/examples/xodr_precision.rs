//! Decision by measurement: lane borders of the `xodr` crate (f32 polylines) against this
//! crate's closed-form f64 borders, on every corpus map.
//!
//! For each vertex of each xodr lane centreline (with its width there), the vertex is
//! located on the same OpenDRIVE road with our projection; the two borders xodr implies
//! (centre ± width/2 across the road) are compared with our exact border t at that s.
//! Run: cargo run --release -p osc2cr-opendrive --example xodr_precision [SHARED_DIR]

use std::path::{Path, PathBuf};

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let shared = std::env::args().nth(1).map(PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let files = testkit::files_with_ext(&shared.join("corpus"), "xodr");
    let (mut all, mut failed) = (Vec::new(), 0usize);
    println!("{:>10} {:>10} {:>8}  map", "median mm", "max mm", "points");
    for f in &files {
        let ours = match opendrive::load(f) {
            Ok(l) => l.network,
            Err(e) => {
                println!("opendrive failed: {e}");
                continue;
            }
        };
        let theirs = match xodr::load_file(f) {
            Ok(n) => n,
            Err(e) => {
                failed += 1;
                println!("xodr cannot read {}: {e}", f.display());
                continue;
            }
        };
        let mut devs = Vec::new();
        for lane in theirs.lanes() {
            let Some(rl) = theirs.road_lane(lane.id) else { continue };
            let Some(od) = theirs.road(rl.road).map(|r| r.od_id().to_string()) else { continue };
            let Some(ri) = ours.road_index(&od) else { continue };
            let road = &ours.roads[ri];
            let pts = lane.center.points();
            for (k, p) in pts.iter().enumerate() {
                let w = f64::from(if lane.widths.is_empty() { lane.width } else { *lane.widths.get(k).or(lane.widths.last()).unwrap_or(&lane.width) });
                let Some(pos) = ours.locate_on_road(ri, f64::from(p.x), f64::from(p.y), road.length * k as f64 / pts.len().max(1) as f64) else { continue };
                // Trust only vertices inside the road's s range (a bad initial guess could land elsewhere).
                let Some(b) = road.lane_borders(rl.section, rl.od_id, pos.s) else { continue };
                let back = road.st_to_world(pos.s, pos.t);
                if (back.x - f64::from(p.x)).hypot(back.y - f64::from(p.y)) > 0.05 {
                    continue;
                }
                let (lo, hi) = (b.inner.min(b.outer), b.inner.max(b.outer));
                let d = (pos.t - 0.5 * w - lo).abs().max((pos.t + 0.5 * w - hi).abs());
                devs.push(d * 1000.0);
            }
        }
        let max = devs.iter().copied().fold(0.0, f64::max);
        let n = devs.len();
        let med = median(&mut devs);
        println!("{med:>10.3} {max:>10.3} {n:>8}  {}", f.strip_prefix(&shared).unwrap_or(f).display());
        all.extend(devs);
    }
    let max = all.iter().copied().fold(0.0, f64::max);
    let n = all.len();
    let med = median(&mut all);
    println!("ALL: median {med:.3} mm, max {max:.3} mm over {n} border points; xodr failed on {failed} of {} maps", files.len());
}
