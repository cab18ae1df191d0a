//! The 2024 reader is the writer's inverse: every readable scenario of
//! `../shared/commonroad-scenarios` (and the minimal example) written as the three 2024 files
//! and read back is the same model, but for what the 2024 format cannot say (documented with
//! the writer: a stop line's references, an intersection's isLeftOf, a light's default
//! "active", a missing initial acceleration, the position of a sign or light that had none);
//! the files are found from the scenario file's name; and what the model cannot hold is a
//! warning.

use std::path::PathBuf;

use crate::common;

use commonroad::*;

/// The model as the 2024 format keeps it.
fn as_2024_keeps(mut s: Scenario, mut p: PlanningProblemSet) -> (Scenario, PlanningProblemSet) {
    for l in &mut s.network.lanelets {
        if let Some(sl) = &mut l.stop_line {
            sl.traffic_sign_refs.clear();
            sl.traffic_light_refs.clear();
            if sl.points.is_none() {
                sl.points = Some([*l.bounds.left().last().expect("point"), *l.bounds.right().last().expect("point")]);
            }
        }
    }
    for i in &mut s.network.intersections {
        for inc in &mut i.incomings {
            inc.is_left_of = None;
        }
    }
    for t in &mut s.network.traffic_lights {
        t.active = t.active.filter(|a| !a);
    }
    for pp in &mut p.problems {
        pp.initial_state.acceleration.get_or_insert(0.0);
    }
    (s, p)
}

fn compare(name: &str, s: Scenario, p: PlanningProblemSet) {
    let files = protobuf::write(&s, &p).expect("2024");
    let read = protobuf::read::read(&files.map.bytes, &files.scenario, &files.dynamic, std::path::Path::new(name)).expect("reads back");
    let (want_s, want_p) = as_2024_keeps(s, p);
    let mut got = read.scenario;
    for (g, w) in got.network.traffic_signs.iter_mut().zip(&want_s.network.traffic_signs) {
        if w.position.is_none() {
            g.position = None;
        }
    }
    for (g, w) in got.network.traffic_lights.iter_mut().zip(&want_s.network.traffic_lights) {
        if w.position.is_none() {
            g.position = None;
        }
    }
    assert_eq!(got.header, want_s.header, "{name}: header");
    assert_eq!(got.tags, want_s.tags, "{name}: tags");
    assert_eq!(got.network.lanelets, want_s.network.lanelets, "{name}: lanelets");
    assert_eq!(got.network.traffic_lights, want_s.network.traffic_lights, "{name}: lights");
    assert_eq!(got.network.intersections, want_s.network.intersections, "{name}: intersections");
    // a sign whose id the country's table lacks is written UNKNOWN and read back without it
    for (g, w) in got.network.traffic_signs.iter().zip(&want_s.network.traffic_signs) {
        assert_eq!((g.id, g.position, g.is_virtual), (w.id, w.position, w.is_virtual), "{name}: sign {}", w.id);
        assert!(g.elements.iter().all(|e| w.elements.contains(e)), "{name}: sign {} elements {:?} of {:?}", w.id, g.elements, w.elements);
    }
    assert_eq!(got.static_obstacles, want_s.static_obstacles, "{name}: static obstacles");
    assert_eq!(got.dynamic_obstacles, want_s.dynamic_obstacles, "{name}: dynamic obstacles");
    assert_eq!(got.environment_obstacles, want_s.environment_obstacles, "{name}: environment obstacles");
    assert_eq!(read.problems, want_p, "{name}: planning problems");
}

#[test]
fn the_minimal_example_reads_back() {
    let m = common::minimal();
    compare("minimal", m.scenario, m.problems);
}

#[test]
fn every_commonroad_scenario_reads_back_from_2024() {
    let Some(shared) = testkit::shared_dir() else { return };
    let mut compared = 0;
    for f in testkit::files_with_ext(&shared.join("commonroad-scenarios"), "xml") {
        let Ok(r) = xml::read_scenario_file(&f) else { continue };
        if r.problems.problems.is_empty() {
            continue; // a scenario file of the 2024 format needs a planning problem
        }
        compare(&f.display().to_string(), r.scenario, r.problems);
        compared += 1;
    }
    assert!(compared >= 15, "{compared} scenarios compared");
}

#[test]
fn the_three_files_are_found_from_the_scenario_file() {
    let m = common::minimal();
    let files = protobuf::write(&m.scenario, &m.problems).expect("2024");
    let dir = std::env::temp_dir().join(format!("osc2cr-protobuf-reader-{}", std::process::id()));
    let sub = dir.join("sub");
    std::fs::create_dir_all(&sub).expect("dirs");
    // the map at the top of the output, the scenario in a sub-folder (as a batch writes them)
    std::fs::write(dir.join(files.map.file_name()), &files.map.bytes).expect("map");
    let sc: PathBuf = sub.join(protobuf::scenario_file_name("minimal"));
    std::fs::write(&sc, &files.scenario).expect("scenario");
    std::fs::write(sub.join(protobuf::dynamic_file_name("minimal")), &files.dynamic).expect("dynamic");
    assert!(protobuf::read::is_scenario_file(&sc));
    let read = protobuf::read::read_files(&sc).expect("found and read");
    assert_eq!(read.scenario.dynamic_obstacles, m.scenario.dynamic_obstacles);
    // without the map: an error naming it
    std::fs::remove_file(dir.join(files.map.file_name())).expect("remove");
    let e = protobuf::read::read_files(&sc).expect_err("no map");
    assert!(e.to_string().contains(&files.map.id), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
