//! Junctions (default, direct, virtual) and signal controllers.

use super::road::ContactPoint;

/// `<junction type=...>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub enum JunctionType {
    #[default]
    Default,
    Direct,
    Virtual,
    Crossing,
}

/// `<laneLink from to>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LaneLink {
    pub from: i32,
    pub to: i32,
}

/// `<connection>`: incoming road → connecting road (default) or linked road (direct).
#[derive(Debug, Clone, PartialEq)]
pub struct Connection {
    pub id: String,
    pub incoming_road: Option<String>,
    pub connecting_road: Option<String>,
    pub linked_road: Option<String>,
    /// Contact point on the connecting (or linked) road.
    pub contact_point: Option<ContactPoint>,
    pub lane_links: Vec<LaneLink>,
}

impl Connection {
    /// The road the connection leads into: `connectingRoad`, else `linkedRoad`.
    pub fn target_road(&self) -> Option<&str> {
        self.connecting_road.as_deref().or(self.linked_road.as_deref())
    }
}

/// `<junction><controller id type sequence>`.
#[derive(Debug, Clone, PartialEq)]
pub struct JunctionController {
    pub id: String,
    pub kind: Option<String>,
    pub sequence: Option<u32>,
}

/// A junction.
#[derive(Debug, Clone, PartialEq)]
pub struct Junction {
    pub id: String,
    pub name: Option<String>,
    pub kind: JunctionType,
    pub connections: Vec<Connection>,
    pub controllers: Vec<JunctionController>,
}

/// `<control signalId type>` of a controller.
#[derive(Debug, Clone, PartialEq)]
pub struct Control {
    pub signal_id: String,
    pub kind: Option<String>,
}

/// Top-level `<controller>`: signals switched together.
#[derive(Debug, Clone, PartialEq)]
pub struct Controller {
    pub id: String,
    pub name: Option<String>,
    pub sequence: Option<u32>,
    pub controls: Vec<Control>,
}
