//! What a run records but does not simulate: the vehicle light states LightStateActions ask
//! for and the environments EnvironmentActions set (time of day, weather, road condition),
//! each with the time it was asked for, so that nothing the scenario says is lost even where
//! the output format (CommonRoad 2020a has no vehicle lights) cannot carry it.

use openscenario::{Environment, LightState, LightType};

/// A LightStateAction started: `entity`'s light `light` is to take `state` over
/// `transition_time` seconds (None: at once).
#[derive(Debug, Clone, PartialEq)]
pub struct LightChange {
    pub time: f64,
    pub entity: String,
    pub light: LightType,
    pub state: LightState,
    pub transition_time: Option<f64>,
}

/// An EnvironmentAction (Init or story) set the environment at `time`.
#[derive(Debug, Clone, PartialEq)]
pub struct EnvironmentChange {
    pub time: f64,
    pub environment: Environment,
}
