//! What the driver models hold while a run goes on: every controller assigned to an entity,
//! with its state (each model's own `state` module). Data only: the modules of `controllers/`
//! change it.

/// One controller assigned to an entity, as esmini keeps it: an entity holds a list of them
/// (Object::controllers_), an AssignControllerAction appends one without switching off the
/// others, and every active one steps.
#[derive(Debug, Clone)]
pub(crate) struct ControllerSlot {
    pub entity: usize,
    /// The controller's place in esmini's list of controllers (ScenarioReader::controller_, the
    /// order they step in): the ObjectControllers first, then the AssignControllerActions' by
    /// their action slots (`step_order.rs`).
    pub rank: usize,
    /// The action slot of the AssignControllerAction that made it; `None`: an ObjectController.
    pub assigned_by: Option<usize>,
    /// When it was last assigned (a count): the entity's most recent one is the one an
    /// ActivateControllerAction naming no controller activates (`controllers_.back()`).
    pub assigned: u64,
    /// Its name (Object::GetController finds a controller by it).
    pub name: String,
    /// Its state; `None` for a type osc2cr does not model (and while it steps).
    pub rt: Option<ControllerRt>,
}

/// A controller's state during a run.
#[derive(Debug, Clone)]
pub(crate) enum ControllerRt {
    Acc(super::acc::state::AccRt),
    AlksR157(Box<super::alks_r157::state::AlksR157Rt>),
    NaturalDriver(Box<super::natural_driver::state::NaturalDriverRt>),
    FollowGhost(Box<super::follow_ghost::state::FollowGhostRt>),
    FollowReference(Box<super::follow_reference::state::FollowReferenceRt>),
    FollowRoute(Box<super::follow_route::state::FollowRouteRt>),
    Looming(super::looming::state::LoomingRt),
    OffroadFollower(Box<super::offroad_follower::state::OffroadFollowerRt>),
}

impl ControllerRt {
    /// Whether the controller sets its entity's speed in each step (esmini's
    /// `Object::SetSpeed`, which marks `DirtyBit::SPEED`): only an active one is stepped
    /// (ScenarioEngine::step asks `Controller::Active`, some domain on), and of the modelled
    /// types every one but ControllerFollowRoute calls SetSpeed in its Step. An ACC activated on
    /// the lateral domain alone stays off (it operates on the longitudinal one only).
    pub(crate) fn sets_speed(&self) -> bool {
        match self {
            ControllerRt::Acc(a) => a.active,
            ControllerRt::AlksR157(a) => a.active,
            ControllerRt::NaturalDriver(a) => a.active,
            ControllerRt::FollowGhost(f) => f.active,
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowRoute(_) => false,
            ControllerRt::Looming(l) => l.active,
            ControllerRt::OffroadFollower(f) => f.active,
        }
    }

    /// Whether it is active on the lateral (`lateral`) or the longitudinal domain, as esmini's
    /// `Controller::IsActiveOnDomains` asks: the ACC, the looming controller and NaturalDriver
    /// operate on the longitudinal domain only; the others on both, on those their activation
    /// asked for where the state keeps that (a ghost follower, FollowReference and FollowRoute
    /// keep no lateral flag: active is active on it).
    pub(crate) fn active_on(&self, lateral: bool) -> bool {
        match self {
            ControllerRt::Acc(a) => !lateral && a.active,
            ControllerRt::Looming(l) => !lateral && l.active,
            ControllerRt::NaturalDriver(n) => !lateral && n.active,
            ControllerRt::AlksR157(a) => a.active && if lateral { a.lateral } else { a.longitudinal },
            ControllerRt::FollowGhost(f) => f.active && (lateral || f.longitudinal),
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowRoute(f) => {
                if lateral {
                    f.active
                } else {
                    f.active_longitudinal()
                }
            }
            ControllerRt::OffroadFollower(f) => {
                if lateral {
                    f.holds_lateral()
                } else {
                    f.holds_longitudinal()
                }
            }
        }
    }
}
