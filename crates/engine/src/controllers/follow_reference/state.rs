//! What a FollowReference controller remembers.

use crate::controllers::kinematic_vehicle::KinematicVehicle;

#[derive(Debug, Clone)]
pub(crate) struct FollowReferenceRt {
    pub active: bool,
    pub(super) cross_track_gain: f64,
    pub(super) speed_stabilizer: f64,
    pub(super) heading_gain: f64,
    pub(super) curvature_gain: f64,
    pub(super) stiffness: f64,
    /// `referenceEntity`; `None`: follow the ghost.
    pub reference_name: Option<String>,
    pub(super) vehicle: Option<KinematicVehicle>,
    pub(super) wheelbase: f64,
}
