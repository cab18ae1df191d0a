//! Which entities a run drives from outside, and from when: by default the entities whose
//! controller needs an outside driver (esmini's ExternalController, InteractiveController,
//! UDPDriverController, ExternalDriverModel), each from the step its controller is activated
//! (ActivateControllerAction, or AssignControllerAction with activation); or the entities the
//! caller names, from the first step after Init placed them.

use openscenario::Controller;

/// Which entities a run drives from outside, and what the storyboard's motion actions do to them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct External {
    pub entities: Chosen,
    pub motion: ScriptedMotion,
}

impl External {
    /// The engine drives everything (a conversion).
    pub fn none() -> External {
        External::default()
    }

    /// The entities whose controller needs an outside driver; esmini's override rule.
    pub fn controllers() -> External {
        External { entities: Chosen::Controllers, motion: ScriptedMotion::Overridden }
    }

    /// These entities; esmini's override rule.
    pub fn named<S: Into<String>>(names: impl IntoIterator<Item = S>) -> External {
        External { entities: Chosen::Named(names.into_iter().map(Into::into).collect()), motion: ScriptedMotion::Overridden }
    }
}

/// Which entities are driven from outside.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Chosen {
    /// None: a controller that needs an outside driver is replaced by the default controller,
    /// with a warning.
    #[default]
    None,
    /// The entities whose controller needs an outside driver, once it is activated.
    Controllers,
    /// These entities, by name, from the first step on.
    Named(Vec<String>),
}

/// What the storyboard's motion actions (and the default controller) do to an entity driven
/// from outside.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ScriptedMotion {
    /// esmini's rule for an entity whose controller overrides both domains (`overridden`): a
    /// SpeedAction ends at once, a lane change, lane offset, trajectory, distance or
    /// synchronize action runs without effect and never ends, a teleport is ignored, the
    /// default controller leaves it alone. The storyboard takes the course the outside
    /// driving gives it.
    #[default]
    Overridden,
    /// The engine moves the entity as the storyboard and the default controller say, and the
    /// outside's input then replaces the result in the same step: the storyboard keeps the
    /// author's timing (an event waiting for the entity's own speed change starts when that
    /// change would have ended), while every condition and driver model sees the entity where
    /// the outside put it.
    Replaced,
}

/// Controller types whose entity waits for an outside driver (`External::Controllers`).
pub const OUTSIDE_DRIVERS: [&str; 4] = ["ExternalController", "InteractiveController", "UDPDriverController", "ExternalDriverModel"];

/// Why an entity is external.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// The caller named it.
    Named,
    /// Its controller needs an outside driver; the controller as the scenario defines it (its
    /// properties carry e.g. a UDP driver's port and input mode).
    Controller(Controller),
}

/// An entity the caller drives.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalEntity {
    /// Index in the trace's entities.
    pub index: usize,
    pub name: String,
    pub source: Source,
    /// Driven from outside now (a controller's entity only once the controller is activated).
    pub active: bool,
}
