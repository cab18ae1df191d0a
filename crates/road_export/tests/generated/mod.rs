//! The map round trip on generated lanelet networks: maps nobody here has seen, drawn by a
//! seeded generator (`families.rs`, on the tools of `builder.rs`) with the shapes real maps
//! have. Each network is exported, read back by osc2cr's map conversion and compared with
//! `round_trip::compare` under the acceptance's criteria (every bound within 0.05 m, relations
//! kept, at most 1 % area added).
//!
//! The CI test runs a few networks of every family; `GENERATED=<count>` with
//! `GENERATED_SEEDS=1,2,...` runs the ignored `generated_networks_at_scale` on more and prints
//! the pass rate per family and the failures.

mod builder;
mod families;

use crate::common::read_back;
use families::{draw, Family, FAMILIES};
use std::collections::BTreeMap;

/// One generated network.
pub(crate) struct Generated {
    pub family: Family,
    pub what: String,
    pub network: commonroad::LaneletNetwork,
}

/// Network `index` of `seed` (its family by turns); redrawn until valid (what `cr_check.py`
/// would accept), at most 50 times.
pub(crate) fn generate(seed: u64, index: usize) -> Generated {
    let family = FAMILIES[index % FAMILIES.len()];
    let mut rng = builder::Rng::new(seed.wrapping_mul(1_000_003).wrapping_add(index as u64));
    let mut why = String::new();
    for _ in 0..50 {
        let (network, what) = draw(&mut rng, family);
        match builder::invalid(&network) {
            None => return Generated { family, what, network },
            Some(w) => why = w,
        }
    }
    panic!("seed {seed} network {index} ({family:?}): no valid network in 50 draws; the last: {why}");
}

/// The outcome of one network's round trip: `None` = passes, else what failed.
pub(crate) fn round_trip(g: &Generated) -> Option<String> {
    let export = match road_export::export(&g.network, &road_export::Options::default()) {
        Ok(e) => e,
        Err(e) => return Some(format!("export error: {e}")),
    };
    let back = read_back(&export.xodr);
    let c = road_export::round_trip::compare(&g.network, &back);
    if c.passes(0.05, 0.01) {
        return None;
    }
    let mut kinds = Vec::new();
    if c.worst_bound_error() > 0.05 {
        kinds.push(format!("bound error {:.3} m", c.worst_bound_error().min(99.0)));
    }
    if c.relations_kept < c.relations {
        kinds.push(format!("relations {}/{}", c.relations_kept, c.relations));
    }
    if c.added_fraction() > 0.01 {
        kinds.push(format!("area added {:.2} %", 100.0 * c.added_fraction()));
    }
    Some(format!("{}; {}", kinds.join(", "), c.failures(0.05).into_iter().take(4).collect::<Vec<_>>().join("; ")))
}

/// Runs `count` networks of each seed; per family (passed, run) and the failures.
fn run(seeds: &[u64], count: usize) -> (BTreeMap<Family, (usize, usize)>, Vec<String>) {
    let mut table: BTreeMap<Family, (usize, usize)> = BTreeMap::new();
    let mut failures = Vec::new();
    for &seed in seeds {
        for index in 0..count {
            let g = generate(seed, index);
            let outcome = std::panic::catch_unwind(|| round_trip(&g)).unwrap_or_else(|_| Some("panic".into()));
            let row = table.entry(g.family).or_default();
            row.1 += 1;
            match outcome {
                None => row.0 += 1,
                Some(why) => failures.push(format!("seed {seed} #{index} {}: {why}", g.what)),
            }
        }
    }
    (table, failures)
}

fn print(table: &BTreeMap<Family, (usize, usize)>) {
    let (mut p, mut n) = (0, 0);
    for (f, (pass, run)) in table {
        eprintln!("{:<12} {pass:>4} / {run:<4}", format!("{f:?}"));
        p += pass;
        n += run;
    }
    eprintln!("all          {p:>4} / {n:<4}");
}

#[test]
fn generated_networks_are_valid_and_deterministic() {
    for index in 0..FAMILIES.len() {
        let (a, b) = (generate(7, index), generate(7, index));
        assert_eq!(a.network, b.network, "network {index} differs between two draws of one seed");
        assert!(builder::invalid(&a.network).is_none());
        assert!(a.network.lanelets.len() >= 2, "{}", a.what);
    }
}

/// Generated networks of the CI run (seed 1) that do not pass yet, and why.
const KNOWN: &[(u64, usize, &str)] = &[(
    1,
    0,
    "a four-lane road whose free end (no successors) is bowed: its lanelets end 1.03 m apart along the road, a lane section ends on one straight cross-section, so lanelet 8 comes back more than 1 m longer (no match); it still fails with free_ends.rs (whose lines would leave each lane's own end within about 0.75 m; not analysed why)",
)];

