//! The planning problem, written back unchanged into the scenario so that converting the
//! exported scenario forward again (`osc2cr convert`) gives it back: the ego entity's property
//! [`PLANNING_PROBLEM_PROPERTY`] holds the problem as CommonRoad 2020a XML
//! ([`commonroad::xml::write_planning_problem`]: the `<planningProblem>` element and copies of
//! the lanelets its goals name, so that the forward conversion can find them in the map it
//! converts back, whose lanelets have other ids). The forward converter reads the property
//! (`convert`'s `carried_problems`), makes the entity that carries it the ego of that problem
//! and not an obstacle (in the CommonRoad scenario it came from it was none).

use commonroad::{GoalPosition, Lanelet, LaneletNetwork, PlanningProblem};

/// The property of an ego entity that carries its planning problem.
pub const PLANNING_PROBLEM_PROPERTY: &str = "osc2cr:commonRoadPlanningProblem";

/// The property's value for `problem`: its XML with the goal lanelets of `network`.
pub(crate) fn carried(problem: &PlanningProblem, network: &LaneletNetwork) -> Result<String, String> {
    let mut lanelets: Vec<&Lanelet> = Vec::new();
    for g in &problem.goal_states {
        if let Some(GoalPosition::Lanelets(ids)) = &g.position {
            for id in ids {
                if let Some(l) = network.lanelets.iter().find(|l| l.id == *id) {
                    if !lanelets.iter().any(|k| k.id == l.id) {
                        lanelets.push(l);
                    }
                }
            }
        }
    }
    commonroad::xml::write_planning_problem(problem, &lanelets).map_err(|e| format!("planning problem {}: {e}", problem.id))
}
