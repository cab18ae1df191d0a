//! The XML reader: files written by `write_scenario`/`write_map` read back into the same model,
//! the shared minimal example reads into the values its text states, and bad input gives
//! errors with line and column (never a panic).

use crate::common;

use std::num::NonZeroU64;
use std::path::Path;

use commonroad::xml::{read_scenario_file, read_scenario_str, write_map, write_scenario};
use commonroad::*;

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

#[test]
fn minimal_model_round_trips() {
    let m = common::minimal();
    let bytes = write_scenario(&m.scenario, &m.problems).unwrap();
    let text = String::from_utf8(bytes).unwrap();
    let read = read_scenario_str(&text, Path::new("mem.xml")).unwrap();
    assert_eq!(read.scenario, m.scenario);
    assert_eq!(read.problems, m.problems);
    assert!(read.warnings.is_empty(), "{:?}", read.warnings);
}

/// Everything the minimal example does not have: intersections, environment obstacles,
/// circle/polygon shapes and goals, a geo transformation, a light offset, z coordinates.
fn rich() -> (Scenario, PlanningProblemSet) {
    let mut s = common::minimal().scenario;
    let mut ids = s.id_allocator(None);
    s.location.geo_transformation = Some(GeoTransformation {
        geo_reference: "+proj=utm +zone=32 +ellps=WGS84".into(),
        x_translation: 1.5,
        y_translation: -2.25,
        z_rotation: 0.1,
        scaling: 1.0,
    });
    s.network.lanelets[0].bounds = LaneletBounds::new(vec![Point::with_z(0.0, 3.5, 1.0), p(100.0, 3.5)], vec![p(0.0, 0.0), p(100.0, 0.0)]).unwrap();
    s.network.lanelets[1].user_bidirectional = vec![RoadUser::Bicycle, RoadUser::Pedestrian];
    s.network.traffic_lights[0].time_offset = 7;
    s.network.traffic_lights[0].direction = Some(TrafficLightDirection::LeftStraight);
    let l = |i: usize| s.network.lanelets[i].id;
    let (l1, l2, l3) = (l(0), l(1), l(2));
    let inc1 = ids.incoming();
    let inc2 = ids.incoming();
    s.network.intersections.push(Intersection {
        id: ids.intersection(),
        incomings: vec![common::incoming(inc1, l1, [&[l3], &[], &[l2]], Some(inc2)), common::incoming(inc2, l2, [&[], &[l3], &[]], None)],
        crossings: vec![vec![l3]],
    });
    s.environment_obstacles.push(EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Building,
        shape: AbsoluteShape::Polygon(Polygon::new(vec![p(10.0, 20.0), p(30.0, 20.0), p(30.0, 40.0)]).unwrap()),
    });
    s.environment_obstacles.push(EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Pillar,
        shape: AbsoluteShape::Circle(PlacedCircle { circle: Circle::new(0.3).unwrap(), center: p(60.0, -3.0) }),
    });
    s.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::RoadBoundary,
        shape: Shape::Polygon(Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)]).unwrap()),
        x: 3.0,
        y: -4.0,
        orientation: -1.25,
    });
    s.dynamic_obstacles.push(DynamicObstacle {
        id: ids.obstacle(),
        obstacle_type: DynamicObstacleType::Pedestrian,
        shape: Shape::circle(0.35).unwrap(),
        initial_state: State { time_step: 5, x: 40.0, y: -2.0, orientation: 1.25, velocity: 1.4, acceleration: -0.5, yaw_rate: 0.01 },
        trajectory: (6..=9)
            .map(|t| State {
                time_step: t,
                x: 40.0,
                y: -2.0 + 0.25 * (t - 5) as f64, // exact in binary: the file holds 6 decimals
                orientation: 1.25,
                velocity: 1.4,
                acceleration: 0.0,
                yaw_rate: 0.0,
            })
            .collect(),
    });
    let problems = PlanningProblemSet {
        problems: vec![PlanningProblem {
            id: ids.planning_problem(),
            initial_state: PlanningInitialState { x: 1.0, y: 2.0, orientation: 0.5, velocity: 3.0, yaw_rate: 0.25, slip_angle: -0.125, acceleration: None },
            goal_states: vec![
                GoalState {
                    time: TimeInterval::new(0, 1).unwrap(),
                    position: Some(GoalPosition::Circles(vec![
                        PlacedCircle { circle: Circle::new(2.0).unwrap(), center: p(5.0, 6.0) },
                        PlacedCircle { circle: Circle::new(1.0).unwrap(), center: p(7.0, 6.0) },
                    ])),
                    orientation: None,
                    velocity: None,
                },
                GoalState {
                    time: TimeInterval::new(3, 9).unwrap(),
                    position: Some(GoalPosition::Polygons(vec![Polygon::new(vec![p(0.0, 0.0), p(2.0, 0.0), p(1.0, 1.5)]).unwrap()])),
                    orientation: Some(Interval::new(-0.1, 0.1).unwrap()),
                    velocity: Some(Interval::new(1.0, 2.0).unwrap()),
                },
                GoalState::at_time(TimeInterval::new(4, 4).unwrap()),
            ],
        }],
    };
    (s, problems)
}

