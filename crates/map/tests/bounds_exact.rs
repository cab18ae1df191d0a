//! Lanelet bounds against the closed-form lane borders of the `opendrive` crate: at 400
//! stations per lanelet, the exact border point lies within 1 cm of the bound polyline that
//! should carry it (+t border = left bound when driving along s, right bound otherwise).

use crate::common::*;

fn check(path: &std::path::Path) -> (usize, f64) {
    let net = load(path);
    let r = convert(&net);
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for (l, o) in r.network.lanelets.iter().zip(&r.origins) {
        let road = &net.roads[o.lane.road];
        let (s0, s1) = road.section_range(o.lane.section).unwrap();
        for k in 0..=400 {
            let s = s0 + (s1 - s0) * k as f64 / 400.0;
            let b = road.lane_borders(o.lane.section, o.lane.lane, s).unwrap();
            // every lane inward must have non-negative width for the unclamped form to apply
            let side_ok =
                road.side_borders(o.lane.section, o.lane.lane > 0, s).iter().all(|(_, bb)| (bb.outer - bb.inner) * (o.lane.lane.signum() as f64) >= 0.0);
            if !side_ok {
                continue;
            }
            let (plus_t, minus_t) = if b.outer >= b.inner { (b.outer, b.inner) } else { (b.inner, b.outer) };
            let (on_left, on_right) = if o.along_s { (plus_t, minus_t) } else { (minus_t, plus_t) };
            for (t, bound) in [(on_left, l.bounds.left()), (on_right, l.bounds.right())] {
                let p = road.st_to_world(s, t);
                let d = dist_to_polyline(p.x, p.y, bound);
                worst = worst.max(d);
                n += 1;
            }
        }
    }
    (n, worst)
}

#[test]
fn example_bounds_within_1cm_of_exact_borders() {
    let (n, worst) = check(&example("two_lane_curve.xodr"));
    assert!(n > 1000);
    assert!(worst < 0.01, "worst deviation {worst} m");
}

#[test]
fn corpus_bounds_within_1cm_of_exact_borders() {
    // lines, arcs, spirals, paramPoly3, poly3, lane offsets, width changes
    for rel in [
        "esmini/xodr/curves.xodr",
        "esmini/xodr/e6mini.xodr",
        "esmini/xodr/fabriksgatan.xodr",
        "esmini/xodr/soderleden.xodr",
        "esmini/xodr/circle_300m.xodr",
        "esmini/scenario_construct_examples/scenario_nurb_curved_road.xodr",
        "osc-examples-1.3/Databases/AB_RQ31_R2000.xodr",
    ] {
        let Some(p) = corpus(rel) else { return };
        let (n, worst) = check(&p);
        assert!(n > 1000, "{rel}: only {n} checks");
        assert!(worst < 0.01, "{rel}: worst deviation {worst} m");
    }
}
