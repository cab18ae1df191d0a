//! What a FollowGhost controller remembers: its mode, head start and vehicle model.

use crate::controllers::kinematic_vehicle::KinematicVehicle;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FollowMode {
    Time,
    Position,
}

#[derive(Debug, Clone)]
pub(crate) struct FollowGhostRt {
    pub active: bool,
    /// Active on the longitudinal domain (else esmini's default controller moves the entity
    /// along its lane before the controller measures from there).
    pub longitudinal: bool,
    pub headstart: f64,
    pub(super) mode: FollowMode,
    pub(super) lookahead_speed: f64,
    pub(super) min_lookahead_speed: f64,
    pub(super) lookahead_steering: f64,
    pub(super) min_lookahead_steering: f64,
    pub(super) steering_scale: f64,
    pub(super) vehicle: Option<KinematicVehicle>,
    /// Trail segment where the last search ended (searches go on from there).
    pub(super) follow_index: usize,
    /// Arc length of the trail point nearest to the entity at the last search.
    pub(super) closest_s: f64,
}
