//! The run state of one entity driven from outside: why it is external, whether it is now,
//! the input of the step in progress, the vehicle model its driver input moves, and what
//! the last state given said (for dead reckoning and the rates it fixes).

use super::choice::Source;
use super::input::Input;
use crate::controllers::analog_vehicle::AnalogVehicle;

#[derive(Debug, Clone)]
pub(crate) struct Driven {
    pub source: Source,
    /// Driven from outside now.
    pub active: bool,
    /// Input for the step in progress (`None`: none given).
    pub input: Option<Input>,
    /// esmini's vehicle model its driver input drives (`driver_vehicle`).
    pub vehicle: AnalogVehicle,
    /// Speed and heading of the last state given, and whether it gave a height.
    pub last_state: Option<LastState>,
    /// Yaw rate the input of this step fixes (else derived).
    pub yaw_rate: Option<f64>,
    /// Pitch and roll the last state fixed (else the road's).
    pub pitch: Option<f64>,
    pub roll: Option<f64>,
    /// Its last placement ended at a dead end (the next step's end-of-road status).
    pub end_of_road: bool,
    /// The run said so once.
    pub told_end_of_road: bool,
    /// Where it was when the step in progress began (hold and dead reckoning start there,
    /// whatever the scripted motion did meanwhile).
    pub start: Option<Pose>,
}

/// An entity's pose and speed, with where that is on the road.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pose {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub h: f64,
    pub speed: f64,
    pub lane: Option<crate::roads::lane_position::LanePos>,
    pub on_road: bool,
    pub yaw_offset: f64,
}

impl Pose {
    pub(crate) fn of(en: &crate::entities::Entity) -> Pose {
        Pose { x: en.x, y: en.y, z: en.z, h: en.h, speed: en.speed, lane: en.lane, on_road: en.on_road, yaw_offset: en.yaw_offset }
    }

    pub(crate) fn put(&self, en: &mut crate::entities::Entity) {
        (en.x, en.y, en.z, en.h, en.speed, en.lane, en.on_road, en.yaw_offset) =
            (self.x, self.y, self.z, self.h, self.speed, self.lane, self.on_road, self.yaw_offset);
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LastState {
    pub speed: f64,
    pub h: f64,
    /// The height was given (kept while dead reckoning) rather than taken from the road.
    pub z_given: bool,
}

impl Driven {
    pub(crate) fn new(source: Source, active: bool) -> Driven {
        Driven {
            source,
            active,
            input: None,
            vehicle: super::driver_vehicle::udp_driver_vehicle(0.0, 0.0, 0.0, 0.0, 5.0),
            last_state: None,
            yaw_rate: None,
            pitch: None,
            roll: None,
            end_of_road: false,
            told_end_of_road: false,
            start: None,
        }
    }
}
