//! Traffic signs and traffic lights.

use std::num::NonZeroU64;

use crate::geometry::Point;
use crate::ids::{TrafficLightId, TrafficSignId};
use crate::str_enum::str_enum;

/// One sign on a `trafficSign` post.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TrafficSignElement {
    /// The XSD spelling, e.g. `"274"` (DEU/ZAM max speed) or `"R2-1"` (USA); must be one of
    /// [`crate::XSD_TRAFFIC_SIGN_IDS`] (`validate()` checks).
    pub sign_id: String,
    /// E.g. a speed limit in **m/s** (format numbers with [`crate::xml::format_decimal`]).
    pub additional_values: Vec<String>,
}

impl TrafficSignElement {
    /// A sign without additional values.
    pub fn new(sign_id: impl Into<String>) -> Self {
        Self { sign_id: sign_id.into(), additional_values: Vec::new() }
    }
}

/// A `trafficSign`. The readers assert that every sign is referenced by at least one lanelet.
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficSign {
    pub id: TrafficSignId,
    /// At least one (XSD); `validate()` reports an empty list.
    pub elements: Vec<TrafficSignElement>,
    /// Without a position the readers place the sign on the first referencing lanelet.
    pub position: Option<Point>,
    /// Written as `<virtual>`; note the readers ignore it (they look for an attribute).
    pub is_virtual: bool,
}

str_enum!(
    /// Colour of a traffic-light cycle phase.
    TrafficLightColor {
        Red => "red",
        RedYellow => "redYellow",
        Green => "green",
        Yellow => "yellow",
        Inactive => "inactive",
    }
);

str_enum!(
    /// Which turns a traffic light controls.
    TrafficLightDirection {
        Right => "right",
        Straight => "straight",
        Left => "left",
        LeftStraight => "leftStraight",
        StraightRight => "straightRight",
        LeftRight => "leftRight",
        All => "all",
    }
);

/// One phase: `duration` time steps (a positive integer) of `color`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CycleElement {
    pub duration: NonZeroU64,
    pub color: TrafficLightColor,
}

/// A `trafficLight`. Without a position, it must be referenced by a lanelet.
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficLight {
    pub id: TrafficLightId,
    /// At least one phase (XSD); `validate()` reports an empty cycle.
    pub cycle: Vec<CycleElement>,
    /// Time steps; written only when > 0 (the XSD type is `positiveInteger`).
    pub time_offset: u64,
    pub position: Option<Point>,
    pub direction: Option<TrafficLightDirection>,
    pub active: Option<bool>,
}
