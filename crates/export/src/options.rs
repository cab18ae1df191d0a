//! What an export is asked for: the OpenSCENARIO version to write, who drives the ego, and
//! whether reaching the goal ends the run.

use std::fmt;
use std::str::FromStr;

use serde::Serialize;

/// The OpenSCENARIO version written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub enum OscVersion {
    /// 1.0, for simulators that read only 1.0 (CARLA's scenario_runner): only 1.0 constructs.
    #[serde(rename = "1.0")]
    V1_0,
    /// 1.3 (the default).
    #[default]
    #[serde(rename = "1.3")]
    V1_3,
}

impl OscVersion {
    /// `revMinor` of the FileHeader.
    pub fn minor(self) -> u32 {
        match self {
            OscVersion::V1_0 => 0,
            OscVersion::V1_3 => 3,
        }
    }
}

impl FromStr for OscVersion {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim() {
            "1.0" | "1" => Ok(OscVersion::V1_0),
            "1.3" => Ok(OscVersion::V1_3),
            other => Err(format!("OpenSCENARIO version {other:?}: expected 1.3 or 1.0")),
        }
    }
}

impl fmt::Display for OscVersion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "1.{}", self.minor())
    }
}

/// Who drives the ego.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EgoController {
    /// The simulator's default controller: the ego keeps its lane and its initial speed.
    #[default]
    Default,
    /// An outside driver: an `ExternalController` (esmini's name), activated in the Init.
    External,
}

impl FromStr for EgoController {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim() {
            "default" => Ok(EgoController::Default),
            "external" => Ok(EgoController::External),
            other => Err(format!("ego controller {other:?}: expected default or external")),
        }
    }
}

/// How a scenario is exported.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize)]
pub struct ExportOptions {
    pub osc: OscVersion,
    pub ego_controller: EgoController,
    /// Run until every obstacle's trajectory and every goal's time window are over, even after
    /// the egos reached their goals (a full replay). By default reaching the goal ends the run.
    pub play_to_end: bool,
}
