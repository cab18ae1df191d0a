//! The XML reader reads what `osc2cr export` meets in `../shared/commonroad-scenarios`: 2018b
//! files (`<obstacle>` with a role), uncertain states (intervals, position shapes) as their
//! midpoints and centres, point-mass states without orientation (heading from the velocity
//! components) — each with a warning — and a planning problem carried as XML.

use std::path::Path;

use commonroad::*;

use crate::common;

const OBSTACLE_2018B: &str = r#"<?xml version="1.0"?>
<commonRoad commonRoadVersion="2018b" benchmarkID="DEU_Test-1_1_T-1" date="2018-01-01" author="" affiliation="" source="" timeStepSize="0.1">
  <lanelet id="1">
    <leftBound><point><x>0</x><y>3</y></point><point><x>50</x><y>3</y></point></leftBound>
    <rightBound><point><x>0</x><y>0</y></point><point><x>50</x><y>0</y></point></rightBound>
  </lanelet>
  <obstacle id="5">
    <role>dynamic</role><type>car</type>
    <shape><rectangle><length>4</length><width>2</width></rectangle></shape>
    <initialState>
      <position><rectangle><length>0.5</length><width>0.2</width><orientation>0</orientation><center><x>10</x><y>1.5</y></center></rectangle></position>
      <orientation><intervalStart>-0.1</intervalStart><intervalEnd>0.3</intervalEnd></orientation>
      <time><exact>0</exact></time>
      <velocity><intervalStart>9</intervalStart><intervalEnd>11</intervalEnd></velocity>
    </initialState>
    <trajectory>
      <state><position><point><x>11</x><y>1.5</y></point></position><time><exact>1</exact></time><velocity><exact>3</exact></velocity><velocityY><exact>4</exact></velocityY></state>
    </trajectory>
  </obstacle>
  <obstacle id="6">
    <role>static</role><type>parkedVehicle</type>
    <shape><rectangle><length>4</length><width>2</width></rectangle></shape>
    <initialState><position><point><x>30</x><y>1.5</y></point></position><orientation><exact>0.2</exact></orientation><time><exact>0</exact></time></initialState>
  </obstacle>
</commonRoad>"#;

#[test]
fn a_2018b_file_reads_with_its_obstacles() {
    let r = xml::read_scenario_str(OBSTACLE_2018B, Path::new("t.xml")).expect("reads");
    let d = &r.scenario.dynamic_obstacles;
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].obstacle_type, DynamicObstacleType::Car);
    let s0 = d[0].initial_state;
    assert_eq!((s0.x, s0.y, s0.velocity), (10.0, 1.5, 10.0), "the centre and the midpoint");
    assert!((s0.orientation - 0.1).abs() < 1e-12);
    // point-mass state: heading and speed from (velocity, velocityY) = (3, 4)
    let s1 = d[0].trajectory[0];
    assert!((s1.orientation - 4f64.atan2(3.0)).abs() < 1e-12 && (s1.velocity - 5.0).abs() < 1e-12, "{s1:?}");
    let st = &r.scenario.static_obstacles;
    assert_eq!((st.len(), st[0].obstacle_type, st[0].x, st[0].orientation), (1, StaticObstacleType::ParkedVehicle, 30.0, 0.2));
    assert!(r.warnings.iter().any(|w| w.message.contains("obstacle 5") && w.message.contains("midpoints")), "{:?}", r.warnings);
    assert!(r.warnings.iter().any(|w| w.message.contains("2018b")), "the version is named: {:?}", r.warnings);
}

#[test]
fn the_shared_2018b_files_read_with_their_obstacles() {
    let Some(shared) = testkit::shared_dir() else { return };
    let a9 = xml::read_scenario_file(&shared.join("commonroad-scenarios/tests/test_scenarios/DEU_A9-3_1_T-1.xml")).expect("DEU_A9 reads");
    assert_eq!(a9.scenario.dynamic_obstacles.len(), 9, "its 9 <obstacle role=dynamic>");
    let lanker = xml::read_scenario_file(&shared.join("commonroad-scenarios/tutorials/USA_Lanker-1_1_T-1.xml")).expect("Lanker reads");
    assert_eq!(lanker.scenario.dynamic_obstacles.len(), 24);
    let pm = xml::read_scenario_file(&shared.join("commonroad-scenarios/tests/test_scenarios/test_reading_pm_state.xml")).expect("point-mass states read");
    assert_eq!(pm.scenario.dynamic_obstacles.len(), 1);
}

#[test]
fn a_planning_problem_travels_as_xml_with_its_goal_lanelets() {
    let m = common_minimal();
    let p = &m.1.problems[0];
    let lanelets: Vec<&Lanelet> = m.0.network.lanelets.iter().take(1).collect();
    let text = xml::write_planning_problem(p, &lanelets).expect("writes");
    assert!(!text.contains('\n') && text.starts_with("<commonRoadPlanningProblem>"), "one line: {text}");
    let back = xml::read_planning_problem_str(&text, Path::new("carrier")).expect("reads");
    assert_eq!(&back.problem, p, "values written to 6 decimals come back (the example's have fewer)");
    assert_eq!(back.lanelets, vec![m.0.network.lanelets[0].clone()]);
    let e = xml::read_planning_problem_str("<commonRoad/>", Path::new("carrier")).expect_err("other root");
    assert!(e.to_string().contains("commonRoadPlanningProblem"));
}

fn common_minimal() -> (Scenario, PlanningProblemSet) {
    let m = common::minimal();
    (m.scenario, m.problems)
}
