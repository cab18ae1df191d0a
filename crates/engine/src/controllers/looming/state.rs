//! What a LoomingController remembers: its set speed and time gap, its vehicle model, the
//! previous steering angles, the OSI points it has looked at.

use crate::controllers::analog_vehicle::AnalogVehicle;
use crate::controllers::looming::view::OsiMemo;

#[derive(Debug, Clone)]
pub(crate) struct LoomingRt {
    pub active: bool,
    pub(super) time_gap: f64,
    pub(super) set_speed: f64,
    pub(super) set_speed_given: bool,
    pub(in crate::controllers) override_mode: bool,
    /// esmini's vehicle model the controller drives (set up when it is activated).
    pub(super) vehicle: Option<AnalogVehicle>,
    pub(super) prev_near: f64,
    pub(super) prev_far: f64,
    pub(super) steering: f64,
    pub(super) osi: OsiMemo,
    /// The last move ended at a road end (seen by the next step).
    pub(super) end_of_road: bool,
    /// The road and s where its last step attached the entity (by XYZ2TrackPos): a position
    /// still there is the controller's own, which esmini holds at a road end's last OSI point.
    pub(super) placed_at: Option<(usize, f64)>,
    /// The heading its last step gave the entity, and that heading as esmini's position holds
    /// it (composed with the road's: `position_heading`).
    pub(super) placed_h: Option<(f64, f64)>,
}
