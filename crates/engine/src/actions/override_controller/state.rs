//! What an OverrideControllerValueAction is to the run: which of esmini's override kinds each
//! value sets, and the control domains the action holds. Data only (`../override_controller.rs`
//! starts the action).

use crate::actions::state::{LAT, LONG};
use openscenario::OverrideValue;

/// esmini's `Object::OverrideType`: throttle, brake, clutch, parking brake, steering wheel, gear.
pub(crate) const OVERRIDE_KINDS: usize = 6;

/// The index of an override value's element (`Throttle`, `Brake`, …) in esmini's order.
pub(crate) fn kind_index(element: &str) -> Option<usize> {
    ["Throttle", "Brake", "Clutch", "ParkingBrake", "SteeringWheel", "Gear"].iter().position(|k| *k == element)
}

/// The domains the action holds, folded over its values in document order as esmini's
/// `OverrideControlAction::AddOverrideStatus` folds them: an active steering wheel sets the
/// lateral domain and an inactive one clears it; every other value sets or clears the
/// longitudinal one. So the last non-steering value decides the longitudinal domain: throttle
/// on then brake off holds none, brake off then throttle on holds it. Starting the action
/// ends the entity's running actions on what it holds.
pub(crate) fn domains(values: &[OverrideValue]) -> u8 {
    values.iter().filter(|v| kind_index(&v.kind).is_some()).fold(0, |d, v| {
        let bit = if v.kind == "SteeringWheel" { LAT } else { LONG };
        if v.active {
            d | bit
        } else {
            d & !bit
        }
    })
}
