//! The trace → CommonRoad conversion on synthetic traces whose expected result is computed by
//! hand: bounding-box centres, shapes, element kinds, appear/vanish, resampling, ids, the ego
//! and its planning problem.

use std::collections::BTreeSet;
use std::f64::consts::{FRAC_PI_2, PI};

use crate::common::*;
use commonroad::{AbsoluteShape, Date, DynamicObstacleType, EnvironmentObstacleType, GoalPosition, Header, Shape, StaticObstacleType};
use convert::{assemble, benchmark_id, Assembled, ConvertOptions, EgoChoice};
use engine::Trace;
use openscenario::{Entity, MiscObjectCategory as M, PedestrianCategory, VehicleCategory};

fn header() -> Header {
    Header {
        benchmark_id: benchmark_id("ZAM", "synthetic", 1).expect("valid id"),
        date: Date::new(2026, 1, 15).expect("date"),
        author: "test".into(),
        affiliation: "".into(),
        source: "synthetic".into(),
        time_step_size: 0.1,
    }
}

fn run(trace: &Trace, entities: &[Entity], options: &ConvertOptions) -> Assembled {
    assemble(header(), None, &BTreeSet::new(), trace, entities, options).expect("assembles")
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn positions_are_box_centres_rotated_by_the_heading() {
    // heading north, box centre 1.4 m ahead and 0.3 m left of the reference point
    let e = vec![vehicle("Ego", VehicleCategory::Car, bbox(1.4, 0.3, 4.5, 2.0))];
    let t = trace(101, &["Ego"], |_, k| Some(sample(10.0, 5.0 + 0.1 * k as f64, FRAC_PI_2, 10.0)));
    let a = run(&t, &e, &ConvertOptions::default());
    let o = &a.scenario.dynamic_obstacles[0];
    assert_eq!(o.obstacle_type, DynamicObstacleType::Car);
    assert_eq!(o.shape, Shape::rectangle(4.5, 2.0).expect("shape"));
    // x: 10 − 0.3, y: 5 + 1.4 (+ 1 m per CommonRoad step)
    assert!(close(o.initial_state.x, 9.7) && close(o.initial_state.y, 6.4));
    for s in &o.trajectory {
        let n = s.time_step as f64;
        assert!(close(s.x, 9.7), "{s:?}");
        assert!(close(s.y, 6.4 + n), "{s:?}");
        assert!(close(s.orientation, FRAC_PI_2));
        assert!(close(s.velocity, 10.0));
    }
    assert_eq!(o.trajectory.len(), 10);
}

#[test]
fn resampled_every_tenth_sample_with_acceleration_and_yaw_rate() {
    let e = vec![car("Ego")];
    // x = t², speed = 2t, acceleration 2, yaw rate 0.1 and heading 0.1 t
    let t = trace(301, &["Ego"], |_, k| {
        let t = k as f64 * 0.01;
        let mut s = sample(t * t, 0.0, 0.1 * t, 2.0 * t);
        s.acceleration = 2.0;
        s.yaw_rate = 0.1;
        Some(s)
    });
    let a = run(&t, &e, &ConvertOptions::default());
    let o = &a.scenario.dynamic_obstacles[0];
    assert_eq!(o.trajectory.len(), 30);
    for s in std::iter::once(&o.initial_state).chain(&o.trajectory) {
        let t = s.time_step as f64 * 0.1;
        let h = 0.1 * t;
        assert!(close(s.x, t * t + 1.4 * h.cos()), "{s:?}");
        assert!(close(s.y, 1.4 * h.sin()), "{s:?}");
        assert!(close(s.velocity, 2.0 * t));
        assert!(close(s.acceleration, 2.0) && close(s.yaw_rate, 0.1));
    }
}

#[test]
fn other_time_steps_interpolate() {
    let e = vec![vehicle("Ego", VehicleCategory::Car, bbox(0.0, 0.0, 4.0, 2.0))];
    let t = trace(101, &["Ego"], |_, k| Some(straight(0.0, 0.0, 10.0)(k)));
    let options = ConvertOptions { dt: 0.025, ..ConvertOptions::default() };
    let a = run(&t, &e, &options);
    let o = &a.scenario.dynamic_obstacles[0];
    assert_eq!(o.trajectory.len(), 40);
    for s in &o.trajectory {
        assert!(close(s.x, 0.25 * s.time_step as f64), "{s:?}");
    }
}

#[test]
fn headings_are_wrapped() {
    let e = vec![car("Ego")];
    // heading increases through π: 3.0 .. 3.3 rad
    let t = trace(31, &["Ego"], |_, k| Some(sample(0.0, 0.0, 3.0 + 0.01 * k as f64, 0.0)));
    let a = run(&t, &e, &ConvertOptions::default());
    let o = &a.scenario.dynamic_obstacles[0];
    for s in std::iter::once(&o.initial_state).chain(&o.trajectory) {
        assert!(s.orientation > -PI && s.orientation <= PI, "{s:?}");
        let want = 3.0 + 0.1 * s.time_step as f64;
        let want = if want > PI { want - 2.0 * PI } else { want };
        assert!(close(s.orientation, want), "{s:?} want {want}");
    }
}

#[test]
fn pedestrians_are_circles_covering_their_box_and_standing_vehicles_stay_dynamic() {
    let e = vec![car("Ego"), pedestrian("Walker", PedestrianCategory::Pedestrian, bbox(0.0, 0.0, 0.6, 0.8)), car("Parked")];
    let t = trace(51, &["Ego", "Walker", "Parked"], |i, k| match i {
        0 => Some(straight(0.0, 0.0, 10.0)(k)),
        1 => Some(sample(20.0, 5.0, -FRAC_PI_2, 1.0)),
        _ => Some(sample(50.0, 0.0, 0.0, 0.0)),
    });
    let a = run(&t, &e, &ConvertOptions::default());
    assert_eq!(a.scenario.dynamic_obstacles.len(), 3);
    assert!(a.scenario.static_obstacles.is_empty());
    let walker = &a.scenario.dynamic_obstacles[1];
    assert_eq!(walker.obstacle_type, DynamicObstacleType::Pedestrian);
    // radius = half the diagonal of 0.6 × 0.8 = 0.5
    assert_eq!(walker.shape, Shape::circle(0.5).expect("circle"));
    let parked = &a.scenario.dynamic_obstacles[2];
    assert_eq!(parked.obstacle_type, DynamicObstacleType::Car);
    assert_eq!(parked.trajectory.len(), 5);
}

#[test]
fn fixed_misc_objects_are_static_or_environment_obstacles_moving_ones_dynamic() {
    let e = vec![
        car("Ego"),
        misc("Pole", M::Pole, bbox(0.0, 0.0, 0.3, 0.3)),
        misc("House", M::Building, bbox(1.0, 0.0, 10.0, 8.0)),
        misc("Works", M::Patch, bbox(0.0, 0.0, 5.0, 3.0)),
        misc("Box", M::Obstacle, bbox(0.0, 0.0, 1.0, 1.0)),
        misc("Lamp", M::StreetLamp, bbox(0.0, 0.0, 0.2, 0.2)),
        misc("Island", M::TrafficIsland, bbox(0.0, 0.0, 6.0, 2.0)),
        misc("FlyingHouse", M::Building, bbox(0.0, 0.0, 10.0, 8.0)),
    ];
    let t = trace(21, &["Ego", "Pole", "House", "Works", "Box", "Lamp", "Island", "FlyingHouse"], |i, k| {
        Some(match i {
            0 => straight(0.0, 0.0, 10.0)(k),
            2 => sample(100.0, 20.0, FRAC_PI_2, 0.0),
            7 => sample(k as f64, 30.0, 0.0, 1.0),
            _ => sample(10.0 * i as f64, -5.0, 0.0, 0.0),
        })
    });
    let a = run(&t, &e, &ConvertOptions::default());
    let s = &a.scenario;
    let statics: Vec<StaticObstacleType> = s.static_obstacles.iter().map(|o| o.obstacle_type).collect();
    assert_eq!(statics, [StaticObstacleType::RoadBoundary, StaticObstacleType::ConstructionZone, StaticObstacleType::Unknown]);
    let env: Vec<EnvironmentObstacleType> = s.environment_obstacles.iter().map(|o| o.obstacle_type).collect();
    assert_eq!(env, [EnvironmentObstacleType::Building, EnvironmentObstacleType::Pillar, EnvironmentObstacleType::MedianStrip]);
    // the house: centre 1 m ahead of its reference point, heading north
    let AbsoluteShape::Rectangle(r) = &s.environment_obstacles[0].shape else { panic!("rectangle expected") };
    assert!(close(r.center.x, 100.0) && close(r.center.y, 21.0));
    assert!(close(r.orientation, FRAC_PI_2));
    assert!(close(r.rectangle.length(), 10.0) && close(r.rectangle.width(), 8.0));
    // the moving building is a dynamic obstacle of type unknown, with a warning
    assert_eq!(s.dynamic_obstacles.len(), 2);
    assert_eq!(s.dynamic_obstacles[1].obstacle_type, DynamicObstacleType::Unknown);
    assert!(a.warnings.iter().any(|w| w.contains("FlyingHouse")), "{:?}", a.warnings);
    assert_eq!(a.obstacles, 8);
}

#[test]
fn entities_that_appear_and_vanish_start_and_end_there() {
    let e = vec![car("Ego"), car("Late"), car("Blink"), car("Once")];
    let t = trace(1001, &["Ego", "Late", "Blink", "Once"], |i, k| {
        let s = straight(0.0, 3.5 * i as f64, 10.0)(k);
        match i {
            0 => Some(s),
            // exists from 2.5 s to before 5.0 s
            1 => (250..500).contains(&k).then_some(s),
            // exists 0–1 s and again 3–4 s
            2 => ((0..=100).contains(&k) || (300..=400).contains(&k)).then_some(s),
            // exists at 7.0 s only
            _ => (k == 700).then_some(s),
        }
    });
    let a = run(&t, &e, &ConvertOptions::default());
    let d = &a.scenario.dynamic_obstacles;
    assert_eq!(d.len(), 5, "Blink is two obstacles");
    let late = &d[1];
    assert_eq!(late.initial_state.time_step, 25);
    assert_eq!(late.trajectory.first().map(|s| s.time_step), Some(26));
    assert_eq!(late.trajectory.last().map(|s| s.time_step), Some(49));
    assert!(close(late.initial_state.x, 25.0 + 1.4));
    let (b1, b2) = (&d[2], &d[3]);
    assert_eq!((b1.initial_state.time_step, b1.trajectory.last().map(|s| s.time_step)), (0, Some(10)));
    assert_eq!((b2.initial_state.time_step, b2.trajectory.last().map(|s| s.time_step)), (30, Some(40)));
    // one time step: padded with a copy one step later
    let once = &d[4];
    assert_eq!(once.initial_state.time_step, 70);
    assert_eq!(once.trajectory.len(), 1);
    assert_eq!(once.trajectory[0].time_step, 71);
    assert!(close(once.trajectory[0].x, once.initial_state.x));
    for o in d {
        for (i, s) in o.trajectory.iter().enumerate() {
            assert_eq!(s.time_step, o.initial_state.time_step + 1 + i as u64);
        }
    }
}

#[test]
fn ids_are_unique_and_the_planning_problem_has_its_own() {
    let e = vec![car("Ego"), car("Other"), misc("Pole", M::Pole, bbox(0.0, 0.0, 0.3, 0.3))];
    let t = trace(101, &["Ego", "Other", "Pole"], |i, k| Some(if i == 2 { sample(5.0, 5.0, 0.0, 0.0) } else { straight(0.0, 3.5 * i as f64, 10.0)(k) }));
    let a = run(&t, &e, &ConvertOptions::default());
    let mut ids: Vec<u64> = a.scenario.network.lanelets.iter().map(|l| l.id.get()).collect();
    ids.extend(a.scenario.dynamic_obstacles.iter().map(|o| o.id.get()));
    ids.extend(a.scenario.static_obstacles.iter().map(|o| o.id.get()));
    ids.extend(a.problems.problems.iter().map(|p| p.id.get()));
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "ids repeat");
    let ego_id = a.scenario.dynamic_obstacles[0].id.get();
    assert_ne!(a.problems.problems[0].id.get(), ego_id);
}

