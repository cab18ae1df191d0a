//! Every position type of the schema.

use super::{Route, Trajectory};
use serde::Serialize;

crate::xml_enum! {
    ReferenceContext { Relative = "relative", Absolute = "absolute" }
}

/// Orientation; a missing angle is `None` (the standard's default is 0, relative). A missing
/// `type` is read as the file's version makes it (absolute up to 1.2, relative from 1.3, as
/// esmini reads it); `None` only outside a scenario (a catalog read alone).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Orientation {
    pub reference: Option<ReferenceContext>,
    pub h: Option<f64>,
    pub p: Option<f64>,
    pub r: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Position {
    World {
        x: f64,
        y: f64,
        z: Option<f64>,
        h: Option<f64>,
        p: Option<f64>,
        r: Option<f64>,
    },
    RelativeWorld {
        entity: String,
        dx: f64,
        dy: f64,
        dz: Option<f64>,
        orientation: Option<Orientation>,
    },
    RelativeObject {
        entity: String,
        dx: f64,
        dy: f64,
        dz: Option<f64>,
        orientation: Option<Orientation>,
    },
    Road {
        road_id: String,
        s: f64,
        t: f64,
        orientation: Option<Orientation>,
    },
    RelativeRoad {
        entity: String,
        ds: f64,
        dt: f64,
        orientation: Option<Orientation>,
    },
    Lane {
        road_id: String,
        lane_id: i32,
        s: f64,
        offset: f64,
        orientation: Option<Orientation>,
    },
    /// `ds` (along the reference line) or `ds_lane` (along the lane centre, 1.1+).
    RelativeLane {
        entity: String,
        d_lane: i32,
        ds: Option<f64>,
        ds_lane: Option<f64>,
        offset: f64,
        orientation: Option<Orientation>,
    },
    Route {
        route: Box<Route>,
        orientation: Option<Orientation>,
        in_route: InRoutePosition,
    },
    Geo {
        latitude_deg: f64,
        longitude_deg: f64,
        altitude: Option<f64>,
        orientation: Option<Orientation>,
    },
    Trajectory {
        trajectory: Box<Trajectory>,
        s: f64,
        t: Option<f64>,
        orientation: Option<Orientation>,
    },
}

impl Position {
    /// The entity this position is relative to, if any.
    pub fn reference_entity(&self) -> Option<&str> {
        match self {
            Position::RelativeWorld { entity, .. }
            | Position::RelativeObject { entity, .. }
            | Position::RelativeRoad { entity, .. }
            | Position::RelativeLane { entity, .. } => Some(entity),
            _ => None,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum InRoutePosition {
    FromCurrentEntity { entity: String },
    FromRoadCoordinates { path_s: f64, t: f64 },
    FromLaneCoordinates { path_s: f64, lane_id: i32, lane_offset: f64 },
}
