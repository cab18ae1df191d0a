//! `Scenario::validate` finds each kind of inconsistency, and nothing in a consistent file.

use crate::common;

use commonroad::*;

fn kinds(s: &Scenario, p: Option<&PlanningProblemSet>) -> Vec<ProblemKind> {
    s.validate(p).into_iter().map(|p| p.kind).collect()
}

/// The one problem `validate` finds, of kind `kind`.
fn only_problem(s: &Scenario, p: Option<&PlanningProblemSet>, kind: ProblemKind) -> Problem {
    let mut problems = s.validate(p);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(problems[0].kind, kind, "{problems:?}");
    problems.remove(0)
}

fn id<T>(f: fn(u64) -> Option<T>, v: u64) -> T {
    f(v).unwrap()
}

#[test]
fn the_minimal_example_is_consistent() {
    let m = common::minimal();
    assert_eq!(m.scenario.validate(Some(&m.problems)), vec![]);
    assert_eq!(m.scenario.validate(None), vec![]);
}

#[test]
fn duplicate_ids_across_kinds() {
    let mut m = common::minimal();
    m.scenario.dynamic_obstacles[0].id = id(ObstacleId::new, m.lanelets[1].get());
    let problem = only_problem(&m.scenario, Some(&m.problems), ProblemKind::DuplicateId);
    assert_eq!(problem.element, ElementKind::DynamicObstacle);
    assert_eq!(problem.id, Some(2));
    // the planning problem shares the id space too
    let mut m = common::minimal();
    m.problems.problems[0].id = id(PlanningProblemId::new, m.sign.get());
    assert_eq!(kinds(&m.scenario, Some(&m.problems)), vec![ProblemKind::DuplicateId]);
}

#[test]
fn dangling_and_wrong_kind_references() {
    let mut m = common::minimal();
    m.scenario.network.lanelets[0].successors.push(id(LaneletId::new, 999));
    assert_eq!(kinds(&m.scenario, Some(&m.problems)), vec![ProblemKind::DanglingRef]);

    let mut m = common::minimal();
    // a "lanelet" reference that names the traffic sign
    let sign_as_lanelet = id(LaneletId::new, m.sign.get());
    m.problems.problems[0].goal_states[1].position = Some(GoalPosition::Lanelets(vec![sign_as_lanelet]));
    let problem = only_problem(&m.scenario, Some(&m.problems), ProblemKind::DanglingRef);
    assert!(problem.message.contains("trafficSign"), "{}", problem);

    let mut m = common::minimal();
    m.scenario.network.lanelets[2].traffic_light_refs.push(id(TrafficLightId::new, 4242));
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::DanglingRef]);
}

#[test]
fn traffic_sign_not_referenced_by_a_lanelet() {
    let mut m = common::minimal();
    m.scenario.network.lanelets[0].traffic_sign_refs.clear();
    let problem = only_problem(&m.scenario, None, ProblemKind::UnreferencedTrafficSign);
    assert_eq!(problem.id, Some(m.sign.get()));
}

#[test]
fn light_without_position_must_be_referenced() {
    let mut m = common::minimal();
    m.scenario.network.traffic_lights[0].position = None;
    assert_eq!(kinds(&m.scenario, None), vec![]); // lanelet 3 references it
    m.scenario.network.lanelets[2].traffic_light_refs.clear();
    m.scenario.network.lanelets[2].stop_line = None;
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::UnreferencedTrafficLight]);
}

#[test]
fn sign_ids_outside_the_xsd_enumeration() {
    let mut m = common::minimal();
    m.scenario.network.traffic_signs[0].elements.push(TrafficSignElement::new("C31a"));
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::UnknownTrafficSignId]);
    assert!(is_xsd_traffic_sign_id("274") && is_xsd_traffic_sign_id("R2-1") && is_xsd_traffic_sign_id("r301"));
}

#[test]
fn trajectories_must_be_consecutive_from_t0_plus_one() {
    let base = common::minimal();
    let t = |steps: &[u64], t0: u64| {
        let mut m = common::minimal();
        let o = &mut m.scenario.dynamic_obstacles[0];
        o.initial_state.time_step = t0;
        o.trajectory = steps.iter().map(|&s| common::state(s, 10.0, 5.25, 20.0)).collect();
        kinds(&m.scenario, Some(&base.problems))
    };
    assert_eq!(t(&[1, 2, 3], 0), vec![]);
    assert_eq!(t(&[6, 7], 5), vec![]);
    assert_eq!(t(&[2, 3], 0), vec![ProblemKind::TrajectoryNotConsecutive]); // starts at t0+2
    assert_eq!(t(&[1, 3], 0), vec![ProblemKind::TrajectoryNotConsecutive]); // gap
    assert_eq!(t(&[1, 2, 2], 0), vec![ProblemKind::TrajectoryNotConsecutive]); // repeat
    assert_eq!(t(&[5, 6], 5), vec![ProblemKind::TrajectoryNotConsecutive]); // starts at t0
    assert_eq!(t(&[], 0), vec![ProblemKind::EmptyTrajectory]);
}

