//! The egos: one entity per planning problem (`Ego`, then `Ego_<problem id>` for the others),
//! placed at the problem's initial state with its initial speed. By default the simulator's
//! default controller drives it — it keeps its lane (the map's, as the simulator finds it under
//! the world position) and its speed; with [`EgoController::External`] an `ExternalController`
//! (esmini's name for an outside driver) is assigned and activated in the Init. The entity
//! carries its planning problem ([`crate::carrier`]). CommonRoad gives an ego no shape: it is a
//! car of 4.5 m × 1.8 m, reference point at the box centre like every entity here.

use commonroad::{LaneletNetwork, PlanningProblem};

use crate::actions::{activate_controller, speed, teleport};
use crate::carrier::{carried, PLANNING_PROBLEM_PROPERTY};
use crate::entity::{BoxShape, Entity, Object};
use crate::options::{EgoController, ExportOptions};
use crate::xml::El;

/// An ego's box (CommonRoad gives none).
const EGO_LENGTH: f64 = 4.5;
const EGO_WIDTH: f64 = 1.8;

/// An ego entity and its Init actions.
pub(crate) struct Ego {
    pub entity: Entity,
    pub controller: Option<El>,
    pub init: Vec<El>,
}

/// The name of the ego of the `index`-th planning problem.
pub(crate) fn ego_name(index: usize, problem: &PlanningProblem) -> String {
    if index == 0 {
        "Ego".to_string()
    } else {
        format!("Ego_{}", problem.id)
    }
}

pub(crate) fn ego(index: usize, problem: &PlanningProblem, network: &LaneletNetwork, options: &ExportOptions) -> Result<Ego, String> {
    let s = &problem.initial_state;
    let shape = BoxShape { length: EGO_LENGTH, width: EGO_WIDTH, cx: 0.0, cy: 0.0 };
    let entity = Entity {
        name: ego_name(index, problem),
        object: Object::Vehicle("car"),
        shape,
        top_speed: s.velocity.abs(),
        properties: vec![(PLANNING_PROBLEM_PROPERTY, carried(problem, network)?)],
    };
    let mut init = vec![teleport(s.x, s.y, s.orientation), speed(s.velocity)];
    let controller = match options.ego_controller {
        EgoController::Default => None,
        EgoController::External => {
            init.push(activate_controller(options.osc));
            let properties = El::new("Properties").child(El::new("Property").attr("name", "esminiController").attr("value", "ExternalController"));
            Some(El::new("Controller").attr("name", "ExternalController").child(properties))
        }
    };
    Ok(Ego { entity, controller, init })
}