#[test]
fn goal_region_defaults_around_the_last_state() {
    let e = vec![car("Ego")];
    // 12 m/s along a 30° heading for 8 s
    let h = 30f64.to_radians();
    let t = trace(801, &["Ego"], |_, k| {
        let d = 12.0 * k as f64 * 0.01;
        Some(sample(d * h.cos(), d * h.sin(), h, 12.0))
    });
    let a = run(&t, &e, &ConvertOptions::default());
    let p = &a.problems.problems[0];
    let ego = &a.scenario.dynamic_obstacles[0];
    // initial state = the ego's first state (box centre)
    assert!(close(p.initial_state.x, 1.4 * h.cos()) && close(p.initial_state.y, 1.4 * h.sin()));
    assert!(close(p.initial_state.velocity, 12.0) && close(p.initial_state.orientation, h));
    let g = &p.goal_states[0];
    assert_eq!((g.time.start(), g.time.end()), (70, 80));
    let v = g.velocity.expect("velocity interval");
    assert!(close(v.start(), 7.0) && close(v.end(), 17.0));
    assert!(g.orientation.is_none());
    let Some(GoalPosition::Rectangles(r)) = &g.position else { panic!("rectangle goal") };
    let last = ego.trajectory.last().expect("states");
    let d = 96.0 + 1.4;
    assert!(close(r[0].center.x, d * h.cos()) && close(r[0].center.y, d * h.sin()));
    assert!(close(r[0].center.x, last.x));
    assert!(close(r[0].orientation, h));
    assert!(close(r[0].rectangle.length(), 50.0) && close(r[0].rectangle.width(), 10.0));
}