#[test]
fn lists_the_xsd_requires_to_be_non_empty() {
    let mut m = common::minimal();
    m.scenario.network.lanelets[1].lanelet_types.clear();
    m.scenario.network.traffic_lights[0].cycle.clear();
    m.scenario.network.traffic_signs[0].elements.clear();
    m.problems.problems[0].goal_states.clear();
    let problems = m.scenario.validate(Some(&m.problems));
    let elements: Vec<ElementKind> = problems.iter().map(|p| p.element).collect();
    assert!(problems.iter().all(|p| p.kind == ProblemKind::EmptyList), "{problems:?}");
    assert_eq!(elements, vec![ElementKind::Lanelet, ElementKind::TrafficSign, ElementKind::TrafficLight, ElementKind::PlanningProblem]);

    let mut m = common::minimal();
    m.scenario.network.lanelets.clear();
    m.scenario.network.traffic_signs.clear();
    m.scenario.network.traffic_lights.clear();
    m.problems.problems[0].goal_states.pop();
    assert_eq!(kinds(&m.scenario, Some(&m.problems)), vec![ProblemKind::EmptyList]);

    let mut m = common::minimal();
    let mut ids = m.scenario.id_allocator(Some(&m.problems));
    m.scenario.network.intersections.push(Intersection { id: ids.intersection(), incomings: vec![], crossings: vec![vec![]] });
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::EmptyList, ProblemKind::EmptyList]);
}

#[test]
fn non_finite_values() {
    let mut m = common::minimal();
    m.scenario.dynamic_obstacles[0].trajectory[1].velocity = f64::NAN;
    m.problems.problems[0].initial_state.yaw_rate = f64::INFINITY;
    m.scenario.network.traffic_signs[0].position = Some(Point::new(f64::NAN, 0.0));
    let problems = m.scenario.validate(Some(&m.problems));
    assert_eq!(problems.len(), 3, "{problems:?}");
    assert!(problems.iter().all(|p| p.kind == ProblemKind::NonFinite));
}

#[test]
fn values_that_must_be_positive() {
    let mut m = common::minimal();
    m.scenario.header.time_step_size = 0.0;
    // positive, but written as 0.0 at six decimals
    m.scenario.static_obstacles[0].shape = Shape::rectangle(4.5, 1e-9).unwrap();
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::NotPositive, ProblemKind::NotPositive]);
}

#[test]
fn scenario_files_need_a_planning_problem_map_files_do_not() {
    let m = common::minimal();
    let empty = PlanningProblemSet::default();
    assert_eq!(kinds(&m.scenario, Some(&empty)), vec![ProblemKind::NoPlanningProblem]);
    assert_eq!(kinds(&m.scenario, None), vec![]);
}

#[test]
fn successor_without_matching_predecessor() {
    let mut m = common::minimal();
    m.scenario.network.lanelets[2].predecessors.clear();
    let problem = only_problem(&m.scenario, None, ProblemKind::AsymmetricSuccessor);
    assert_eq!(problem.id, Some(m.lanelets[0].get()));
}

#[test]
fn adjacency_must_be_mirrored() {
    // same direction: 1.left = 2 needs 2.right = 1
    let mut m = common::minimal();
    m.scenario.network.lanelets[1].adjacent_right = None;
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::AsymmetricAdjacency]);
    // mirrored but with a different driving direction on one side
    let mut m = common::minimal();
    m.scenario.network.lanelets[1].adjacent_right = Some(Adjacent { lanelet: m.lanelets[0], driving_dir: DrivingDir::Opposite });
    let k = kinds(&m.scenario, None);
    assert!(!k.is_empty() && k.iter().all(|k| *k == ProblemKind::AsymmetricAdjacency), "{k:?}");
}

#[test]
fn opposite_adjacency_is_mirrored_on_the_left() {
    // lanelet 2 reversed: its left bound is lanelet 1's left bound backwards
    let mut m = common::minimal();
    let [l1, l2, _] = m.lanelets;
    let b = &mut m.scenario.network.lanelets[1];
    b.bounds = LaneletBounds::new(vec![Point::new(100.0, 3.5), Point::new(0.0, 3.5)], vec![Point::new(100.0, 7.0), Point::new(0.0, 7.0)]).unwrap();
    b.adjacent_right = None;
    b.adjacent_left = Some(Adjacent { lanelet: l1, driving_dir: DrivingDir::Opposite });
    m.scenario.network.lanelets[0].adjacent_left = Some(Adjacent { lanelet: l2, driving_dir: DrivingDir::Opposite });
    assert_eq!(kinds(&m.scenario, None), vec![]);
    // the same-direction mirror is wrong for an opposite neighbour
    let b = &mut m.scenario.network.lanelets[1];
    b.adjacent_left = None;
    b.adjacent_right = Some(Adjacent { lanelet: l1, driving_dir: DrivingDir::Opposite });
    let k = kinds(&m.scenario, None);
    assert!(k.contains(&ProblemKind::AsymmetricAdjacency), "{k:?}");
}

#[test]
fn swapped_bounds_are_found() {
    let mut m = common::minimal();
    let l = &mut m.scenario.network.lanelets[1];
    l.bounds = LaneletBounds::new(l.bounds.right().to_vec(), l.bounds.left().to_vec()).unwrap();
    assert_eq!(kinds(&m.scenario, None), vec![ProblemKind::LeftBoundOnRight]);
}

#[test]
fn problems_display_element_and_id() {
    let mut m = common::minimal();
    m.scenario.network.traffic_lights[0].cycle = vec![];
    let p = &m.scenario.validate(None)[0];
    assert_eq!(p.to_string(), format!("trafficLight {}: cycle must not be empty", m.light));
}
