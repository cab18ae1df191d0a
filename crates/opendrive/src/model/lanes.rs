//! Lane sections, lanes and their records (width, border, road mark, speed).

use super::poly::CubicRecord;
use diagnostic::LineCol;

/// Lane types of OpenDRIVE 1.4–1.8; the raw string is kept in [`Lane::type_raw`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum LaneType {
    None,
    Driving,
    Stop,
    Shoulder,
    Biking,
    Sidewalk,
    Walking,
    Border,
    Restricted,
    Parking,
    Bidirectional,
    Median,
    Curb,
    Entry,
    Exit,
    OnRamp,
    OffRamp,
    ConnectingRamp,
    MwyEntry,
    MwyExit,
    SlipLane,
    Special1,
    Special2,
    Special3,
    RoadWorks,
    Tram,
    Rail,
    Bus,
    Taxi,
    Hov,
    /// Not a value of the standard.
    Other,
}

impl LaneType {
    /// Parse the `type` attribute (case-insensitive, as esmini does).
    pub fn parse(raw: &str) -> LaneType {
        match raw.to_ascii_lowercase().as_str() {
            "none" => LaneType::None,
            "driving" => LaneType::Driving,
            "stop" => LaneType::Stop,
            "shoulder" => LaneType::Shoulder,
            "biking" => LaneType::Biking,
            "sidewalk" => LaneType::Sidewalk,
            "walking" => LaneType::Walking,
            "border" => LaneType::Border,
            "restricted" => LaneType::Restricted,
            "parking" => LaneType::Parking,
            "bidirectional" => LaneType::Bidirectional,
            "median" => LaneType::Median,
            "curb" => LaneType::Curb,
            "entry" => LaneType::Entry,
            "exit" => LaneType::Exit,
            "onramp" => LaneType::OnRamp,
            "offramp" => LaneType::OffRamp,
            "connectingramp" => LaneType::ConnectingRamp,
            "mwyentry" => LaneType::MwyEntry,
            "mwyexit" => LaneType::MwyExit,
            "sliplane" => LaneType::SlipLane,
            "special1" => LaneType::Special1,
            "special2" => LaneType::Special2,
            "special3" => LaneType::Special3,
            "roadworks" => LaneType::RoadWorks,
            "tram" => LaneType::Tram,
            "rail" => LaneType::Rail,
            "bus" => LaneType::Bus,
            "taxi" => LaneType::Taxi,
            "hov" => LaneType::Hov,
            _ => LaneType::Other,
        }
    }

    /// Whether vehicles drive on a lane of this type: esmini's "any driving" set
    /// (`LANE_TYPE_ANY_DRIVING`: driving, entry, exit, on- and off-ramp, connecting ramp,
    /// bidirectional; `mwyEntry`/`mwyExit` are its entry and exit).
    pub fn is_any_driving(self) -> bool {
        matches!(
            self,
            LaneType::Driving
                | LaneType::Entry
                | LaneType::Exit
                | LaneType::OnRamp
                | LaneType::OffRamp
                | LaneType::ConnectingRamp
                | LaneType::MwyEntry
                | LaneType::MwyExit
                | LaneType::Bidirectional
        )
    }
}

/// Road mark types of `<roadMark type=...>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum RoadMarkType {
    None,
    Solid,
    Broken,
    SolidSolid,
    SolidBroken,
    BrokenSolid,
    BrokenBroken,
    BottsDots,
    Grass,
    Curb,
    Custom,
    Edge,
    Other,
}

impl RoadMarkType {
    /// Parse the `type` attribute (case-insensitive; `"solid solid"` with a space).
    pub fn parse(raw: &str) -> RoadMarkType {
        match raw.to_ascii_lowercase().as_str() {
            "none" => RoadMarkType::None,
            "solid" => RoadMarkType::Solid,
            "broken" => RoadMarkType::Broken,
            "solid solid" => RoadMarkType::SolidSolid,
            "solid broken" => RoadMarkType::SolidBroken,
            "broken solid" => RoadMarkType::BrokenSolid,
            "broken broken" => RoadMarkType::BrokenBroken,
            "botts dots" => RoadMarkType::BottsDots,
            "grass" => RoadMarkType::Grass,
            "curb" => RoadMarkType::Curb,
            "custom" => RoadMarkType::Custom,
            "edge" => RoadMarkType::Edge,
            _ => RoadMarkType::Other,
        }
    }
}

/// `laneChange` of a road mark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum LaneChange {
    Increase,
    Decrease,
    Both,
    None,
}

