//! Rules the XSD cannot express: value ranges of the standard, and deprecated attributes that must
//! not be combined with what replaced them.

use std::sync::OnceLock;

/// A value range of the ASAM OpenSCENARIO 1.3 standard: `attribute op bound` on a complex type.
/// The table (`range_rules.tsv`) records the ranges the ASAM OpenSCENARIO API checks.
pub(super) struct RangeRule {
    pub type_name: &'static str,
    pub attribute: &'static str,
    pub op: &'static str,
    pub bound: f64,
    pub bound_text: &'static str,
}

pub(super) fn range_rules() -> &'static [RangeRule] {
    static RULES: OnceLock<Vec<RangeRule>> = OnceLock::new();
    RULES.get_or_init(|| {
        include_str!("range_rules.tsv")
            .lines()
            .filter(|line| !line.starts_with('#'))
            .filter_map(|line| {
                let mut f = line.split('\t');
                let (type_name, attribute, op, bound_text) = (f.next()?, f.next()?, f.next()?, f.next()?);
                let bound = if bound_text == "M_PI" { std::f64::consts::PI } else { bound_text.parse().ok()? };
                let bound_text = if bound_text == "M_PI" { "π" } else { bound_text };
                Some(RangeRule { type_name, attribute, op, bound, bound_text })
            })
            .collect()
    })
}

impl RangeRule {
    pub(super) fn holds(&self, v: f64) -> bool {
        match self.op {
            ">=" => v >= self.bound,
            "<=" => v <= self.bound,
            ">" => v > self.bound,
            "<" => v < self.bound,
            _ => true,
        }
    }
}

/// Ranges that published, working scenarios leave, and that esmini reads with a meaning (or does
/// not read): outside them is a warning, not an error. The ASAM 1.2 examples write negative
/// SpeedActionDynamics rates for decelerations; esmini's catalogs write maxSteering in degrees
/// (esmini does not use it); a clothoid's curvature may fall (negative curvatureDot).
pub(super) const LENIENT_RANGES: &[(&str, &str)] = &[
    ("TransitionDynamics", "value"),
    ("Axle", "maxSteering"),
    ("Clothoid", "curvatureDot"),
    ("Clothoid", "curvaturePrime"),
    ("Weather", "atmosphericPressure"),
    ("OverrideClutchAction", "value"),
];

/// What replaced a deprecated attribute: an attribute, or one of some child elements.
pub(super) enum Replacement {
    Attribute(&'static str),
    Elements(&'static [&'static str]),
}

/// Deprecated attributes and their replacements (OpenSCENARIO 1.1–1.3 annotations). Writing both
/// is contradictory: which one holds?
pub(super) const DEPRECATED_WITH_REPLACEMENT: &[(&str, &str, Replacement)] = &[
    ("Weather", "cloudState", Replacement::Attribute("fractionalCloudCover")),
    ("Sun", "intensity", Replacement::Attribute("illuminance")),
    ("Precipitation", "intensity", Replacement::Attribute("precipitationIntensity")),
    ("GeoPosition", "height", Replacement::Attribute("altitude")),
    ("GeoPosition", "latitude", Replacement::Attribute("latitudeDeg")),
    ("GeoPosition", "longitude", Replacement::Attribute("longitudeDeg")),
    ("OverrideBrakeAction", "value", Replacement::Elements(&["BrakePercent", "BrakeForce"])),
    ("OverrideParkingBrakeAction", "value", Replacement::Elements(&["BrakePercent", "BrakeForce"])),
    ("OverrideGearAction", "number", Replacement::Elements(&["ManualGear", "AutomaticGear"])),
    ("TrafficSourceAction", "velocity", Replacement::Attribute("speed")),
    ("TrafficSwarmAction", "velocity", Replacement::Elements(&["InitialSpeedRange"])),
    ("Clothoid", "curvatureDot", Replacement::Attribute("curvaturePrime")),
    ("DistanceCondition", "alongRoute", Replacement::Attribute("coordinateSystem")),
    ("DistanceCondition", "alongRoute", Replacement::Attribute("relativeDistanceType")),
    ("RelativeDistanceCondition", "alongRoute", Replacement::Attribute("coordinateSystem")),
];
