use crate::common::{exports, read_back};

#[test]
fn scratch_diag() {
    let Some(exports) = exports() else { return };
    let want = std::env::var("DIAG").unwrap_or_default();
    for e in exports.iter().filter(|e| e.name.contains(&want)) {
        let back = read_back(&e.export.xodr);
        let c = road_export::round_trip::compare(&e.network, &back);
        eprintln!("== {}", e.name);
        for f in c.failures(0.05) {
            eprintln!("  {f}");
        }
        for w in &e.export.warnings {
            eprintln!("  W {w}");
        }
        if let Ok(at) = std::env::var("DIAG_AT") {
            let v: Vec<f64> = at.split(',').map(|x| x.parse().unwrap()).collect();
            for l in &back.lanelets {
                for (side, b) in [("L", l.bounds.left()), ("R", l.bounds.right())] {
                    for (k, p) in b.iter().enumerate() {
                        if (p.x - v[0]).hypot(p.y - v[1]) < v[2] {
                            eprintln!("  back {} {side} #{k}/{} ({:.4}, {:.4})", l.id.get(), b.len(), p.x, p.y);
                        }
                    }
                }
            }
        }
        if let Ok(ids) = std::env::var("DIAG_IDS") {
            for id in ids.split(',').filter_map(|s| s.parse::<u64>().ok()) {
                if let Some(l) = e.network.lanelets.iter().find(|l| l.id.get() == id) {
                    eprintln!("  lanelet {id} left {:?}", l.bounds.left().iter().map(|p| (p.x, p.y)).collect::<Vec<_>>());
                    eprintln!("  lanelet {id} right {:?}", l.bounds.right().iter().map(|p| (p.x, p.y)).collect::<Vec<_>>());
                }
            }
        }
    }
}

#[test]
fn scratch_time() {
    let Some(exports) = exports() else { return };
    let mut total = 0.0;
    let mut lines = Vec::new();
    let cpu = || -> f64 {
        let s = std::fs::read_to_string("/proc/self/stat").unwrap();
        let f: Vec<&str> = s.rsplit(')').next().unwrap().split_whitespace().collect();
        (f[11].parse::<f64>().unwrap() + f[12].parse::<f64>().unwrap()) / 100.0
    };
    let c0 = cpu();
    for e in exports {
        let mut v = Vec::new();
        for _ in 0..3 {
            let t = std::time::Instant::now();
            let _ = road_export::export(&e.network, &road_export::Options { name: e.name.clone(), ..Default::default() });
            v.push(t.elapsed().as_secs_f64());
        }
        v.sort_by(f64::total_cmp);
        total += v[1];
        lines.push(format!("TIME {:.4} {}", v[1], e.name));
    }
    eprintln!("{}", lines.join("\n"));
    eprintln!("TIME total {total:.3} s over {} maps; cpu {:.2} s for 3 runs", exports.len(), cpu() - c0);
}
