//! The scenario's obstacles as entities with what places and moves them. A dynamic obstacle
//! follows its trajectory ([`crate::trajectory`]); one present from time 0 is placed and set
//! going by the Init, one that appears later is added by a story event, and one that leaves
//! before the end is deleted by another. Static and environment obstacles are placed by the
//! Init and stand. A trajectory that esmini's filter of close vertices would change is
//! followed piece by piece ([`crate::trajectory`]): the further pieces are story events.
//!
//! Timing of appearance (esmini 3.6.0, `OSCGlobalAction.cpp` and `ScenarioEngine::step`, run
//! on scenarios written for it): only the entities the Init names exist from the start; an
//! event's actions run in the step its trigger holds, and a step moves the entity to where the
//! trajectory is at the *end* of the step. So an obstacle whose first state is at step k is
//! added when the simulation time passes (k − 1)·dt: a simulator stepping at dt shows it first
//! at k·dt on its first state; a finer step shows it standing on its first state a little
//! earlier (less than dt). It is deleted when the time passes its last step, so it is still
//! there at that step. Times carry a margin of a thousandth of dt against the rounding of
//! summed steps, and no event fires at time 0 (`> dt/1000` at the earliest): esmini runs time 0
//! twice — its Init frame (a step of 0, whose events already fire and whose row is logged at 0)
//! and its first step — so an obstacle whose first state is at step 1 is added in the step
//! after 0 and is there at step 1 when the simulator steps at dt/2 or finer (at dt it is one
//! step late).

use commonroad::{AbsoluteShape, DynamicObstacle, EnvironmentObstacle, Scenario, State, StaticObstacle};

use crate::actions::{action, add_entity, after, delete_entity, teleport};
use crate::entity::{box_of, BoxShape, Element, Entity};
use crate::options::OscVersion;
use crate::trajectory::{follow, reference};
use crate::xml::El;

/// The margin of trigger times, as a fraction of the time step.
pub(crate) const TIME_MARGIN: f64 = 1e-3;

/// An entity and how the storyboard places and moves it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Placed {
    pub entity: Entity,
    /// Its `Private` actions of the Init (empty for one that appears later).
    pub init: Vec<El>,
    /// Its story events.
    pub events: Vec<El>,
    /// The last time step it exists at (`None`: it stands for the whole run).
    pub last_step: Option<u64>,
}

/// A run of events named after the entity.
fn event(name: String, actions: Vec<El>, at: f64) -> El {
    El::new("Event")
        .attr("name", name.clone())
        .attr("priority", "parallel")
        .attr("maximumExecutionCount", "1")
        .children(actions)
        .child(crate::actions::trigger("StartTrigger", vec![vec![after(format!("{name}_time"), at)]]))
}

fn dynamic(o: &DynamicObstacle, dt: f64, end_step: u64, version: OscVersion, warnings: &mut Vec<String>) -> Placed {
    let element = Element::Dynamic(o.obstacle_type);
    let pedestrian = o.obstacle_type == commonroad::DynamicObstacleType::Pedestrian;
    let (shape, note) = box_of(&o.shape, pedestrian);
    let states: Vec<State> = std::iter::once(o.initial_state).chain(o.trajectory.iter().copied()).collect();
    let top = states.iter().map(|s| s.velocity.abs()).fold(0.0, f64::max);
    let entity = Entity::obstacle(o.id.get(), element, shape, top);
    if let Some(n) = note {
        warnings.push(format!("{}: {n}", entity.name));
    }
    if states.windows(2).any(|w| w[1].time_step != w[0].time_step + 1) {
        warnings.push(format!("{}: its time steps are not consecutive; the trajectory goes straight between the states it has", entity.name));
    }
    let first = states[0];
    let last = states[states.len() - 1];
    let (x, y) = reference(&first, &shape);
    let mut pieces = if states.len() >= 2 { follow(&entity.name, &states, &shape, dt, version) } else { Vec::new() }.into_iter();
    let moves = pieces.next().map(|p| p.action);
    let name = entity.name.clone();
    let margin = TIME_MARGIN * dt;
    let (init, mut events) = if first.time_step == 0 {
        let mut private = vec![teleport(x, y, first.orientation)];
        private.extend(moves);
        (private, Vec::new())
    } else {
        let mut actions = vec![action(format!("{name}_add"), add_entity(&name, x, y, first.orientation))];
        actions.extend(moves.map(|m| action(format!("{name}_follow"), m)));
        let at = ((first.time_step - 1) as f64 * dt - margin).max(margin);
        (Vec::new(), vec![event(format!("{name}_appears"), actions, at)])
    };
    // each further piece of the trajectory starts when the time reaches its first state, where
    // the previous piece ended: in the step after that one ended it moves the entity
    for (k, p) in pieces.enumerate() {
        let label = format!("{name}_moves_{}", k + 2);
        let at = (p.first_step as f64 * dt - margin).max(margin);
        events.push(event(label, vec![action(format!("{name}_follow_{}", k + 2), p.action)], at));
    }
    if last.time_step < end_step {
        let at = (last.time_step as f64 * dt - margin).max(margin);
        events.push(event(format!("{name}_leaves"), vec![action(format!("{name}_delete"), delete_entity(&name))], at));
    }
    Placed { entity, init, events, last_step: Some(last.time_step) }
}

