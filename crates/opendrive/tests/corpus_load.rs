//! Every corpus map loads; geometry continuity is measured and reported.

use crate::common;

#[test]
fn all_corpus_maps_load() {
    let Some(files) = common::corpus_xodr() else { return };
    assert_eq!(files.len(), 99, "expected the 99 corpus maps");
    let mut failures = Vec::new();
    for f in &files {
        match opendrive::load(f) {
            Ok(l) => {
                let n = l.network.roads.len();
                eprintln!("{:>5} roads {:>4} warnings  {}", n, l.warnings.len(), f.display());
                let mut kinds = std::collections::BTreeMap::<String, usize>::new();
                for w in &l.warnings {
                    *kinds.entry(w.message.chars().take(60).collect()).or_default() += 1;
                }
                for (k, c) in kinds {
                    eprintln!("        {c:>4} × {k}");
                }
                assert!(n > 0);
            }
            Err(e) => failures.push(e.to_string()),
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// End of geometry i vs start of geometry i+1 (position and heading), over all roads.
#[test]
fn geometry_continuity_is_measured() {
    let Some(files) = common::corpus_xodr() else { return };
    let mut worst_file = (0.0f64, String::new());
    for f in &files {
        let Ok(l) = opendrive::load(f) else { continue };
        let mut worst = 0.0f64;
        let mut worst_h = 0.0f64;
        for r in &l.network.roads {
            for w in r.geometries.windows(2) {
                let end = w[0].pose_at(w[0].length);
                let gap = (end.x - w[1].x).hypot(end.y - w[1].y);
                let dh = (end.hdg - w[1].hdg + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
                worst = worst.max(gap);
                worst_h = worst_h.max(dh.abs());
            }
        }
        eprintln!("continuity: max gap {:9.3e} m, max heading jump {:9.3e} rad  {}", worst, worst_h, f.display());
        if worst > worst_file.0 {
            worst_file = (worst, f.display().to_string());
        }
    }
    eprintln!("continuity: worst gap over the corpus {:.3e} m in {}", worst_file.0, worst_file.1);
}
