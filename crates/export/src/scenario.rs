//! The whole OpenSCENARIO document of one CommonRoad scenario: the file header, the flags the
//! goal events set, the road network (the map file, the traffic-light controllers), the
//! entities (egos first, then the obstacles in file order), the Init that places them, one
//! story whose maneuver groups add, move and delete the obstacles and watch the egos' goals,
//! and the stop trigger: every ego at its goal (unless `play_to_end`), or the time of the last
//! obstacle state or goal time, whichever is later.

use commonroad::{PlanningProblemSet, Scenario};
use serde::Serialize;

use crate::actions::{after, trigger};
use crate::ego::ego;
use crate::goal::{goal_event, goal_groups, goal_reached};
use crate::obstacles::{last_step, placed, TIME_MARGIN};
use crate::options::{ExportOptions, OscVersion};
use crate::xml::{document as xml_document, time, El};

/// What an exported scenario holds, for the report.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Facts {
    /// Entities of the scenario (egos included).
    pub entities: usize,
    /// Egos (one per planning problem).
    pub egos: usize,
    pub dynamic_obstacles: usize,
    pub static_obstacles: usize,
    pub environment_obstacles: usize,
    /// Obstacles added after time 0 / deleted before the end.
    pub added: usize,
    pub deleted: usize,
    pub traffic_lights: usize,
    /// Egos whose goal became an end condition.
    pub goals: usize,
    /// When the run ends at the latest, s.
    pub end_time: f64,
}

/// The document's text, its warnings and facts.
#[derive(Debug, Clone, PartialEq)]
pub struct Document {
    pub xosc: String,
    pub warnings: Vec<String>,
    pub facts: Facts,
}

fn flag_name(ego: &str) -> String {
    format!("{ego}_goal_reached")
}

