//! A `<road>`: identity, links, type records, reference line, profiles, lanes, objects, signals.

use super::lanes::LaneSection;
use super::objects::Object;
use super::poly::CubicRecord;
use super::signals::{Signal, SignalReference};
use crate::geometry::Geometry;
use diagnostic::LineCol;

/// Traffic rule of a road (`rule` attribute); right-hand traffic when absent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub enum TrafficRule {
    #[default]
    RightHand,
    LeftHand,
}

/// Which kind of element a link points to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ElementType {
    Road,
    Junction,
}

/// The end of a road a link attaches to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ContactPoint {
    Start,
    End,
}

impl ContactPoint {
    /// The other end.
    pub fn opposite(self) -> ContactPoint {
        match self {
            ContactPoint::Start => ContactPoint::End,
            ContactPoint::End => ContactPoint::Start,
        }
    }
}

/// `elementDir` of a link into a virtual/direct junction element (`+` or `-`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ElementDir {
    Plus,
    Minus,
}

/// `<road><link><predecessor|successor>`.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadLink {
    pub element_type: ElementType,
    pub element_id: String,
    /// Required for roads, absent for junctions.
    pub contact_point: Option<ContactPoint>,
    pub element_s: Option<f64>,
    pub element_dir: Option<ElementDir>,
}

/// Road type classes of `<road><type type=...>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum RoadKind {
    Unknown,
    Rural,
    Motorway,
    Town,
    LowSpeed,
    Pedestrian,
    Bicycle,
    TownExpressway,
    TownCollector,
    TownArterial,
    TownPrivate,
    TownLocal,
    TownPlayStreet,
    /// A value not in the standard; the raw string is kept in [`RoadTypeRecord::raw`].
    Other,
}

impl RoadKind {
    /// Parse the `type` attribute (case-insensitive).
    pub fn parse(raw: &str) -> RoadKind {
        match raw.to_ascii_lowercase().as_str() {
            "unknown" => RoadKind::Unknown,
            "rural" => RoadKind::Rural,
            "motorway" => RoadKind::Motorway,
            "town" => RoadKind::Town,
            "lowspeed" => RoadKind::LowSpeed,
            "pedestrian" => RoadKind::Pedestrian,
            "bicycle" => RoadKind::Bicycle,
            "townexpressway" => RoadKind::TownExpressway,
            "towncollector" => RoadKind::TownCollector,
            "townarterial" => RoadKind::TownArterial,
            "townprivate" => RoadKind::TownPrivate,
            "townlocal" => RoadKind::TownLocal,
            "townplaystreet" => RoadKind::TownPlayStreet,
            _ => RoadKind::Other,
        }
    }
}

/// A speed limit (`<speed max= unit=>`).
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedLimit {
    /// Limit in m/s; `None` for "no limit" / "undefined".
    pub max_mps: Option<f64>,
    /// The `max` attribute as written.
    pub max_raw: String,
    /// The `unit` attribute as written (`m/s`, `km/h`, `mph`); m/s when absent.
    pub unit: Option<String>,
}

/// `<road><type>`: road class from `s` on.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadTypeRecord {
    pub s: f64,
    pub kind: RoadKind,
    pub raw: String,
    pub country: Option<String>,
    pub speed: Option<SpeedLimit>,
}

/// One OpenDRIVE road.
#[derive(Debug, Clone)]
pub struct Road {
    pub id: String,
    pub name: String,
    pub length: f64,
    /// Id of the junction this road belongs to; `None` for `-1` or absent.
    pub junction: Option<String>,
    pub rule: TrafficRule,
    pub types: Vec<RoadTypeRecord>,
    pub predecessor: Option<RoadLink>,
    pub successor: Option<RoadLink>,
    /// Plan-view geometries sorted by `s`.
    pub geometries: Vec<Geometry>,
    /// Elevation records (absolute s).
    pub elevation: Vec<CubicRecord>,
    /// Superelevation records (absolute s): the road's roll. The engine applies it; this crate's
    /// 2D geometry (lane borders, OSI points) lays lateral offsets flat.
    pub superelevation: Vec<CubicRecord>,
    /// Lane offset records (absolute s).
    pub lane_offsets: Vec<CubicRecord>,
    /// Lane sections sorted by `s`; at least one.
    pub lane_sections: Vec<LaneSection>,
    pub objects: Vec<Object>,
    pub signals: Vec<Signal>,
    pub signal_references: Vec<SignalReference>,
    /// Where `<road>` starts in the file.
    pub pos: LineCol,
    /// The s of lane 0's OSI points, worked out on first use ([`Road::lane0_osi_s`]): a
    /// network shared by many runs (a batch, a bench) samples each road once.
    pub lane0_osi: std::sync::OnceLock<Vec<f64>>,
    /// Whether some lane has height records, worked out on first use ([`Road::has_raised_lanes`]).
    pub raised_lanes: std::sync::OnceLock<bool>,
}

impl Road {
    /// Whether some lane of the road has `<height>` records (a kerb, a raised sidewalk): the
    /// question every lane position asks, answered once.
    pub fn has_raised_lanes(&self) -> bool {
        *self.raised_lanes.get_or_init(|| self.lane_sections.iter().any(|sec| sec.lanes_left_to_right().any(|l| !l.heights.is_empty())))
    }

    /// Road type record in force at `s` (last with `record.s <= s`, else the first).
    pub fn type_at(&self, s: f64) -> Option<&RoadTypeRecord> {
        let i = self.types.partition_point(|t| t.s <= s);
        self.types.get(i.saturating_sub(1))
    }
    /// The link at one end: `Start` → predecessor, `End` → successor.
    pub fn link_at(&self, end: ContactPoint) -> Option<&RoadLink> {
        match end {
            ContactPoint::Start => self.predecessor.as_ref(),
            ContactPoint::End => self.successor.as_ref(),
        }
    }
}
