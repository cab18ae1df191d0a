//! Files written by the model pass `cr_check.py` (both 2020a XSDs, commonroad-io 2026.1 and
//! 2024.3 readers, semantic checks). Skipped with a notice when `../shared` is absent.

use crate::common;

use std::path::PathBuf;

use commonroad::xml::{write_map, write_scenario};
use commonroad::*;

fn out_path(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("commonroad-oracle");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn write_file(name: &str, bytes: &[u8]) -> PathBuf {
    let p = out_path(name);
    xml::write_atomic(&p, bytes).unwrap();
    p
}

#[test]
fn minimal_example_built_with_the_model_passes_every_check() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let m = common::minimal();
    assert_eq!(m.scenario.validate(Some(&m.problems)), vec![]);
    let path = write_file("minimal.xml", &write_scenario(&m.scenario, &m.problems).unwrap());
    let car = m.car.to_string();
    let r = testkit::cr_check(&[&path], &["--on-road", "--drivability", "--ego-id", &car]);
    assert_eq!(r.len(), 1);
    assert!(r[0].ok, "{}", r[0].summary());
    assert_eq!(r[0].n_errors(), 0, "{}", r[0].summary());
    assert_eq!(r[0].n_warnings(), 0, "{}", r[0].summary());
    // both readers saw every element
    let counts = &r[0].json["read"]["counts"];
    assert_eq!(counts["lanelets"], 3);
    assert_eq!(counts["traffic_signs"], 1);
    assert_eq!(counts["dynamic_obstacles"], 1);
    assert_eq!(r[0].json["extra_reads"][0]["counts"]["planning_problems"], 1);
}

#[test]
fn obstacle_appearing_at_step_5_is_written_from_5_and_passes_with_one_warning() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let mut m = common::minimal();
    let mut ids = m.scenario.id_allocator(Some(&m.problems));
    let late = ids.obstacle();
    let t0 = 5;
    m.scenario.dynamic_obstacles.push(DynamicObstacle {
        id: late,
        obstacle_type: DynamicObstacleType::Car,
        shape: Shape::rectangle(4.0, 1.8).unwrap(),
        initial_state: common::state(t0, 30.0, 1.75, 10.0),
        trajectory: (t0 + 1..=t0 + 4).map(|t| common::state(t, 30.0 + (t - t0) as f64, 1.75, 10.0)).collect(),
    });
    assert_eq!(m.scenario.validate(Some(&m.problems)), vec![]);
    let bytes = write_scenario(&m.scenario, &m.problems).unwrap();

    let text = String::from_utf8(bytes.clone()).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let obstacle = doc.descendants().find(|n| n.has_tag_name("dynamicObstacle") && n.attribute("id") == Some(late.to_string().as_str())).unwrap();
    let time_of = |n: roxmltree::Node| -> u64 {
        let t = n.children().find(|c| c.has_tag_name("time")).unwrap();
        t.children().find(|c| c.has_tag_name("exact")).unwrap().text().unwrap().parse().unwrap()
    };
    let init = obstacle.children().find(|c| c.has_tag_name("initialState")).unwrap();
    assert_eq!(time_of(init), 5);
    let traj = obstacle.children().find(|c| c.has_tag_name("trajectory")).unwrap();
    let times: Vec<u64> = traj.children().filter(|c| c.has_tag_name("state")).map(time_of).collect();
    assert_eq!(times, vec![6, 7, 8, 9]);

    let path = write_file("late.xml", &bytes);
    let r = &testkit::cr_check(&[&path], &[])[0];
    assert!(r.ok, "{}", r.summary());
    assert_eq!(r.n_warnings(), 1, "{}", r.summary());
    assert_eq!(r.warning_counts.get("xsd"), Some(&1), "{}", r.summary());
    assert!(r.warnings[0].msg.contains("initialState time=5"), "{}", r.summary());
    // with --strict-xsd the same file fails: the warning really is about the late start
    let strict = &testkit::cr_check(&[&path], &["--strict-xsd"])[0];
    assert!(!strict.ok);
}

#[test]
fn map_mode_writes_no_planning_problem_and_passes_map_only_check() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let m = common::minimal();
    let mut map = m.scenario.clone();
    map.static_obstacles.clear();
    map.dynamic_obstacles.clear();
    assert_eq!(map.validate(None), vec![]);
    let bytes = write_map(&map).unwrap();
    assert!(!String::from_utf8(bytes.clone()).unwrap().contains("planningProblem"));
    let path = write_file("map.xml", &bytes);
    let r = &testkit::cr_check(&[&path], &["--map-only"])[0];
    assert!(r.ok, "{}", r.summary());
    assert_eq!(r.n_warnings(), 0, "{}", r.summary());
}

