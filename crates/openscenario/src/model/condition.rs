//! Triggers and conditions.

use super::{CoordinateSystem, ObjectType, Origin, Position};
use serde::Serialize;

/// OR over condition groups; a group is an AND over conditions.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Trigger {
    pub groups: Vec<ConditionGroup>,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ConditionGroup {
    pub conditions: Vec<Condition>,
}

crate::xml_enum! {
    ConditionEdge { Rising = "rising", Falling = "falling", RisingOrFalling = "risingOrFalling", None = "none" }
}
crate::xml_enum! {
    Rule {
        GreaterThan = "greaterThan", LessThan = "lessThan", EqualTo = "equalTo",
        GreaterOrEqual = "greaterOrEqual", LessOrEqual = "lessOrEqual", NotEqualTo = "notEqualTo",
    }
}
crate::xml_enum! {
    TriggeringEntitiesRule { Any = "any", All = "all" }
}
crate::xml_enum! {
    RelativeDistanceType {
        Longitudinal = "longitudinal", Lateral = "lateral",
        /// 1.0 `cartesianDistance`, read as euclidean.
        EuclidianDistance = "euclidianDistance" | "cartesianDistance",
    }
}
crate::xml_enum! {
    RoutingAlgorithm {
        AssignedRoute = "assignedRoute", Fastest = "fastest", LeastIntersections = "leastIntersections",
        Shortest = "shortest", Undefined = "undefined",
    }
}
crate::xml_enum! {
    DirectionalDimension { Longitudinal = "longitudinal", Lateral = "lateral", Vertical = "vertical" }
}
crate::xml_enum! {
    AngleType { Heading = "heading", Pitch = "pitch", Roll = "roll" }
}
crate::xml_enum! {
    StoryboardElementType {
        Story = "story", Act = "act", Maneuver = "maneuver", Event = "event", Action = "action",
        ManeuverGroup = "maneuverGroup",
    }
}
crate::xml_enum! {
    StoryboardElementState {
        StartTransition = "startTransition", EndTransition = "endTransition", StopTransition = "stopTransition",
        SkipTransition = "skipTransition", CompleteState = "completeState", RunningState = "runningState",
        StandbyState = "standbyState",
    }
}

