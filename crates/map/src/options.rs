//! What the caller can tune, and what a conversion returns.

use commonroad::{LaneletId, LaneletNetwork, TrafficLightId};
use diagnostic::Diagnostic;
use opendrive::LaneRef;
use std::collections::BTreeMap;

/// Conversion settings.
#[derive(Debug, Clone, PartialEq)]
pub struct MapOptions {
    /// Largest distance (m) allowed between a bound polyline and the exact lane border.
    pub tolerance: f64,
    /// Country assumed for signals that name none (ISO alpha-2/3 or OpenDRIVE spelling);
    /// `None` = Germany, the convention of most OpenDRIVE tools.
    pub default_country: Option<String>,
    /// Time steps per phase of the default traffic-light cycle (red, redYellow, green, yellow)
    /// — OpenDRIVE has no timing, so every light gets this one.
    pub light_cycle: [u64; 4],
}

impl Default for MapOptions {
    fn default() -> Self {
        // 0.5 cm leaves margin below the 1 cm promised (checks are at sample points only).
        Self { tolerance: 0.005, default_country: None, light_cycle: [200, 20, 200, 30] }
    }
}

/// Where a lanelet came from: one lane of one lane section, and its driving direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct LaneletOrigin {
    pub lane: LaneRef,
    /// Whether traffic drives along +s (points are in s order) or against it (reversed).
    pub along_s: bool,
}

/// The converted map: the CommonRoad lanelet network and what happened on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct MapResult {
    pub network: LaneletNetwork,
    /// Origin of each lanelet, parallel to `network.lanelets`.
    pub origins: Vec<LaneletOrigin>,
    /// Lanelet of each converted (road, section, lane).
    pub lanelet_of: BTreeMap<LaneRef, LaneletId>,
    /// The traffic light made of each OpenDRIVE signal id (dropped signals are absent).
    pub light_of_signal: BTreeMap<String, TrafficLightId>,
    pub warnings: Vec<Diagnostic>,
}
