//! The 2024 writer against commonroad-io 2026.1: a model written as 2020a XML and as the three
//! 2024 files reads back as the same objects (`testkit::compare_2024`, object by object), for
//! the minimal example and for a model with the rarer parts (circle and polygon shapes, an
//! environment obstacle, several goal shapes, a lanelet goal, a sign and a light without a
//! position, a stop line without points, an intersection with a crossing). The map is named by
//! its content, and the same model gives the same bytes.

use crate::common;

use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use commonroad::*;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("osc2cr-protobuf-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Writes both renderings of the model into `dir` and returns the case to compare.
fn write_both(dir: &Path, stem: &str, scenario: &Scenario, problems: &PlanningProblemSet) -> (testkit::Case2024, Vec<String>) {
    let xml = dir.join(format!("{stem}.xml"));
    std::fs::write(&xml, xml::write_scenario(scenario, problems).expect("xml")).expect("write xml");
    let files = protobuf::write(scenario, problems).expect("2024");
    let map = dir.join(files.map.file_name());
    let sc = dir.join(protobuf::scenario_file_name(stem));
    let dy = dir.join(protobuf::dynamic_file_name(stem));
    std::fs::write(&map, &files.map.bytes).expect("write map");
    std::fs::write(&sc, &files.scenario).expect("write scenario");
    std::fs::write(&dy, &files.dynamic).expect("write dynamic");
    (testkit::Case2024 { xml, map, scenario: sc, dynamic: dy }, files.warnings)
}

/// The minimal example with what it lacks.
fn rich() -> (Scenario, PlanningProblemSet) {
    let m = common::minimal();
    let (mut scenario, mut problems) = (m.scenario, m.problems);
    let mut ids = scenario.id_allocator(Some(&problems));
    let [l1, _, l3] = m.lanelets;
    // a sign and a light without position (the 2024 map needs one: placed as the readers do)
    let sign = ids.traffic_sign();
    scenario.network.traffic_signs.push(TrafficSign {
        id: sign,
        elements: vec![TrafficSignElement::new("206"), TrafficSignElement { sign_id: "R2-1".into(), additional_values: vec![] }],
        position: None,
        is_virtual: true,
    });
    let light = ids.traffic_light();
    scenario.network.traffic_lights.push(TrafficLight {
        id: light,
        cycle: vec![CycleElement { duration: NonZeroU64::new(7).expect("7"), color: TrafficLightColor::Green }],
        time_offset: 3,
        position: None,
        direction: Some(TrafficLightDirection::LeftStraight),
        active: Some(true),
    });
    for l in &mut scenario.network.lanelets {
        if l.id == l3 {
            l.traffic_sign_refs.push(sign);
            l.traffic_light_refs.push(light);
            if let Some(sl) = l.stop_line.as_mut() {
                sl.points = None;
                sl.traffic_light_refs.push(light);
            }
            l.left_marking = None;
        }
    }
    let inc = ids.incoming();
    scenario.network.intersections.push(Intersection {
        id: ids.intersection(),
        incomings: vec![common::incoming(inc, l1, [&[], &[l3], &[]], None)],
        crossings: vec![vec![l3]],
    });
    scenario.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::ConstructionZone,
        shape: Shape::circle(1.5).expect("circle"),
        x: 120.0,
        y: 1.0,
        orientation: 0.3,
    });
    let poly = Polygon::new(vec![Point::new(-1.0, -0.5), Point::new(1.0, -0.5), Point::new(0.0, 0.8)]).expect("polygon");
    let walker = |t: u64| State { time_step: t, x: 30.0, y: -2.0 + 0.1 * t as f64, orientation: 1.5, velocity: 1.0, acceleration: 0.0, yaw_rate: 0.0 };
    scenario.dynamic_obstacles.push(DynamicObstacle {
        id: ids.obstacle(),
        obstacle_type: DynamicObstacleType::Pedestrian,
        shape: Shape::Polygon(poly.clone()),
        initial_state: walker(4),
        trajectory: (5..=9).map(walker).collect(),
    });
    scenario.environment_obstacles.push(EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Building,
        shape: AbsoluteShape::Polygon(
            Polygon::new(vec![Point::new(0.0, 20.0), Point::new(10.0, 20.0), Point::new(10.0, 30.0), Point::new(0.0, 30.0)]).expect("building"),
        ),
    });
    let p = &mut problems.problems[0];
    p.initial_state.acceleration = None;
    p.goal_states.push(GoalState {
        time: TimeInterval::new(0, 5).expect("time"),
        position: Some(GoalPosition::Circles(vec![
            PlacedCircle { circle: Circle::new(2.0).expect("circle"), center: Point::new(60.0, 1.0) },
            PlacedCircle { circle: Circle::new(1.0).expect("circle"), center: Point::new(70.0, 1.0) },
        ])),
        orientation: None,
        velocity: Some(Interval::new(1.0, 2.0).expect("interval")),
    });
    p.goal_states.push(GoalState {
        time: TimeInterval::new(3, 9).expect("time"),
        position: Some(GoalPosition::Polygons(vec![poly])),
        orientation: Some(Interval::new(-0.1, 0.2).expect("interval")),
        velocity: None,
    });
    scenario.tags.insert(Tag::Intersection);
    assert!(scenario.validate(Some(&problems)).is_empty(), "{:?}", scenario.validate(Some(&problems)));
    (scenario, problems)
}

