//! Steps 3–5 of the paper's algorithm: the lanelet network and the simulated trace become one
//! CommonRoad scenario with obstacles and the ego's planning problem, checked by
//! `commonroad::Scenario::validate`. A scenario whose entities carry CommonRoad planning
//! problems (`osc2cr export`'s, see `carried.rs`) gets those, and their entities are egos, not
//! obstacles.

use std::collections::BTreeSet;

use commonroad::{Header, Lanelet, LaneletBounds, LaneletNetwork, LaneletType, PlanningProblem, PlanningProblemSet, Point, Scenario, State, Tag};
use engine::Trace;
use openscenario::Entity;

use crate::carried::{carried_problems, retarget};
use crate::ego::choose_ego;
use crate::goal::planning_problem;
use crate::obstacles::obstacles;
use crate::options::ConvertOptions;
use crate::tags::scenario_tags;
use crate::tracks::{tracks, Placement, Track};

/// A scenario ready to be written, and what the report says about it.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembled {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
    /// The entity chosen as ego.
    pub ego: String,
    /// Dynamic, static and environment obstacles.
    pub obstacles: usize,
    /// The entity each obstacle was made of: (obstacle id, entity name).
    pub names: Vec<(u64, String)>,
    /// Lanelets of the road network (0 when a placeholder stands in for a missing network).
    pub lanelets: usize,
    pub warnings: Vec<String>,
}

/// Builds the scenario from a trace. `network` is the converted road network (`None`: the
/// scenario names none, or it could not be used).
pub fn assemble(
    header: Header,
    network: Option<LaneletNetwork>,
    extra_tags: &BTreeSet<Tag>,
    trace: &Trace,
    entities: &[Entity],
    options: &ConvertOptions,
) -> Result<Assembled, String> {
    let (tracks, mut warnings) = tracks(trace, entities, options.dt);
    // planning problems the scenario carries (an `osc2cr export`): their entities are the egos
    let carried = carried_problems(entities, &mut warnings);
    let carried_ego = carried.iter().find_map(|c| tracks.iter().position(|t| t.entity == c.entity));
    let ego_index = match carried_ego {
        Some(i) => i,
        None => choose_ego(&tracks, &options.ego)?,
    };
    let ego = &tracks[ego_index];
    let (first, last) = match &ego.placement {
        Placement::Moving(runs) => (runs.first().and_then(|r| r.first()).copied(), runs.last().and_then(|r| r.last()).copied()),
        &Placement::Fixed { x, y, orientation, last_step } => {
            warnings
                .push(format!("no entity of the scenario moves: the planning problem starts at the fixed object {:?}, at rest for the whole run", ego.entity));
            let at = |time_step| State { time_step, x, y, orientation, velocity: 0.0, acceleration: 0.0, yaw_rate: 0.0 };
            (Some(at(0)), Some(at(last_step.max(1))))
        }
    };
    let (Some(first), Some(last)) = (first, last) else {
        return Err(format!("the ego {:?} has no state", ego.entity));
    };

    let mut scenario = Scenario::new(header);
    scenario.tags = scenario_tags(network.as_ref());
    scenario.tags.extend(extra_tags.iter().copied());
    let lanelets = network.as_ref().map_or(0, |n| n.lanelets.len());
    let needs_placeholder = lanelets == 0;
    if let Some(n) = network {
        scenario.network = n;
    }
    let mut ids = scenario.id_allocator(None);
    if needs_placeholder {
        let lanelet = placeholder_lanelet(&first, ego, &mut ids)?;
        scenario.network.lanelets.push(lanelet);
        warnings.push(
            "no road network: a placeholder lanelet (type unknown) the size of the ego is written \
             under the ego's initial position, because a CommonRoad file needs at least one lanelet"
                .to_string(),
        );
    }

    let skip: Vec<&str> = if carried.is_empty() {
        options.drop_ego.then_some(ego.entity.as_str()).into_iter().collect()
    } else {
        carried.iter().map(|c| c.entity.as_str()).collect()
    };
    let built = obstacles(&tracks, &skip, &mut ids);
    warnings.extend(built.warnings);
    let n_obstacles = built.dynamic.len() + built.statics.len() + built.environment.len();
    scenario.dynamic_obstacles = built.dynamic;
    scenario.static_obstacles = built.statics;
    scenario.environment_obstacles = built.environment;
    let names = built.names;

    let problems = if carried.is_empty() {
        let problem =
            planning_problem(ids.planning_problem(), &first, &last, &options.goal).map_err(|e| format!("planning problem of the ego {:?}: {e}", ego.entity))?;
        PlanningProblemSet { problems: vec![problem] }
    } else {
        let network = (lanelets > 0).then_some(&scenario.network);
        let problems = carried.iter().map(|c| PlanningProblem { id: ids.planning_problem(), ..retarget(c, network, &mut warnings) }).collect();
        PlanningProblemSet { problems }
    };
    let found = scenario.validate(Some(&problems));
    if !found.is_empty() {
        let list: Vec<String> = found.iter().take(5).map(ToString::to_string).collect();
        return Err(format!("the CommonRoad scenario is inconsistent ({} problems): {}", found.len(), list.join("; ")));
    }
    Ok(Assembled { scenario, problems, ego: ego.entity.clone(), obstacles: n_obstacles, names, lanelets, warnings })
}

/// A lanelet the size of the ego's box under its initial state, aligned with its heading.
fn placeholder_lanelet(first: &State, ego: &Track, ids: &mut commonroad::IdAllocator) -> Result<Lanelet, String> {
    let (s, c) = first.orientation.sin_cos();
    let (hl, hw) = (0.5 * ego.length, 0.5 * ego.width);
    let at = |along: f64, left: f64| Point::new(first.x + c * along - s * left, first.y + s * along + c * left);
    let bounds = LaneletBounds::new(vec![at(-hl, hw), at(hl, hw)], vec![at(-hl, -hw), at(hl, -hw)]).map_err(|e| format!("placeholder lanelet: {e}"))?;
    Ok(Lanelet::new(ids.lanelet(), bounds, LaneletType::Unknown))
}
