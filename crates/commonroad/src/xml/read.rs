//! The CommonRoad 2020a XML reader: the inverse of [`super::write_scenario`], for tools that
//! look at a file (e.g. `osc2cr render`). It is lenient where commonroad-io is lenient
//! (missing optional state fields become 0.0, unknown elements are skipped with a warning)
//! and strict where the model is (equal bound point counts, per-element obstacle types).
//! Every error and warning names the file, line and column.

mod cursor;
mod header;
mod network;
mod obstacles;
mod planning;

use std::path::Path;

use diagnostic::Diagnostic;

use crate::planning::PlanningProblemSet;
use crate::scenario::Scenario;
use crate::Error;

/// Largest file the reader loads (a converted scenario is a few MB; this bounds memory).
pub const MAX_FILE_BYTES: u64 = 512 * 1024 * 1024;

/// A scenario read from a file, its planning problems (none for a map) and what was skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadScenario {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
    pub warnings: Vec<Diagnostic>,
}

/// Reads a CommonRoad 2020a file. A missing file names the path tried.
pub fn read_scenario_file(path: &Path) -> Result<ReadScenario, Error> {
    let io = |source| Error::ReadFile { path: path.to_path_buf(), source: std::sync::Arc::new(source) };
    let len = std::fs::metadata(path).map_err(io)?.len();
    if len > MAX_FILE_BYTES {
        return Err(Error::TooLarge { path: path.to_path_buf(), bytes: len, max: MAX_FILE_BYTES });
    }
    let text = std::fs::read_to_string(path).map_err(io)?;
    read_scenario_str(&text, path)
}

/// Reads CommonRoad 2020a XML text; `path` is only used in messages.
pub fn read_scenario_str(text: &str, path: &Path) -> Result<ReadScenario, Error> {
    let doc = roxmltree::Document::parse(text).map_err(|source| Error::Xml { path: path.to_path_buf(), source })?;
    let mut cx = cursor::Cursor::new(&doc, path);
    let root = doc.root_element();
    if root.tag_name().name() != "commonRoad" {
        return Err(cx.err(root, "expected the root element <commonRoad>"));
    }
    let mut scenario = Scenario::new(header::header(&mut cx, root)?);
    header::location_and_tags(&mut cx, root, &mut scenario)?;
    let mut problems = PlanningProblemSet::default();
    for child in root.children().filter(|n| n.is_element()) {
        match child.tag_name().name() {
            "location" | "scenarioTags" => {}
            "lanelet" => scenario.network.lanelets.push(network::lanelet(&mut cx, child)?),
            "trafficSign" => scenario.network.traffic_signs.push(network::traffic_sign(&mut cx, child)?),
            "trafficLight" => scenario.network.traffic_lights.push(network::traffic_light(&mut cx, child)?),
            "intersection" => scenario.network.intersections.push(network::intersection(&mut cx, child)?),
            "staticObstacle" => scenario.static_obstacles.push(obstacles::static_obstacle(&mut cx, child)?),
            "dynamicObstacle" => {
                if let Some(o) = obstacles::dynamic_obstacle(&mut cx, child)? {
                    scenario.dynamic_obstacles.push(o);
                }
            }
            "environmentObstacle" => scenario.environment_obstacles.push(obstacles::environment_obstacle(&mut cx, child)?),
            "planningProblem" => problems.problems.push(planning::planning_problem(&mut cx, child)?),
            other => cx.warn(child, format!("element <{other}> is not read; skipped")),
        }
    }
    Ok(ReadScenario { scenario, problems, warnings: cx.into_warnings() })
}
