//! What the driver models hold while a run goes on: one controller state per entity (each
//! model's own `state` module). Data only: the modules of `controllers/` change it.

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
}