/// The document of `scenario` and its planning problems; `logic_file` is the path of the map
/// as the document names it (`None`: no map).
pub fn document(scenario: &Scenario, problems: &PlanningProblemSet, logic_file: Option<&str>, options: &ExportOptions) -> Result<Document, String> {
    let version = options.osc;
    let dt = scenario.header.time_step_size;
    if !(dt.is_finite() && dt > 0.0) {
        return Err(format!("time step size {dt} is not a positive number of seconds"));
    }
    let mut warnings = Vec::new();
    let goal_end = problems.problems.iter().flat_map(|p| p.goal_states.iter().map(|g| g.time.end())).max().unwrap_or(0);
    let end_step = last_step(scenario).max(goal_end).max(1);
    let mut facts = Facts { end_time: end_step as f64 * dt, traffic_lights: scenario.network.traffic_lights.len(), ..Facts::default() };

    let obstacles = placed(scenario, end_step, version, &mut warnings);
    let mut egos = Vec::new();
    for (i, p) in problems.problems.iter().enumerate() {
        egos.push(ego(i, p, &scenario.network, options)?);
    }

    // entities: egos first (simulators take the first entity for the ego), then the obstacles
    let mut entities = El::new("Entities");
    for e in &egos {
        entities.push(e.entity.scenario_object(version, e.controller.clone()));
    }
    for o in &obstacles {
        entities.push(o.entity.scenario_object(version, None));
    }
    facts.egos = egos.len();
    facts.entities = egos.len() + obstacles.len();
    facts.dynamic_obstacles = scenario.dynamic_obstacles.len();
    facts.static_obstacles = scenario.static_obstacles.len();
    facts.environment_obstacles = scenario.environment_obstacles.len();

    // the Init places every entity present at time 0
    let mut init = El::new("Actions");
    let privates = egos.iter().map(|e| (&e.entity.name, &e.init)).chain(obstacles.iter().map(|o| (&o.entity.name, &o.init)));
    for (name, actions) in privates {
        if !actions.is_empty() {
            init.push(El::new("Private").attr("entityRef", name.clone()).children(actions.iter().cloned()));
        }
    }

    // the story: goal events of the egos, add/delete events of the obstacles
    let mut groups = Vec::new();
    let mut declared = Vec::new();
    let mut reached = Vec::new();
    for (e, p) in egos.iter().zip(&problems.problems) {
        let name = &e.entity.name;
        let cond = goal_groups(p, name, &scenario.network, dt, version, &mut warnings);
        if cond.is_empty() {
            warnings.push(format!("{name}: no goal state of planning problem {} can be said in OpenSCENARIO; the run ends by time only", p.id));
            continue;
        }
        let flag = flag_name(name);
        groups.push(maneuver_group(name, vec![goal_event(name, &flag, cond, version)]));
        declared.push(flag);
        reached.push(goal_reached(name));
    }
    facts.goals = reached.len();
    for o in &obstacles {
        if o.events.is_empty() {
            continue;
        }
        facts.added += usize::from(o.init.is_empty());
        facts.deleted += usize::from(o.last_step.is_some_and(|l| l < end_step));
        groups.push(maneuver_group(&o.entity.name, o.events.clone()));
    }
    if groups.is_empty() {
        // a story needs a maneuver group (1.0 a story too)
        groups.push(
            El::new("ManeuverGroup")
                .attr("name", "nothing_happens")
                .attr("maximumExecutionCount", "1")
                .child(El::new("Actors").attr("selectTriggeringEntities", "false")),
        );
    }
    let margin = TIME_MARGIN * dt;
    let act = El::new("Act").attr("name", "replay").children(groups).child(trigger("StartTrigger", vec![vec![after("replay_starts".to_string(), -margin)]]));
    let story = El::new("Story").attr("name", "commonroad").child(act);
    let mut stop_groups = Vec::new();
    if !options.play_to_end && !reached.is_empty() {
        stop_groups.push(reached);
    }
    stop_groups.push(vec![after("time_is_up".to_string(), end_step as f64 * dt - margin)]);
    let storyboard = El::new("Storyboard").child(El::new("Init").child(init)).child(story).child(trigger("StopTrigger", stop_groups));

    // the road network: the map and the lights' controllers
    let mut road = El::new("RoadNetwork");
    if let Some(f) = logic_file {
        road.push(El::new("LogicFile").attr("filepath", f));
    }
    if !scenario.network.traffic_lights.is_empty() {
        road.push(El::new("TrafficSignals").children(scenario.network.traffic_lights.iter().map(|l| crate::lights::controller(l, dt))));
    }

    let h = &scenario.header;
    let author = if h.author.trim().is_empty() { "osc2cr".to_string() } else { h.author.clone() };
    let header = El::new("FileHeader")
        .attr("revMajor", "1")
        .attr("revMinor", version.minor().to_string())
        .attr("date", format!("{}T00:00:00", h.date))
        .attr("description", format!("CommonRoad scenario {} (time step {} s), exported by osc2cr", h.benchmark_id, time(dt)))
        .attr("author", author);
    let mut root = El::new("OpenSCENARIO").child(header);
    match version {
        OscVersion::V1_0 => {
            root = root.child(El::new("ParameterDeclarations").children(
                declared.iter().map(|n| El::new("ParameterDeclaration").attr("name", n.clone()).attr("parameterType", "boolean").attr("value", "false")),
            ));
        }
        OscVersion::V1_3 => {
            root = root.child(El::new("ParameterDeclarations"));
            if !declared.is_empty() {
                root = root.child(El::new("VariableDeclarations").children(
                    declared.iter().map(|n| El::new("VariableDeclaration").attr("name", n.clone()).attr("variableType", "boolean").attr("value", "false")),
                ));
            }
        }
    }
    root = root.child(El::new("CatalogLocations")).child(road).child(entities).child(storyboard);
    Ok(Document { xosc: xml_document(&root), warnings, facts })
}

/// A maneuver group whose actor is `entity`, with one maneuver holding `events`.
fn maneuver_group(entity: &str, events: Vec<El>) -> El {
    El::new("ManeuverGroup")
        .attr("name", entity.to_string())
        .attr("maximumExecutionCount", "1")
        .child(El::new("Actors").attr("selectTriggeringEntities", "false").child(El::new("EntityRef").attr("entityRef", entity)))
        .child(El::new("Maneuver").attr("name", entity.to_string()).children(events))
}
