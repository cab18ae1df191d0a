//! Small CommonRoad scenarios built in code for the feature tests: a straight two-lanelet road
//! with a light, obstacles of several kinds that appear and leave at chosen steps, and a
//! planning problem with a goal of each kind.

use std::num::NonZeroU64;

use commonroad::*;

pub(crate) struct Built {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
}

fn state(t: u64, x: f64, y: f64, v: f64) -> State {
    State { time_step: t, x, y, orientation: 0.0, velocity: v, acceleration: 0.0, yaw_rate: 0.0 }
}

/// States of a road user going east at `v` from `x0` at steps `from..=to`.
pub(crate) fn going_east(from: u64, to: u64, x0: f64, y: f64, v: f64) -> (State, Vec<State>) {
    let at = |t: u64| state(t, x0 + v * 0.1 * (t - from) as f64, y, v);
    (at(from), (from + 1..=to).map(at).collect())
}

/// The scenario: a 300 m road of two lanelets side by side (y 0..3.5 and 3.5..7), a light with
/// an offset, a car from step 0 to the end (step 100), a truck from step 1 to 60, a pedestrian
/// (circle) from step 5 to 40, a static parked vehicle and a construction zone (polygon), a
/// building; one planning problem whose goal is `goal`.
pub(crate) fn scenario(goal: GoalPosition) -> Built {
    let header = Header {
        benchmark_id: BenchmarkId::parse("DEU_Synthetic-1_1_T-1").expect("id"),
        date: Date::new(2026, 3, 1).expect("date"),
        author: "tests".into(),
        affiliation: "".into(),
        source: "export tests".into(),
        time_step_size: 0.1,
    };
    let mut s = Scenario::new(header);
    let mut ids = IdAllocator::new();
    let line = |y: f64| vec![Point::new(0.0, y), Point::new(150.0, y), Point::new(300.0, y)];
    let right = ids.lanelet();
    let left = ids.lanelet();
    let mut a = Lanelet::new(right, LaneletBounds::new(line(3.5), line(0.0)).expect("bounds"), LaneletType::Urban);
    let mut b = Lanelet::new(left, LaneletBounds::new(line(7.0), line(3.5)).expect("bounds"), LaneletType::Urban);
    a.adjacent_left = Some(Adjacent { lanelet: left, driving_dir: DrivingDir::Same });
    b.adjacent_right = Some(Adjacent { lanelet: right, driving_dir: DrivingDir::Same });
    let light = ids.traffic_light();
    a.traffic_light_refs.push(light);
    s.network.lanelets = vec![a, b];
    let d = |n: u64| NonZeroU64::new(n).expect("positive");
    s.network.traffic_lights.push(TrafficLight {
        id: light,
        cycle: vec![
            CycleElement { duration: d(30), color: TrafficLightColor::Red },
            CycleElement { duration: d(5), color: TrafficLightColor::RedYellow },
            CycleElement { duration: d(40), color: TrafficLightColor::Green },
            CycleElement { duration: d(5), color: TrafficLightColor::Yellow },
        ],
        time_offset: 12,
        position: Some(Point::new(290.0, -1.0)),
        direction: None,
        active: None,
    });
    let mut dynamic = |t: DynamicObstacleType, shape: Shape, (init, traj): (State, Vec<State>)| {
        s.dynamic_obstacles.push(DynamicObstacle { id: ids.obstacle(), obstacle_type: t, shape, initial_state: init, trajectory: traj });
    };
    dynamic(DynamicObstacleType::Car, Shape::rectangle(4.5, 1.8).expect("box"), going_east(0, 100, 20.0, 1.75, 12.0));
    dynamic(DynamicObstacleType::Truck, Shape::rectangle(9.0, 2.5).expect("box"), going_east(1, 60, 5.0, 5.25, 8.0));
    dynamic(DynamicObstacleType::Pedestrian, Shape::circle(0.4).expect("circle"), going_east(5, 40, 100.0, 8.0, 1.2));
    s.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::ParkedVehicle,
        shape: Shape::rectangle(4.0, 1.8).expect("box"),
        x: 200.0,
        y: -2.0,
        orientation: 0.0,
    });
    let zone = Polygon::new(vec![Point::new(0.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 2.0), Point::new(0.0, 2.0)]).expect("polygon");
    s.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::ConstructionZone,
        shape: Shape::Polygon(zone),
        x: 240.0,
        y: -4.0,
        orientation: 0.0,
    });
    s.environment_obstacles.push(EnvironmentObstacle {
        id: ids.obstacle(),
        obstacle_type: EnvironmentObstacleType::Building,
        shape: AbsoluteShape::Rectangle(PlacedRectangle {
            rectangle: Rectangle::new(20.0, 10.0).expect("box"),
            center: Point::new(150.0, 30.0),
            orientation: 0.3,
        }),
    });
    let problem = PlanningProblem {
        id: ids.planning_problem(),
        initial_state: PlanningInitialState { x: 10.0, y: 1.75, orientation: 0.0, velocity: 10.0, yaw_rate: 0.0, slip_angle: 0.0, acceleration: Some(0.0) },
        goal_states: vec![GoalState {
            time: TimeInterval::new(20, 90).expect("time"),
            position: Some(goal),
            orientation: Some(Interval::new(-0.5, 0.5).expect("interval")),
            velocity: Some(Interval::new(5.0, 15.0).expect("interval")),
        }],
    };
    Built { scenario: s, problems: PlanningProblemSet { problems: vec![problem] } }
}

/// A goal circle around (x, y).
pub(crate) fn circle(x: f64, y: f64, r: f64) -> GoalPosition {
    GoalPosition::Circles(vec![PlacedCircle { circle: Circle::new(r).expect("radius"), center: Point::new(x, y) }])
}

/// The scenario as a source (no reader warnings).
pub(crate) fn source(b: Built) -> export::Source {
    export::Source { scenario: b.scenario, problems: b.problems, warnings: Vec::new() }
}