#[test]
fn generated_networks_round_trip() {
    // three networks of every family
    let (seed, count) = (1, 3 * FAMILIES.len());
    let mut failures = Vec::new();
    let mut still_known = Vec::new();
    for index in 0..count {
        let g = generate(seed, index);
        let known = KNOWN.iter().any(|&(s, i, _)| s == seed && i == index);
        match (round_trip(&g), known) {
            (None, true) => still_known.push(index),
            (Some(why), false) => failures.push(format!("#{index} {}: {why}", g.what)),
            _ => {}
        }
    }
    assert!(failures.is_empty(), "generated networks that fail the round trip:\n{}", failures.join("\n"));
    assert!(still_known.is_empty(), "these pass now; take them out of KNOWN: {still_known:?}");
}

/// `GENERATED=200 GENERATED_SEEDS=1,2 cargo test --release -p osc2cr-road-export --test tests
/// generated_networks_at_scale -- --ignored --nocapture`
#[test]
#[ignore = "slow: set GENERATED (networks per seed) and GENERATED_SEEDS"]
fn generated_networks_at_scale() {
    let count = std::env::var("GENERATED").ok().and_then(|v| v.parse().ok()).unwrap_or(200);
    let seeds: Vec<u64> =
        std::env::var("GENERATED_SEEDS").ok().map(|v| v.split(',').filter_map(|s| s.trim().parse().ok()).collect()).unwrap_or_else(|| vec![1]);
    let (table, failures) = run(&seeds, count);
    for f in &failures {
        eprintln!("FAIL {f}");
    }
    print(&table);
}

/// A lanelet's point count and the ends of its bounds, as text.
fn ends(l: &commonroad::Lanelet) -> String {
    let (a, b) = (l.bounds.left(), l.bounds.right());
    let p = |q: Option<&commonroad::Point>| q.map_or(String::new(), |q| format!("({:.2},{:.2})", q.x, q.y));
    format!("points {} left {}->{} right {}->{}", a.len(), p(a.first()), p(a.last()), p(b.first()), p(b.last()))
}

/// One network in detail: `GENERATED_ONE=<seed>:<index>` (and `GENERATED_DUMP=<dir>` for its
/// CommonRoad XML and OpenDRIVE files).
#[test]
#[ignore = "a tool: set GENERATED_ONE=<seed>:<index>"]
fn generated_network_in_detail() {
    let Some((seed, index)) = std::env::var("GENERATED_ONE").ok().and_then(|v| v.split_once(':').and_then(|(a, b)| Some((a.parse().ok()?, b.parse().ok()?))))
    else {
        return;
    };
    let g = generate(seed, index);
    eprintln!("{}", g.what);
    let export = road_export::export(&g.network, &road_export::Options::default()).expect("exports");
    for w in &export.warnings {
        eprintln!("warning: {w}");
    }
    let back = read_back(&export.xodr);
    let c = road_export::round_trip::compare(&g.network, &back);
    for f in c.failures(0.05) {
        eprintln!("{f}");
    }
    for r in c.lanelets.iter().filter(|r| r.bound_error > 0.05 || !r.lost.is_empty()) {
        eprintln!("lanelet {} matched {:?}", r.id, r.matched);
    }
    for l in &g.network.lanelets {
        eprintln!(
            "lanelet {} {} succ {:?} pred {:?} adj {:?} {:?}",
            l.id,
            ends(l),
            l.successors.iter().map(|x| x.get()).collect::<Vec<_>>(),
            l.predecessors.iter().map(|x| x.get()).collect::<Vec<_>>(),
            l.adjacent_left.map(|x| (x.lanelet.get(), x.driving_dir)),
            l.adjacent_right.map(|x| (x.lanelet.get(), x.driving_dir))
        );
    }
    for l in &back.lanelets {
        eprintln!("back {} {}", l.id, ends(l));
    }
    if let Some(dir) = std::env::var_os("GENERATED_DUMP") {
        let dir = std::path::PathBuf::from(dir);
        std::fs::create_dir_all(&dir).expect("creates the folder");
        std::fs::write(dir.join(format!("gen_{seed}_{index}.xodr")), &export.xodr).expect("writes");
        let mut scenario = commonroad::Scenario::new(builder::header());
        scenario.network = g.network.clone();
        let xml = commonroad::xml::write_map(&scenario).expect("writes XML");
        std::fs::write(dir.join(format!("gen_{seed}_{index}.xml")), xml).expect("writes");
    }
}

/// Generated networks whose lanes are cut on zig-zag joints (the joint's points on no
/// straight line; up to 1.4 m apart along the road) and which failed before `joints.rs`
/// sliced such joints: every bound back within 5 cm, every relation kept.
#[test]
fn zig_zag_joints_round_trip() {
    for (seed, index) in [(1, 55), (1, 136), (1, 153), (1, 154), (2, 46)] {
        let g = generate(seed, index);
        assert_eq!(round_trip(&g), None, "seed {seed} #{index} {}", g.what);
    }
}