#[test]
fn commonroad_io_reads_the_2024_files_as_the_2020a_file() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let dir = tmp("read-back");
    let m = common::minimal();
    let (minimal, minimal_warnings) = write_both(&dir, "minimal", &m.scenario, &m.problems);
    assert!(minimal_warnings.is_empty(), "{minimal_warnings:?}");
    let (s, p) = rich();
    let (rich_case, rich_warnings) = write_both(&dir, "rich", &s, &p);
    // the sign and the light without position are placed, and each says so
    for what in ["trafficSign", "trafficLight"] {
        assert!(rich_warnings.iter().any(|w| w.starts_with(what) && w.contains("no position")), "{what}: {rich_warnings:?}");
    }
    // the comparison can fail: the minimal example's XML against the richer model's 2024 files
    let crossed = testkit::Case2024 { xml: minimal.xml.clone(), ..rich_case.clone() };
    let results = testkit::compare_2024(&[minimal, rich_case, crossed], &dir);
    for r in &results[..2] {
        assert!(r.ok, "{}", r.summary());
    }
    let crossed = &results[2];
    assert!(!crossed.ok && crossed.error.is_none(), "{}", crossed.summary());
    for expected in ["traffic signs: ids only in 2020a [], only in 2024 [", "dynamic_obstacles: ids", "planningProblem"] {
        assert!(crossed.differences.iter().any(|d| d.contains(expected)), "{expected}: {}", crossed.summary());
    }
    // everything was there to compare
    let counted = &results[1].counted;
    for (kind, at_least) in [
        ("lanelets", 3),
        ("traffic signs", 2),
        ("traffic lights", 2),
        ("intersections", 1),
        ("stop lines", 1),
        ("static_obstacles", 2),
        ("dynamic_obstacles", 2),
        ("environment_obstacle", 1),
        ("trajectory states", 8),
        ("planning problems", 1),
    ] {
        assert!(counted[kind].as_u64().unwrap_or(0) >= at_least, "{kind}: {counted}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_map_is_named_by_its_content_and_shared_by_scenarios_that_have_it() {
    let m = common::minimal();
    let a = protobuf::write(&m.scenario, &m.problems).expect("2024");
    assert_eq!(protobuf::write(&m.scenario, &m.problems).expect("again"), a, "same model, same bytes");
    assert!(a.map.id.starts_with("DEU_") && a.map.id.ends_with("-1"), "{}", a.map.id);
    assert_eq!(a.map.file_name(), format!("{}.pb", a.map.id));
    assert_eq!(protobuf::map_id_of_scenario(&a.scenario).as_deref(), Some(a.map.id.as_str()));

    // other obstacles, another benchmark id, an author: the same map
    let mut other = m.scenario.clone();
    other.header.benchmark_id = BenchmarkId::parse("DEU_Other-1_7_T-1").expect("id");
    other.header.author = "someone else".into();
    other.dynamic_obstacles.clear();
    let b = protobuf::write(&other, &m.problems).expect("2024");
    assert_eq!(b.map, a.map);
    assert_ne!(b.dynamic, a.dynamic);

    // one point moved by a micrometre: another map, another name
    let mut moved = m.scenario.clone();
    let l = &mut moved.network.lanelets[0];
    let mut left = l.bounds.left().to_vec();
    left[1].x += 1e-6;
    l.bounds = LaneletBounds::new(left, l.bounds.right().to_vec()).expect("bounds");
    let c = protobuf::write(&moved, &m.problems).expect("2024");
    assert_ne!(c.map.id, a.map.id);
    assert_ne!(c.map.bytes, a.map.bytes);
}

#[test]
fn ids_in_the_range_of_the_maps_parts_are_refused() {
    let m = common::minimal();
    let mut s = m.scenario.clone();
    s.dynamic_obstacles[0].id = ObstacleId::new(protobuf::FIRST_MAP_PART_ID).expect("id");
    let e = protobuf::write(&s, &m.problems).expect_err("refused");
    assert!(e.to_string().contains("1000000000"), "{e}");
    let mut s = m.scenario.clone();
    s.dynamic_obstacles[0].trajectory[1].x = f64::NAN;
    let e = protobuf::write(&s, &m.problems).expect_err("refused");
    assert!(e.to_string().contains("dynamicObstacle") && e.to_string().contains("time step 2"), "{e}");
    assert!(matches!(protobuf::write(&m.scenario, &PlanningProblemSet::default()), Err(commonroad::Error::NoPlanningProblem { .. })));
}