impl Rule {
    /// `a rule b`, with a small tolerance for equality as floating-point values rarely match.
    pub fn compare(self, a: f64, b: f64) -> bool {
        const EPS: f64 = 1e-9;
        match self {
            Rule::GreaterThan => a > b,
            Rule::LessThan => a < b,
            Rule::EqualTo => (a - b).abs() <= EPS,
            Rule::GreaterOrEqual => a >= b,
            Rule::LessOrEqual => a <= b,
            Rule::NotEqualTo => (a - b).abs() > EPS,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Condition {
    pub name: String,
    pub delay: f64,
    pub edge: ConditionEdge,
    pub kind: ConditionKind,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ConditionKind {
    ByEntity {
        rule: TriggeringEntitiesRule,
        entities: Vec<String>,
        condition: EntityCondition,
    },
    ByValue(ValueCondition),
    /// An element the model does not represent yet (also a load warning).
    Unsupported {
        element: String,
    },
}

/// Distance measurement options shared by several conditions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DistanceOptions {
    pub freespace: bool,
    pub coordinate_system: Option<CoordinateSystem>,
    pub relative_distance_type: Option<RelativeDistanceType>,
    pub routing_algorithm: Option<RoutingAlgorithm>,
    /// 1.0 `alongRoute` (deprecated): true means road coordinates.
    pub along_route: Option<bool>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum CollisionTarget {
    Entity(String),
    ByType(ObjectType),
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum TtcTarget {
    Entity(String),
    Position(Position),
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum EntityCondition {
    EndOfRoad {
        duration: f64,
    },
    Collision {
        target: CollisionTarget,
    },
    Offroad {
        duration: f64,
    },
    TimeHeadway {
        entity: String,
        value: f64,
        rule: Rule,
        options: DistanceOptions,
    },
    TimeToCollision {
        target: TtcTarget,
        value: f64,
        rule: Rule,
        options: DistanceOptions,
    },
    Acceleration {
        value: f64,
        rule: Rule,
        direction: Option<DirectionalDimension>,
    },
    StandStill {
        duration: f64,
    },
    Speed {
        value: f64,
        rule: Rule,
        direction: Option<DirectionalDimension>,
    },
    RelativeSpeed {
        entity: String,
        value: f64,
        rule: Rule,
        direction: Option<DirectionalDimension>,
    },
    TraveledDistance {
        value: f64,
    },
    ReachPosition {
        position: Position,
        tolerance: f64,
    },
    Distance {
        position: Position,
        value: f64,
        rule: Rule,
        options: DistanceOptions,
    },
    RelativeDistance {
        entity: String,
        value: f64,
        rule: Rule,
        options: DistanceOptions,
    },
    RelativeClearance {
        entities: Vec<String>,
        opposite_lanes: bool,
        free_space: bool,
        distance_forward: Option<f64>,
        distance_backward: Option<f64>,
        /// RelativeLaneRange (from, to) pairs.
        lane_ranges: Vec<(Option<i32>, Option<i32>)>,
    },
    Angle {
        angle_type: AngleType,
        angle: f64,
        tolerance: f64,
        coordinate_system: Option<CoordinateSystem>,
    },
    RelativeAngle {
        entity: String,
        angle_type: AngleType,
        angle: f64,
        tolerance: f64,
        coordinate_system: Option<CoordinateSystem>,
    },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ValueCondition {
    Parameter { parameter: String, value: String, rule: Rule },
    TimeOfDay { date_time: String, rule: Rule },
    SimulationTime { value: f64, rule: Rule },
    StoryboardElementState { element_type: StoryboardElementType, element: String, state: StoryboardElementState },
    UserDefinedValue { name: String, value: String, rule: Rule },
    TrafficSignal { name: String, state: String },
    TrafficSignalController { controller: String, phase: String },
    Variable { variable: String, value: String, rule: Rule },
}

impl ConditionKind {
    /// The schema element name of the condition (for messages and outlines).
    pub fn element_name(&self) -> &str {
        match self {
            ConditionKind::ByEntity { condition, .. } => condition.element_name(),
            ConditionKind::ByValue(v) => v.element_name(),
            ConditionKind::Unsupported { element } => element,
        }
    }
}

impl EntityCondition {
    pub fn element_name(&self) -> &'static str {
        match self {
            EntityCondition::EndOfRoad { .. } => "EndOfRoadCondition",
            EntityCondition::Collision { .. } => "CollisionCondition",
            EntityCondition::Offroad { .. } => "OffroadCondition",
            EntityCondition::TimeHeadway { .. } => "TimeHeadwayCondition",
            EntityCondition::TimeToCollision { .. } => "TimeToCollisionCondition",
            EntityCondition::Acceleration { .. } => "AccelerationCondition",
            EntityCondition::StandStill { .. } => "StandStillCondition",
            EntityCondition::Speed { .. } => "SpeedCondition",
            EntityCondition::RelativeSpeed { .. } => "RelativeSpeedCondition",
            EntityCondition::TraveledDistance { .. } => "TraveledDistanceCondition",
            EntityCondition::ReachPosition { .. } => "ReachPositionCondition",
            EntityCondition::Distance { .. } => "DistanceCondition",
            EntityCondition::RelativeDistance { .. } => "RelativeDistanceCondition",
            EntityCondition::RelativeClearance { .. } => "RelativeClearanceCondition",
            EntityCondition::Angle { .. } => "AngleCondition",
            EntityCondition::RelativeAngle { .. } => "RelativeAngleCondition",
        }
    }
}

impl ValueCondition {
    pub fn element_name(&self) -> &'static str {
        match self {
            ValueCondition::Parameter { .. } => "ParameterCondition",
            ValueCondition::TimeOfDay { .. } => "TimeOfDayCondition",
            ValueCondition::SimulationTime { .. } => "SimulationTimeCondition",
            ValueCondition::StoryboardElementState { .. } => "StoryboardElementStateCondition",
            ValueCondition::UserDefinedValue { .. } => "UserDefinedValueCondition",
            ValueCondition::TrafficSignal { .. } => "TrafficSignalCondition",
            ValueCondition::TrafficSignalController { .. } => "TrafficSignalControllerCondition",
            ValueCondition::Variable { .. } => "VariableCondition",
        }
    }
}
