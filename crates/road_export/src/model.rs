//! The OpenDRIVE document as the export builds it: just what the writer needs, in the order
//! it writes it.

use crate::offsets::Cubic;
use opendrive::Geometry;

/// What a road end links to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LinkTarget {
    /// A road, at its start (`true`) or end.
    Road {
        id: u64,
        at_start: bool,
    },
    Junction {
        id: u64,
    },
}

/// A road mark on a lane's outer border.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Mark {
    pub kind: &'static str,
    pub weight: Option<&'static str>,
}

/// One lane of a lane section.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Lane {
    pub id: i32,
    pub kind: &'static str,
    /// The road user an `<access rule="allow">` names (bus lanes).
    pub access: Option<&'static str>,
    pub predecessors: Vec<i32>,
    pub successors: Vec<i32>,
    /// Width records, `s` relative to the section start.
    pub widths: Vec<Cubic>,
    pub mark: Option<Mark>,
}

/// A lane section.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Section {
    pub s: f64,
    /// Lanes 1, 2, … outward.
    pub left: Vec<Lane>,
    pub centre_mark: Option<Mark>,
    /// Lanes −1, −2, … outward.
    pub right: Vec<Lane>,
}

/// `<validity fromLane toLane>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Validity {
    pub from: i32,
    pub to: i32,
}

/// A `<signal>`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Signal {
    pub id: u64,
    pub s: f64,
    pub t: f64,
    pub name: String,
    pub dynamic: bool,
    /// `+`, `-` or `none`.
    pub orientation: &'static str,
    pub country: Option<String>,
    pub kind: String,
    pub subtype: String,
    pub value: Option<(f64, &'static str)>,
    pub validity: Vec<Validity>,
}

/// A `<signalReference>`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SignalReference {
    pub id: u64,
    pub s: f64,
    pub t: f64,
    pub orientation: &'static str,
    pub validity: Vec<Validity>,
}

/// A road.
#[derive(Debug, Clone)]
pub(crate) struct Road {
    pub id: u64,
    pub name: String,
    pub junction: Option<u64>,
    pub lht: bool,
    pub road_type: &'static str,
    pub length: f64,
    pub predecessor: Option<LinkTarget>,
    pub successor: Option<LinkTarget>,
    pub geometries: Vec<Geometry>,
    pub lane_offsets: Vec<Cubic>,
    pub sections: Vec<Section>,
    pub signals: Vec<Signal>,
    pub signal_references: Vec<SignalReference>,
}

/// A junction connection: `target` is the connecting road (default) or linked road (direct).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Connection {
    pub incoming: u64,
    pub target: u64,
    pub target_at_start: bool,
    pub lane_links: Vec<(i32, i32)>,
}

/// A junction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Junction {
    pub id: u64,
    pub name: String,
    pub direct: bool,
    pub connections: Vec<Connection>,
}

/// The document.
#[derive(Debug, Clone, Default)]
pub(crate) struct Document {
    pub name: String,
    pub geo_reference: Option<String>,
    pub roads: Vec<Road>,
    pub junctions: Vec<Junction>,
}
