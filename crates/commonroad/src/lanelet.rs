//! Lanelets: two bounds with equal point counts (enforced by [`LaneletBounds`]), topology,
//! stop line, types, users and traffic-control references.

use crate::error::{finite, Error};
use crate::geometry::Point;
use crate::ids::{LaneletId, TrafficLightId, TrafficSignId};
use crate::str_enum::str_enum;

str_enum!(
    /// `lineMarking` of a bound or stop line.
    LineMarking {
        Dashed => "dashed",
        Solid => "solid",
        SolidSolid => "solid_solid",
        DashedDashed => "dashed_dashed",
        SolidDashed => "solid_dashed",
        DashedSolid => "dashed_solid",
        Curb => "curb",
        LoweredCurb => "lowered_curb",
        BroadDashed => "broad_dashed",
        BroadSolid => "broad_solid",
        Unknown => "unknown",
        NoMarking => "no_marking",
    }
);

str_enum!(
    /// `laneletType`.
    LaneletType {
        Urban => "urban",
        Interstate => "interstate",
        Country => "country",
        Highway => "highway",
        Sidewalk => "sidewalk",
        Crosswalk => "crosswalk",
        BusLane => "busLane",
        BicycleLane => "bicycleLane",
        ExitRamp => "exitRamp",
        MainCarriageWay => "mainCarriageWay",
        AccessRamp => "accessRamp",
        Shoulder => "shoulder",
        DriveWay => "driveWay",
        BusStop => "busStop",
        Intersection => "intersection",
        Border => "border",
        Parking => "parking",
        Restricted => "restricted",
        RestrictedArea => "restricted_area",
        Unknown => "unknown",
    }
);

str_enum!(
    /// Road users of `userOneWay` / `userBidirectional` (XSD `vehicleType`).
    RoadUser {
        Vehicle => "vehicle",
        Car => "car",
        Truck => "truck",
        Bus => "bus",
        Motorcycle => "motorcycle",
        Bicycle => "bicycle",
        Pedestrian => "pedestrian",
        PriorityVehicle => "priorityVehicle",
        Train => "train",
        Taxi => "taxi",
    }
);

str_enum!(
    /// Driving direction of an adjacent lanelet relative to this one.
    DrivingDir {
        Same => "same",
        Opposite => "opposite",
    }
);

/// Left and right bound of a lanelet. The only constructor checks what the readers need:
/// the same number of points on both sides (commonroad-io computes the centre line point by
/// point), at least two, all finite. Driving direction = point order.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneletBounds {
    left: Vec<Point>,
    right: Vec<Point>,
}

impl LaneletBounds {
    /// Fails if the counts differ, a side has fewer than 2 points, or a coordinate is not finite.
    pub fn new(left: Vec<Point>, right: Vec<Point>) -> Result<Self, Error> {
        if left.len() != right.len() {
            return Err(Error::BoundPointCountMismatch { left: left.len(), right: right.len() });
        }
        if left.len() < 2 {
            return Err(Error::TooFewBoundPoints { got: left.len() });
        }
        for p in left.iter().chain(&right) {
            finite("bound point x", p.x)?;
            finite("bound point y", p.y)?;
            if let Some(z) = p.z {
                finite("bound point z", z)?;
            }
        }
        Ok(Self { left, right })
    }
    pub fn left(&self) -> &[Point] {
        &self.left
    }
    pub fn right(&self) -> &[Point] {
        &self.right
    }
    /// Points per side (>= 2).
    pub fn len(&self) -> usize {
        self.left.len()
    }
    /// Always false (kept for clippy's `len_without_is_empty`).
    pub fn is_empty(&self) -> bool {
        self.left.is_empty()
    }
}

/// `adjacentLeft` / `adjacentRight`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Adjacent {
    pub lanelet: LaneletId,
    pub driving_dir: DrivingDir,
}

/// `stopLine`. Without `points` the readers use the lanelet's last left/right points.
#[derive(Debug, Clone, PartialEq)]
pub struct StopLine {
    pub points: Option<[Point; 2]>,
    pub line_marking: LineMarking,
    pub traffic_sign_refs: Vec<TrafficSignId>,
    pub traffic_light_refs: Vec<TrafficLightId>,
}

/// A `lanelet`. Build with [`Lanelet::new`], then fill the public fields.
#[derive(Debug, Clone, PartialEq)]
pub struct Lanelet {
    pub id: LaneletId,
    pub bounds: LaneletBounds,
    /// `None` = unknown (not written).
    pub left_marking: Option<LineMarking>,
    pub right_marking: Option<LineMarking>,
    pub predecessors: Vec<LaneletId>,
    pub successors: Vec<LaneletId>,
    pub adjacent_left: Option<Adjacent>,
    pub adjacent_right: Option<Adjacent>,
    pub stop_line: Option<StopLine>,
    /// At least one (XSD); `validate()` reports an empty list. Written in this order.
    pub lanelet_types: Vec<LaneletType>,
    pub user_one_way: Vec<RoadUser>,
    pub user_bidirectional: Vec<RoadUser>,
    pub traffic_sign_refs: Vec<TrafficSignId>,
    pub traffic_light_refs: Vec<TrafficLightId>,
}

impl Lanelet {
    /// A lanelet with one type and no markings, neighbours or references.
    pub fn new(id: LaneletId, bounds: LaneletBounds, lanelet_type: LaneletType) -> Self {
        Self {
            id,
            bounds,
            left_marking: None,
            right_marking: None,
            predecessors: Vec::new(),
            successors: Vec::new(),
            adjacent_left: None,
            adjacent_right: None,
            stop_line: None,
            lanelet_types: vec![lanelet_type],
            user_one_way: Vec::new(),
            user_bidirectional: Vec::new(),
            traffic_sign_refs: Vec::new(),
            traffic_light_refs: Vec::new(),
        }
    }
}
