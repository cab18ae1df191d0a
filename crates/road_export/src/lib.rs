//! `road_export` — a CommonRoad lanelet network as an OpenDRIVE road network.
//!
//! **This is the stand-in of the `xosc-export` branch**, not the map converter of issue 24: it
//! has the seam's exact interface ([`Options`], [`RoadExport`], [`export`]) and the smallest
//! honest implementation, so that `osc2cr export` can be built and tested before the real crate
//! is merged in its place. Each lanelet becomes a one-lane road of its own along its centre
//! line (straight `line` pieces between the centre points, the lane as wide as the lanelet at
//! each point, centred on the line by a lane offset); roads are not linked, there are no
//! junctions and no road marks, and a warning says so. Every traffic light and traffic sign
//! becomes a `<signal>` whose `id` is its CommonRoad id in decimal (the part of the seam the
//! scenario relies on: traffic-signal controllers name lights by that id), on the road of the
//! first lanelet that refers to it.
//!
//! It must not know OpenSCENARIO. Warnings are returned, never printed.

mod geometry;
mod write;

use std::fmt;

use commonroad::LaneletNetwork;

/// How the network is written.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Options {
    /// The header's `name`.
    pub name: String,
    /// The header's `geoReference` (a PROJ string), when the network has one.
    pub geo_reference: Option<String>,
}

/// Something of the network the OpenDRIVE file does not say, or says approximately.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// Why no OpenDRIVE file could be written.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// OpenDRIVE needs at least one road.
    #[error("the lanelet network has no lanelet that can be a road (OpenDRIVE needs at least one road)")]
    NoRoad,
    /// A coordinate that is not a finite number.
    #[error("{0}: not a finite number")]
    NotFinite(String),
}

/// The OpenDRIVE text and what it could not say.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RoadExport {
    pub xodr: String,
    pub warnings: Vec<Warning>,
}

/// The OpenDRIVE road network of `network` (the stand-in writes 1.7; see `write.rs`). Deterministic: the same network and options
/// give the same text.
pub fn export(network: &LaneletNetwork, options: &Options) -> Result<RoadExport, Error> {
    let mut warnings = vec![Warning {
        message: "map written in the stand-in's minimal form: each lanelet a one-lane road of its own along its centre line \
                  (straight pieces), no links between roads, no junctions, no road marks"
            .to_string(),
    }];
    let roads = geometry::roads(network, &mut warnings)?;
    if roads.is_empty() {
        return Err(Error::NoRoad);
    }
    let xodr = write::document(network, &roads, options, &mut warnings)?;
    Ok(RoadExport { xodr, warnings })
}