#[test]
fn goal_velocity_is_clamped_at_zero_and_options_apply() {
    let e = vec![car("Ego")];
    let t = trace(51, &["Ego"], |_, k| Some(sample(0.1 * k as f64, 0.0, 0.0, 2.0)));
    let mut options = ConvertOptions::default();
    options.goal.length = 20.0;
    options.goal.width = 4.0;
    options.goal.time_window = 100; // longer than the run: starts at 0
    options.goal.orientation_margin = Some(0.2);
    let a = run(&t, &e, &options);
    let g = &a.problems.problems[0].goal_states[0];
    assert_eq!((g.time.start(), g.time.end()), (0, 5));
    let v = g.velocity.expect("velocity");
    assert!(close(v.start(), 0.0) && close(v.end(), 7.0));
    let o = g.orientation.expect("orientation");
    assert!(close(o.start(), -0.2) && close(o.end(), 0.2));
    let Some(GoalPosition::Rectangles(r)) = &g.position else { panic!("rectangle goal") };
    assert!(close(r[0].rectangle.length(), 20.0) && close(r[0].rectangle.width(), 4.0));
}

#[test]
fn ego_choice_and_drop_ego() {
    let e = vec![car("Car1"), car("ego_b"), car("Ego_a")];
    let t = trace(21, &["Car1", "ego_b", "Ego_a"], |i, k| Some(straight(0.0, 3.5 * i as f64, 5.0)(k)));
    let a = run(&t, &e, &ConvertOptions::default());
    assert_eq!(a.ego, "Ego_a", "first by name among the matches");
    let named = ConvertOptions { ego: EgoChoice::Name("Car1".into()), ..Default::default() };
    assert_eq!(run(&t, &e, &named).ego, "Car1");
    let none = ConvertOptions { ego: EgoChoice::Name("Nobody".into()), ..Default::default() };
    let err = assemble(header(), None, &BTreeSet::new(), &t, &e, &none).expect_err("no such ego");
    assert!(err.contains("Nobody") && err.contains("Car1"), "{err}");
    // no name matches: the first moving entity
    let e2 = vec![car("A"), car("B")];
    let t2 = trace(21, &["B", "A"], |i, k| Some(straight(0.0, 3.5 * i as f64, 5.0)(k)));
    assert_eq!(run(&t2, &e2, &ConvertOptions::default()).ego, "B");
    // --drop-ego: the ego is no obstacle, the planning problem stays
    let dropped = ConvertOptions { drop_ego: true, ..Default::default() };
    let a = run(&t, &e, &dropped);
    assert_eq!(a.scenario.dynamic_obstacles.len(), 2);
    assert_eq!(a.problems.problems.len(), 1);
    assert!(close(a.problems.problems[0].initial_state.y, 7.0));
}

