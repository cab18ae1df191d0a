//! Intersections: incomings with their successors sorted into right / straight / left.

use crate::ids::{IncomingId, IntersectionId, LaneletId};

/// `intersection/incoming`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Incoming {
    pub id: IncomingId,
    /// At least one (XSD).
    pub incoming_lanelets: Vec<LaneletId>,
    pub successors_right: Vec<LaneletId>,
    pub successors_straight: Vec<LaneletId>,
    pub successors_left: Vec<LaneletId>,
    /// The incoming this one is left of.
    pub is_left_of: Option<IncomingId>,
}

/// `intersection`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Intersection {
    pub id: IntersectionId,
    /// At least one (XSD).
    pub incomings: Vec<Incoming>,
    /// Each crossing lists at least one lanelet.
    pub crossings: Vec<Vec<LaneletId>>,
}

impl Incoming {
    /// The incoming's lanelet lists by their 2020a XML element names, in the XSD's order: what
    /// the writer emits and the validator checks, one list at a time.
    pub fn lanelet_groups(&self) -> [(&'static str, &[LaneletId]); 4] {
        [
            ("incomingLanelet", &self.incoming_lanelets),
            ("successorsRight", &self.successors_right),
            ("successorsStraight", &self.successors_straight),
            ("successorsLeft", &self.successors_left),
        ]
    }
}
