//! The scenario of `../shared/tools/examples/minimal_2020a.xml`, built with the model.
#![allow(dead_code)]

use std::num::NonZeroU64;

use commonroad::*;

pub(crate) struct Minimal {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
    pub lanelets: [LaneletId; 3],
    pub sign: TrafficSignId,
    pub light: TrafficLightId,
    pub car: ObstacleId,
}

fn pts(v: &[(f64, f64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::new(x, y)).collect()
}

pub(crate) fn header() -> Header {
    Header {
        benchmark_id: BenchmarkId::parse("DEU_Example-1_1_T-1").unwrap(),
        date: Date::new(2026, 1, 15).unwrap(),
        author: "osc2cr".into(),
        affiliation: "example".into(),
        source: "OpenSCENARIO conversion".into(),
        time_step_size: 0.1,
    }
}

pub(crate) fn state(t: u64, x: f64, y: f64, v: f64) -> State {
    State { time_step: t, x, y, orientation: 0.0, velocity: v, acceleration: 0.0, yaw_rate: 0.0 }
}

pub(crate) fn minimal() -> Minimal {
    let mut ids = IdAllocator::new();
    let (l1, l2, l3) = (ids.lanelet(), ids.lanelet(), ids.lanelet());
    let sign = ids.traffic_sign();
    let light = ids.traffic_light();

    let mut a = Lanelet::new(
        l1,
        LaneletBounds::new(pts(&[(0.0, 3.5), (50.0, 3.5), (100.0, 3.5)]), pts(&[(0.0, 0.0), (50.0, 0.0), (100.0, 0.0)])).unwrap(),
        LaneletType::Highway,
    );
    a.left_marking = Some(LineMarking::Dashed);
    a.right_marking = Some(LineMarking::Solid);
    a.successors.push(l3);
    a.adjacent_left = Some(Adjacent { lanelet: l2, driving_dir: DrivingDir::Same });
    a.lanelet_types.push(LaneletType::MainCarriageWay);
    a.user_one_way.push(RoadUser::Vehicle);
    a.traffic_sign_refs.push(sign);

    let mut b = Lanelet::new(l2, LaneletBounds::new(pts(&[(0.0, 7.0), (100.0, 7.0)]), pts(&[(0.0, 3.5), (100.0, 3.5)])).unwrap(), LaneletType::Highway);
    b.left_marking = Some(LineMarking::Solid);
    b.right_marking = Some(LineMarking::Dashed);
    b.adjacent_right = Some(Adjacent { lanelet: l1, driving_dir: DrivingDir::Same });
    b.user_one_way.push(RoadUser::Vehicle);

    let mut c = Lanelet::new(l3, LaneletBounds::new(pts(&[(100.0, 3.5), (150.0, 3.5)]), pts(&[(100.0, 0.0), (150.0, 0.0)])).unwrap(), LaneletType::Highway);
    c.predecessors.push(l1);
    c.stop_line = Some(StopLine {
        points: Some([Point::new(150.0, 3.5), Point::new(150.0, 0.0)]),
        line_marking: LineMarking::Solid,
        traffic_sign_refs: vec![],
        traffic_light_refs: vec![light],
    });
    c.traffic_light_refs.push(light);

    let mut scenario = Scenario::new(header());
    scenario.tags.insert(Tag::Highway);
    scenario.tags.insert(Tag::MultiLane);
    scenario.network.lanelets = vec![a, b, c];
    scenario.network.traffic_signs.push(TrafficSign {
        id: sign,
        elements: vec![TrafficSignElement { sign_id: "274".into(), additional_values: vec!["33.33".into()] }],
        position: Some(Point::new(5.0, -1.0)),
        is_virtual: false,
    });
    let phase = |d: u64, color| CycleElement { duration: NonZeroU64::new(d).unwrap(), color };
    scenario.network.traffic_lights.push(TrafficLight {
        id: light,
        cycle: vec![
            phase(50, TrafficLightColor::Red),
            phase(10, TrafficLightColor::RedYellow),
            phase(50, TrafficLightColor::Green),
            phase(10, TrafficLightColor::Yellow),
        ],
        time_offset: 0,
        position: Some(Point::new(150.0, -1.0)),
        direction: None,
        active: Some(true),
    });
    scenario.static_obstacles.push(StaticObstacle {
        id: ids.obstacle(),
        obstacle_type: StaticObstacleType::ParkedVehicle,
        shape: Shape::rectangle(4.5, 1.8).unwrap(),
        x: 80.0,
        y: 1.75,
        orientation: 0.0,
    });
    let car = ids.obstacle();
    scenario.dynamic_obstacles.push(DynamicObstacle {
        id: car,
        obstacle_type: DynamicObstacleType::Car,
        shape: Shape::rectangle(4.5, 1.8).unwrap(),
        initial_state: state(0, 10.0, 5.25, 20.0),
        trajectory: (1..=3).map(|t| state(t, 10.0 + 2.0 * t as f64, 5.25, 20.0)).collect(),
    });
    let problems = PlanningProblemSet {
        problems: vec![PlanningProblem {
            id: ids.planning_problem(),
            initial_state: PlanningInitialState { x: 5.0, y: 1.75, orientation: 0.0, velocity: 15.0, yaw_rate: 0.0, slip_angle: 0.0, acceleration: Some(0.0) },
            goal_states: vec![
                GoalState {
                    time: TimeInterval::new(10, 80).unwrap(),
                    position: Some(GoalPosition::Rectangles(vec![PlacedRectangle {
                        rectangle: Rectangle::new(10.0, 3.5).unwrap(),
                        center: Point::new(140.0, 1.75),
                        orientation: 0.0,
                    }])),
                    orientation: Some(Interval::new(-0.5, 0.5).unwrap()),
                    velocity: Some(Interval::new(0.0, 30.0).unwrap()),
                },
                GoalState { time: TimeInterval::new(10, 80).unwrap(), position: Some(GoalPosition::Lanelets(vec![l3])), orientation: None, velocity: None },
            ],
        }],
    };
    Minimal { scenario, problems, lanelets: [l1, l2, l3], sign, light, car }
}

/// An intersection's incoming: the lanelets entering it from `from`, its successors to the right,
/// straight on and to the left, and the incoming it is left of.
pub(crate) fn incoming(id: IncomingId, from: LaneletId, [right, straight, left]: [&[LaneletId]; 3], is_left_of: Option<IncomingId>) -> Incoming {
    Incoming {
        id,
        incoming_lanelets: vec![from],
        successors_right: right.to_vec(),
        successors_straight: straight.to_vec(),
        successors_left: left.to_vec(),
        is_left_of,
    }
}