#[test]
fn rich_model_round_trips() {
    let (s, problems) = rich();
    assert!(s.validate(Some(&problems)).is_empty(), "{:?}", s.validate(Some(&problems)));
    let text = String::from_utf8(write_scenario(&s, &problems).unwrap()).unwrap();
    let read = read_scenario_str(&text, Path::new("rich.xml")).unwrap();
    assert_eq!(read.scenario, s);
    assert_eq!(read.problems, problems);
}

#[test]
fn map_file_reads_without_planning_problems() {
    let m = common::minimal();
    let text = String::from_utf8(write_map(&m.scenario).unwrap()).unwrap();
    let read = read_scenario_str(&text, Path::new("map.xml")).unwrap();
    assert_eq!(read.scenario, m.scenario);
    assert!(read.problems.problems.is_empty());
}

#[test]
fn shared_minimal_example_reads_as_its_text_says() {
    let Some(shared) = testkit::shared_dir() else { return };
    let path = shared.join("tools/examples/minimal_2020a.xml");
    let r = read_scenario_file(&path).unwrap();
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
    let s = &r.scenario;
    assert_eq!(s.header.benchmark_id.as_str(), "DEU_Example-1_1_T-1");
    assert_eq!(s.header.date.to_string(), "2026-01-15");
    assert_eq!(s.header.time_step_size, 0.1);
    assert_eq!(s.tags.iter().copied().collect::<Vec<_>>(), vec![Tag::Highway, Tag::MultiLane]);
    let ids: Vec<u64> = s.network.lanelets.iter().map(|l| l.id.get()).collect();
    assert_eq!(ids, vec![1, 2, 3]);
    let l1 = &s.network.lanelets[0];
    assert_eq!(l1.bounds.left(), &[p(0.0, 3.5), p(50.0, 3.5), p(100.0, 3.5)]);
    assert_eq!(l1.left_marking, Some(LineMarking::Dashed));
    assert_eq!(l1.right_marking, Some(LineMarking::Solid));
    assert_eq!(l1.successors.iter().map(|i| i.get()).collect::<Vec<_>>(), vec![3]);
    assert_eq!(l1.adjacent_left.map(|a| (a.lanelet.get(), a.driving_dir)), Some((2, DrivingDir::Same)));
    assert_eq!(l1.lanelet_types, vec![LaneletType::Highway, LaneletType::MainCarriageWay]);
    let l3 = &s.network.lanelets[2];
    let stop = l3.stop_line.as_ref().unwrap();
    assert_eq!(stop.points, Some([p(150.0, 3.5), p(150.0, 0.0)]));
    assert_eq!(stop.traffic_light_refs.iter().map(|i| i.get()).collect::<Vec<_>>(), vec![11]);
    let sign = &s.network.traffic_signs[0];
    assert_eq!((sign.id.get(), sign.elements[0].sign_id.as_str()), (10, "274"));
    assert_eq!(sign.elements[0].additional_values, vec!["33.33".to_string()]);
    let light = &s.network.traffic_lights[0];
    let durations: Vec<u64> = light.cycle.iter().map(|c| c.duration.get()).collect();
    assert_eq!(durations, vec![50, 10, 50, 10]);
    assert_eq!(light.cycle[1].color, TrafficLightColor::RedYellow);
    assert_eq!(light.active, Some(true));
    let st = &s.static_obstacles[0];
    assert_eq!((st.id.get(), st.obstacle_type, st.x, st.y), (20, StaticObstacleType::ParkedVehicle, 80.0, 1.75));
    let car = &s.dynamic_obstacles[0];
    assert_eq!(car.id.get(), 21);
    assert_eq!(car.shape, Shape::rectangle(4.5, 1.8).unwrap());
    assert_eq!(car.initial_state.velocity, 20.0);
    let xs: Vec<(u64, f64)> = car.trajectory.iter().map(|s| (s.time_step, s.x)).collect();
    assert_eq!(xs, vec![(1, 12.0), (2, 14.0), (3, 16.0)]);
    // yawRate is absent from the trajectory states: 0.0, as commonroad-io fills it
    assert!(car.trajectory.iter().all(|s| s.yaw_rate == 0.0));
    let pp = &r.problems.problems[0];
    assert_eq!(pp.id.get(), 100);
    assert_eq!((pp.initial_state.x, pp.initial_state.velocity, pp.initial_state.acceleration), (5.0, 15.0, Some(0.0)));
    assert_eq!(pp.goal_states.len(), 2);
    match &pp.goal_states[0].position {
        Some(GoalPosition::Rectangles(r)) => {
            assert_eq!((r[0].rectangle.length(), r[0].rectangle.width(), r[0].center), (10.0, 3.5, p(140.0, 1.75)))
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(pp.goal_states[0].time, TimeInterval::new(10, 80).unwrap());
    assert_eq!(pp.goal_states[1].position, Some(GoalPosition::Lanelets(vec![LaneletId::new(3).unwrap()])));
    assert!(s.validate(Some(&r.problems)).is_empty());
}

fn invalid_at(text: &str) -> (u32, u32, String) {
    match read_scenario_str(text, Path::new("bad.xml")) {
        Err(Error::Invalid { location, message }) => (location.line, location.col, message),
        other => panic!("expected Invalid, got {other:?}"),
    }
}

const HEAD: &str =
    "<commonRoad commonRoadVersion=\"2020a\" benchmarkID=\"ZAM_T-1\" date=\"2026-01-01\" author=\"a\" affiliation=\"b\" source=\"c\" timeStepSize=\"0.1\">\n";

#[test]
fn errors_name_line_column_and_expectation() {
    let text = format!(
        "{HEAD}<lanelet id=\"1\">\n  <leftBound><point><x>0</x><y>1</y></point><point><x>1</x><y>1</y></point></leftBound>\n  <rightBound><point><x>0</x><y>0</y></point></rightBound>\n</lanelet></commonRoad>"
    );
    let (line, col, msg) = invalid_at(&text);
    assert_eq!((line, col), (2, 1));
    assert!(msg.contains("same number of points"), "{msg}");

    let text = format!("{HEAD}<staticObstacle id=\"5\">\n <type>car</type></staticObstacle></commonRoad>");
    let (line, col, msg) = invalid_at(&text);
    assert_eq!((line, col), (3, 2));
    assert!(msg.contains("\"car\" is not one of") && msg.contains("parkedVehicle"), "{msg}");

    let text = format!("{HEAD}<trafficLight id=\"0\"/></commonRoad>");
    let (_, _, msg) = invalid_at(&text);
    assert!(msg.contains("positive integer"), "{msg}");

    let text = format!("{HEAD}<staticObstacle id=\"5\"><type>unknown</type><shape><circle><radius>NaN</radius></circle></shape></staticObstacle></commonRoad>");
    let (_, _, msg) = invalid_at(&text);
    assert!(msg.contains("finite decimal"), "{msg}");

    assert!(matches!(read_scenario_str("<a><b></a>", Path::new("x.xml")), Err(Error::Xml { .. })));
    let (_, _, msg) = invalid_at("<scenario/>");
    assert!(msg.contains("<commonRoad>"));
}

#[test]
fn missing_file_names_the_path() {
    let e = read_scenario_file(Path::new("/nonexistent/dir/x.xml")).unwrap_err();
    assert!(e.to_string().contains("/nonexistent/dir/x.xml"), "{e}");
}

#[test]
fn unsupported_parts_are_warnings() {
    let text = format!(
        "{HEAD}<location><geoNameId>1</geoNameId><gpsLatitude>0</gpsLatitude><gpsLongitude>0</gpsLongitude></location><scenarioTags><nonsense/></scenarioTags><phantomObstacle id=\"3\"/></commonRoad>"
    );
    let r = read_scenario_str(&text, Path::new("w.xml")).unwrap();
    assert_eq!(r.warnings.len(), 2, "{:?}", r.warnings);
    assert!(r.warnings[1].message.contains("phantomObstacle"));
    assert_eq!(r.scenario.location.geo_name_id, 1);
    // durations keep their NonZero type through the reader
    let _ = NonZeroU64::MIN;
}