fn standing(entity: Entity, x: f64, y: f64, h: f64) -> Placed {
    let shape = entity.shape;
    let s = State { time_step: 0, x, y, orientation: h, velocity: 0.0, acceleration: 0.0, yaw_rate: 0.0 };
    let (rx, ry) = reference(&s, &shape);
    Placed { entity, init: vec![teleport(rx, ry, h)], events: Vec::new(), last_step: None }
}

fn static_obstacle(o: &StaticObstacle, warnings: &mut Vec<String>) -> Placed {
    let (shape, note) = box_of(&o.shape, false);
    let entity = Entity::obstacle(o.id.get(), Element::Static(o.obstacle_type), shape, 0.0);
    if let Some(n) = note {
        warnings.push(format!("{}: {n}", entity.name));
    }
    standing(entity, o.x, o.y, o.orientation)
}

/// An environment obstacle's shape is placed in the world: a rectangle is its box; a circle
/// and a polygon their (axis-aligned) bounding boxes.
fn environment_obstacle(o: &EnvironmentObstacle, warnings: &mut Vec<String>) -> Placed {
    let element = Element::Environment(o.obstacle_type);
    let (shape, x, y, h, note) = match &o.shape {
        AbsoluteShape::Rectangle(r) => {
            (BoxShape { length: r.rectangle.length(), width: r.rectangle.width(), cx: 0.0, cy: 0.0 }, r.center.x, r.center.y, r.orientation, None)
        }
        AbsoluteShape::Circle(c) => {
            let d = 2.0 * c.circle.radius();
            (BoxShape { length: d, width: d, cx: 0.0, cy: 0.0 }, c.center.x, c.center.y, 0.0, Some("a circle is written as its bounding square"))
        }
        AbsoluteShape::Polygon(p) => {
            let polygon = commonroad::Shape::Polygon(p.clone());
            let (b, _) = box_of(&polygon, false);
            (b, 0.0, 0.0, 0.0, Some("a polygon is written as its axis-aligned bounding box"))
        }
    };
    let entity = Entity::obstacle(o.id.get(), element, shape, 0.0);
    if let Some(n) = note {
        warnings.push(format!("{}: {n}", entity.name));
    }
    standing(entity, x, y, h)
}

/// The last time step of any dynamic obstacle (0 if none).
pub(crate) fn last_step(scenario: &Scenario) -> u64 {
    let last = |o: &DynamicObstacle| o.trajectory.last().map_or(o.initial_state.time_step, |s| s.time_step);
    scenario.dynamic_obstacles.iter().map(last).max().unwrap_or(0)
}

/// Every obstacle of the scenario, in file order: dynamic, static, environment. The run ends at
/// `end_step`: an obstacle there until then is not deleted.
pub(crate) fn placed(scenario: &Scenario, end_step: u64, version: OscVersion, warnings: &mut Vec<String>) -> Vec<Placed> {
    let dt = scenario.header.time_step_size;
    let mut out = Vec::new();
    out.extend(scenario.dynamic_obstacles.iter().map(|o| dynamic(o, dt, end_step, version, warnings)));
    out.extend(scenario.static_obstacles.iter().map(|o| static_obstacle(o, warnings)));
    out.extend(scenario.environment_obstacles.iter().map(|o| environment_obstacle(o, warnings)));
    out
}