/// Every optional construct the model offers, in one file.
fn kitchen_sink() -> (Scenario, PlanningProblemSet) {
    let mut m = common::minimal();
    let mut ids = m.scenario.id_allocator(Some(&m.problems));
    let s = &mut m.scenario;
    s.tags = Tag::ALL.iter().copied().collect();
    s.location.geo_transformation = Some(GeoTransformation::proj("+proj=utm +zone=32 +ellps=WGS84 <&>"));
    s.header.author = "Zoë & \"friends\" <team>".into();
    // z coordinates and a stop line without points on a new lanelet behind lanelet 3
    let [_, _, l3] = m.lanelets;
    let l4 = ids.lanelet();
    let mut lane = Lanelet::new(
        l4,
        LaneletBounds::new(
            vec![Point::with_z(150.0, 3.5, 0.5), Point::with_z(200.0, 3.5, 0.75)],
            vec![Point::with_z(150.0, 0.0, 0.5), Point::with_z(200.0, 0.0, 0.75)],
        )
        .unwrap(),
        LaneletType::Urban,
    );
    lane.predecessors.push(l3);
    lane.user_bidirectional.push(RoadUser::Pedestrian);
    lane.stop_line = Some(StopLine { points: None, line_marking: LineMarking::BroadSolid, traffic_sign_refs: vec![], traffic_light_refs: vec![] });
    let sign2 = ids.traffic_sign();
    lane.traffic_sign_refs.push(sign2);
    let light2 = ids.traffic_light();
    lane.traffic_light_refs.push(light2);
    s.network.lanelets[2].successors.push(l4);
    s.network.lanelets.push(lane);
    s.network.traffic_signs.push(TrafficSign {
        id: sign2,
        elements: vec![TrafficSignElement::new("206"), TrafficSignElement::new("1002-10")],
        position: None,
        is_virtual: true,
    });
    s.network.traffic_lights.push(TrafficLight {
        id: light2,
        cycle: vec![CycleElement { duration: std::num::NonZeroU64::new(30).unwrap(), color: TrafficLightColor::Inactive }],
        time_offset: 7,
        position: None,
        direction: Some(TrafficLightDirection::LeftStraight),
        active: None,
    });
    let inc1 = ids.incoming();
    let inc2 = ids.incoming();
    s.network.intersections.push(Intersection {
        id: ids.intersection(),
        incomings: vec![common::incoming(inc1, m.lanelets[0], [&[], &[l3], &[]], Some(inc2)), common::incoming(inc2, m.lanelets[1], [&[l4], &[], &[l3]], None)],
        crossings: vec![vec![l4]],
    });
    s.dynamic_obstacles.push(DynamicObstacle {
        id: ids.obstacle(),
        obstacle_type: DynamicObstacleType::Pedestrian,
        shape: Shape::circle(0.4).unwrap(),
        initial_state: State { time_step: 0, x: 160.0, y: -2.0, orientation: std::f64::consts::FRAC_PI_2, velocity: 1.0, acceleration: 0.0, yaw_rate: 0.0 },
        trajectory: (1..=3)
            .map(|t| State {
                time_step: t,
                x: 160.0,
                y: -2.0 + 0.1 * t as f64,
                orientation: std::f64::consts::FRAC_PI_2,
                velocity: 1.0,
                acceleration: 0.0,
                yaw_rate: 0.0,
            })
            .collect(),
    });
    let tri = Polygon::new(vec![Point::new(-0.5, -0.5), Point::new(0.5, -0.5), Point::new(0.0, 0.5)]).unwrap();
    s.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::RoadBoundary,
        shape: Shape::Polygon(tri.clone()),
        x: 120.0,
        y: -3.0,
        orientation: 0.3,
    });
    let b1 = EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Building,
        shape: AbsoluteShape::Rectangle(PlacedRectangle { rectangle: Rectangle::new(20.0, 10.0).unwrap(), center: Point::new(50.0, 30.0), orientation: 0.1 }),
    };
    let pillar = EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Pillar,
        shape: AbsoluteShape::Circle(PlacedCircle { circle: Circle::new(0.3).unwrap(), center: Point::new(60.0, -5.0) }),
    };
    let strip = EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::MedianStrip,
        shape: AbsoluteShape::Polygon(Polygon::new(vec![Point::new(0.0, 8.0), Point::new(100.0, 8.0), Point::new(100.0, 9.0), Point::new(0.0, 9.0)]).unwrap()),
    };
    s.environment_obstacles = vec![b1, pillar, strip];
    let pp = &mut m.problems.problems[0];
    pp.initial_state.acceleration = None;
    pp.goal_states.push(GoalState {
        time: TimeInterval::new(0, 1).unwrap(),
        position: Some(GoalPosition::Circles(vec![PlacedCircle { circle: Circle::new(2.0).unwrap(), center: Point::new(140.0, 1.75) }])),
        orientation: None,
        velocity: None,
    });
    let mut second = pp.clone();
    second.id = ids.planning_problem();
    second.goal_states = vec![GoalState {
        time: TimeInterval::new(5, 50).unwrap(),
        position: Some(GoalPosition::Polygons(vec![Polygon::new(vec![Point::new(130.0, 0.0), Point::new(150.0, 0.0), Point::new(150.0, 3.5)]).unwrap()])),
        orientation: None,
        velocity: Some(Interval::new(1.0, 2.0).unwrap()),
    }];
    m.problems.problems.push(second);
    (m.scenario, m.problems)
}

#[test]
fn every_optional_construct_passes_every_check() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let (s, p) = kitchen_sink();
    assert_eq!(s.validate(Some(&p)), vec![]);
    let path = write_file("kitchen_sink.xml", &write_scenario(&s, &p).unwrap());
    let r = &testkit::cr_check(&[&path], &["--on-road"])[0];
    assert!(r.ok, "{}", r.summary());
    assert_eq!(r.n_errors(), 0, "{}", r.summary());
    let counts = &r.json["read"]["counts"];
    assert_eq!(counts["lanelets"], 4, "{}", r.json);
    assert_eq!(counts["intersections"], 1);
    assert_eq!(counts["planning_problems"], 2);
    assert_eq!(r.json["extra_reads"][0]["counts"]["traffic_signs"], 2, "{}", r.json);
}
