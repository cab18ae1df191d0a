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
}