/// `<roadMark>` on the outer border of a lane (centre lane: on the lane-offset line).
#[derive(Debug, Clone, PartialEq)]
pub struct RoadMark {
    /// Start relative to the lane section start.
    pub s_offset: f64,
    pub kind: RoadMarkType,
    pub type_raw: String,
    pub weight: Option<String>,
    pub color: Option<String>,
    pub material: Option<String>,
    pub width: Option<f64>,
    pub height: Option<f64>,
    pub lane_change: Option<LaneChange>,
    /// Lines its `<type>` and `<explicit>` children define (0: none, the type's stand-in lines).
    pub lines: usize,
}

/// `<lane><speed>`.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneSpeed {
    pub s_offset: f64,
    pub max_mps: Option<f64>,
    pub max_raw: String,
    pub unit: Option<String>,
}

/// `<lane><height>`: the lane's surface raised above the road (a kerb, a raised sidewalk),
/// `inner` m at its inner border and `outer` m at its outer one, from `s_offset` (relative to
/// the section start) on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneHeight {
    pub s_offset: f64,
    pub inner: f64,
    pub outer: f64,
}

/// One lane of a lane section.
#[derive(Debug, Clone, PartialEq)]
pub struct Lane {
    /// Positive left of the reference line, 0 centre, negative right.
    pub id: i32,
    pub kind: LaneType,
    pub type_raw: String,
    /// `level="true"`: lane kept level (no superelevation).
    pub level: bool,
    /// Lane ids linked in the previous section / road (usually 0 or 1 entry).
    pub predecessors: Vec<i32>,
    /// Lane ids linked in the next section / road (usually 0 or 1 entry).
    pub successors: Vec<i32>,
    /// Width records, `s` = sOffset relative to the section start, sorted.
    pub widths: Vec<CubicRecord>,
    /// Border records (used only when there are no width records, as the standard says).
    pub borders: Vec<CubicRecord>,
    pub road_marks: Vec<RoadMark>,
    pub speeds: Vec<LaneSpeed>,
    /// Height records, sorted by `s_offset` (equal ones in file order).
    pub heights: Vec<LaneHeight>,
    pub pos: LineCol,
}

impl Lane {
    /// The lane's height above the road at `ds` from its section's start, `offset` m from its
    /// centre (+ left of the reference line), the lane `width` m wide there; 0 without height
    /// records. As esmini's Lane::GetHeightBySAndOffset: the record at `ds` (the first one before
    /// it starts), inner and outer heights interpolated linearly towards the next record (and
    /// extrapolated before the first), then across the lane from its inner border (0) to its
    /// outer one (1), clamped to the lane.
    pub fn height_at(&self, ds: f64, offset: f64, width: f64) -> f64 {
        const SMALL_NUMBER: f64 = 1e-10;
        let Some(first) = self.heights.first() else { return 0.0 };
        let i = self.heights.iter().position(|h| ds < h.s_offset - SMALL_NUMBER).unwrap_or(self.heights.len());
        let i = i.saturating_sub(1);
        let h = self.heights.get(i).unwrap_or(first);
        let (mut inner, mut outer) = (h.inner, h.outer);
        if let Some(next) = self.heights.get(i + 1) {
            let f = (ds - h.s_offset) / (next.s_offset - h.s_offset);
            inner += f * (next.inner - h.inner);
            outer += f * (next.outer - h.outer);
        }
        let across = if width > 0.0 { ((offset * f64::from(self.id.signum()) + 0.5 * width) / width).clamp(0.0, 1.0) } else { 0.0 };
        inner + across * (outer - inner)
    }
}

/// A lane section: lanes valid from `s` to the next section (or the road end).
#[derive(Debug, Clone, PartialEq)]
pub struct LaneSection {
    pub s: f64,
    pub single_side: Option<bool>,
    /// Left lanes sorted by id ascending (1, 2, 3, ... outward).
    pub left: Vec<Lane>,
    /// The centre lane (id 0), if present.
    pub center: Option<Lane>,
    /// Right lanes sorted by id descending (-1, -2, ... outward).
    pub right: Vec<Lane>,
    pub pos: LineCol,
}

impl LaneSection {
    /// The lane with `id`, if any.
    pub fn lane(&self, id: i32) -> Option<&Lane> {
        match id {
            0 => self.center.as_ref(),
            i if i > 0 => self.left.iter().find(|l| l.id == i),
            i => self.right.iter().find(|l| l.id == i),
        }
    }
    /// All lanes left (outermost first), centre, right (innermost first): left-to-right order.
    pub fn lanes_left_to_right(&self) -> impl Iterator<Item = &Lane> {
        self.left.iter().rev().chain(self.center.iter()).chain(self.right.iter())
    }
}
