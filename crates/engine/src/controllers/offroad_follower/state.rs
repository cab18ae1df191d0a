//! What an OffroadFollower remembers: whom it follows, how closely, and its vehicle model.

use crate::controllers::analog_vehicle::AnalogVehicle;

#[derive(Debug, Clone)]
pub(crate) struct OffroadFollowerRt {
    pub active: bool,
    /// The domains it is active on (ActivateControllerAction's `lateral`, `longitudinal`).
    pub(super) lateral: bool,
    pub(super) longitudinal: bool,
    /// `followEntity` (esmini does nothing without it).
    pub(super) follow: Option<String>,
    /// `targetDistance`, m (20 by default).
    pub(super) target_distance: f64,
    /// `steeringRate` of the vehicle model (4 by default).
    pub(super) steering_rate: f64,
    pub(super) vehicle: Option<AnalogVehicle>,
}
