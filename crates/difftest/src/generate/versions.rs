//! How each OpenSCENARIO version spells what the generator writes. A production draws as for
//! 1.3 (the same draws in every version, so a scenario's other parts do not move) and writes
//! the words of the file's own version, as users' older files have them: `overwrite` before
//! 1.2, the 1.0 rules, `cartesianDistance` and `alongRoute`, no `world` coordinate system
//! before 1.3, the weather's older attributes. What an older schema has no words for still
//! makes the scenario fall back to 1.3 (`generate`).

use super::Gen;

impl Gen<'_> {
    /// Whether the file's version has what came with 1.`minor` (an attribute drawn for a
    /// version without it is left out: the reader's default then applies, as in a file of
    /// that version).
    pub(crate) fn since(&self, minor: u32) -> bool {
        self.rev_minor >= minor
    }

    /// A comparison rule: 1.0 has only greaterThan, lessThan and equalTo, so the inclusive rules
    /// become the strict ones (a step later or earlier at most) and notEqualTo greaterThan.
    pub(crate) fn rule_word(&self, rule: &'static str) -> &'static str {
        if self.rev_minor > 0 {
            return rule;
        }
        match rule {
            "greaterOrEqual" | "notEqualTo" => "greaterThan",
            "lessOrEqual" => "lessThan",
            r => r,
        }
    }

    /// An event's priority: `override` is 1.2's word for 1.0's `overwrite`.
    pub(crate) fn priority_word(&mut self, priority: &'static str) -> &'static str {
        if priority == "override" && self.rev_minor < 2 {
            self.feature("priority:overwrite");
            return "overwrite";
        }
        priority
    }

    /// The euclidean relative distance type: `cartesianDistance` in 1.0.
    pub(crate) fn distance_type_word(&mut self, t: &'static str) -> &'static str {
        if t == "euclidianDistance" && self.rev_minor == 0 {
            self.feature("relative-distance-type:cartesianDistance");
            return "cartesianDistance";
        }
        t
    }

    /// A coordinate system: `world` came with 1.3; before, the euclidean distance it goes with
    /// is measured in the entity system (esmini's Position::Distance takes the euclidean
    /// distance whatever the system).
    pub(crate) fn coordinate_system_word(&self, cs: &'static str) -> &'static str {
        if cs == "world" && self.rev_minor < 3 {
            return "entity";
        }
        cs
    }

    /// An EnvironmentAction's Weather: 1.2 and earlier give the sun's `intensity`, 1.0 the
    /// cloud state and the precipitation's `intensity`.
    pub(crate) fn weather(&self) -> &'static str {
        match self.rev_minor {
            0 => {
                r#"<Weather cloudState="free"><Sun azimuth="0" elevation="1.2" intensity="90000"/><Fog visualRange="100000"/><Precipitation precipitationType="dry" intensity="0"/></Weather>"#
            }
            1 | 2 => {
                r#"<Weather><Sun azimuth="0" elevation="1.2" intensity="90000"/><Fog visualRange="100000"/><Precipitation precipitationType="dry" precipitationIntensity="0"/></Weather>"#
            }
            _ => {
                r#"<Weather fractionalCloudCover="zeroOktas"><Sun azimuth="0" elevation="1.2" illuminance="90000"/><Fog visualRange="100000"/><Precipitation precipitationType="dry" precipitationIntensity="0"/></Weather>"#
            }
        }
    }

    /// A Pedestrian's `model`, required in 1.0 only.
    pub(crate) fn pedestrian_model(&self) -> &'static str {
        if self.rev_minor == 0 {
            r#" model="walker""#
        } else {
            ""
        }
    }
}