#[test]
fn without_road_network_a_placeholder_lanelet_lies_under_the_ego() {
    let e = vec![car("Ego")];
    let t = trace(21, &["Ego"], |_, k| Some(straight(3.0, 4.0, 5.0)(k)));
    let a = run(&t, &e, &ConvertOptions::default());
    assert_eq!(a.lanelets, 0);
    let l = &a.scenario.network.lanelets[0];
    assert_eq!(l.lanelet_types, [commonroad::LaneletType::Unknown]);
    // box 4.5 × 2 centred on (4.4, 4)
    assert!(close(l.bounds.left()[0].x, 4.4 - 2.25) && close(l.bounds.left()[0].y, 5.0));
    assert!(close(l.bounds.right()[1].x, 4.4 + 2.25) && close(l.bounds.right()[1].y, 3.0));
    assert!(a.warnings.iter().any(|w| w.contains("placeholder")));
    assert!(a.scenario.tags.contains(&commonroad::Tag::Simulated));
}

#[test]
fn a_scenario_of_fixed_objects_starts_its_planning_problem_at_one_at_rest() {
    let e = vec![misc("Pole", M::Pole, bbox(0.0, 0.0, 0.3, 0.3)), misc("Wall", M::Barrier, bbox(0.0, 0.0, 0.3, 0.3))];
    let t = trace(21, &["Wall", "Pole"], |i, _| Some(sample(10.0 * i as f64, 2.0, 0.0, 0.0)));
    let a = run(&t, &e, &ConvertOptions::default());
    // no name matches "ego" and nothing moves: the first entity of the trace
    assert_eq!(a.ego, "Wall");
    let p = &a.problems.problems[0];
    assert!(close(p.initial_state.x, 0.0) && close(p.initial_state.y, 2.0) && close(p.initial_state.velocity, 0.0));
    assert!(a.warnings.iter().any(|w| w.contains("no entity of the scenario moves") && w.contains("Wall")), "{:?}", a.warnings);
    // the fixed objects stay static obstacles
    assert_eq!(a.scenario.static_obstacles.len(), 2);
    assert!(a.scenario.dynamic_obstacles.is_empty());
}

#[test]
fn a_scenario_without_entities_fails_clearly() {
    let t = trace(21, &[], |_, _| None);
    let err = assemble(header(), None, &BTreeSet::new(), &t, &[], &ConvertOptions::default()).expect_err("no ego");
    assert!(err.contains("no entity"), "{err}");
}
