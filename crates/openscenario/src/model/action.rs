//! Actions: private (one entity), global, user-defined.

use super::{Controller, Environment, Origin, Position, Route, Trajectory};
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Action {
    /// `name` of the Action element ("" for Init actions).
    pub name: String,
    pub kind: ActionKind,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ActionKind {
    Private(PrivateAction),
    Global(GlobalAction),
    /// UserDefinedAction / CustomCommandAction: type and text content are not interpreted.
    CustomCommand {
        command_type: String,
    },
    /// An element the model does not represent yet (also reported as a warning at load).
    Unsupported {
        element: String,
    },
}

crate::xml_enum! {
    DynamicsShape { Linear = "linear", Cubic = "cubic", Sinusoidal = "sinusoidal", Step = "step" }
}
crate::xml_enum! {
    DynamicsDimension { Time = "time", Distance = "distance", Rate = "rate" }
}
crate::xml_enum! {
    FollowingMode { Position = "position", Follow = "follow" }
}
crate::xml_enum! {
    SpeedTargetValueType { Delta = "delta", Factor = "factor" }
}
crate::xml_enum! {
    CoordinateSystem { Entity = "entity", Lane = "lane", Road = "road", Trajectory = "trajectory", World = "world" }
}
crate::xml_enum! {
    LateralDisplacement { Any = "any", LeftToReferencedEntity = "leftToReferencedEntity", RightToReferencedEntity = "rightToReferencedEntity" }
}
crate::xml_enum! {
    LongitudinalDisplacement { Any = "any", TrailingReferencedEntity = "trailingReferencedEntity", LeadingReferencedEntity = "leadingReferencedEntity" }
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TransitionDynamics {
    pub shape: DynamicsShape,
    pub dimension: DynamicsDimension,
    pub value: f64,
    pub following_mode: Option<FollowingMode>,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct DynamicConstraints {
    pub max_acceleration: Option<f64>,
    pub max_deceleration: Option<f64>,
    pub max_speed: Option<f64>,
    pub max_acceleration_rate: Option<f64>,
    pub max_deceleration_rate: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum SpeedTarget {
    Absolute { value: f64 },
    Relative { entity: String, value: f64, value_type: SpeedTargetValueType, continuous: bool },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpeedProfileEntry {
    pub speed: f64,
    pub time: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum LaneChangeTarget {
    Relative { entity: String, value: i32 },
    Absolute { lane_id: i32 },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum LaneOffsetTarget {
    Relative { entity: String, value: f64 },
    Absolute { value: f64 },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum TimeReference {
    None,
    Timing { domain: super::ReferenceContext, scale: f64, offset: f64 },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum FinalSpeed {
    Absolute { value: f64, steady_state: Option<SteadyState> },
    RelativeToMaster { value: f64, value_type: SpeedTargetValueType, steady_state: Option<SteadyState> },
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum SteadyState {
    Distance(f64),
    Time(f64),
}

crate::xml_enum! {
    LightMode { On = "on", Off = "off", Flashing = "flashing" }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum LightType {
    Vehicle(String),
    UserDefined(String),
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LightState {
    pub mode: LightMode,
    pub luminous_intensity: Option<f64>,
    pub flashing_on_duration: Option<f64>,
    pub flashing_off_duration: Option<f64>,
    /// RGB in [0, 1] when given as ColorRgb; other colour forms keep only their `colorType`.
    pub color_type: Option<String>,
    pub rgb: Option<(f64, f64, f64)>,
}

/// One value of an OverrideControllerValueAction (throttle, brake, ...).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OverrideValue {
    pub kind: String,
    pub active: bool,
    pub value: Option<f64>,
    pub max_rate: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum PrivateAction {
    Speed {
        dynamics: TransitionDynamics,
        target: SpeedTarget,
    },
    SpeedProfile {
        entity: Option<String>,
        following_mode: FollowingMode,
        constraints: Option<DynamicConstraints>,
        entries: Vec<SpeedProfileEntry>,
    },
    LongitudinalDistance {
        entity: String,
        distance: Option<f64>,
        time_gap: Option<f64>,
        freespace: bool,
        continuous: bool,
        coordinate_system: Option<CoordinateSystem>,
        displacement: Option<LongitudinalDisplacement>,
        constraints: Option<DynamicConstraints>,
    },
    LaneChange {
        dynamics: TransitionDynamics,
        target: LaneChangeTarget,
        target_lane_offset: Option<f64>,
    },
    LaneOffset {
        continuous: bool,
        shape: DynamicsShape,
        max_lateral_acc: Option<f64>,
        target: LaneOffsetTarget,
    },
    LateralDistance {
        entity: String,
        distance: Option<f64>,
        freespace: bool,
        continuous: bool,
        coordinate_system: Option<CoordinateSystem>,
        displacement: Option<LateralDisplacement>,
        constraints: Option<DynamicConstraints>,
    },
    Visibility {
        graphics: bool,
        sensors: bool,
        traffic: bool,
        sensor_refs: Vec<String>,
    },
    Synchronize {
        master: String,
        target_position_master: Position,
        target_position: Position,
        final_speed: Option<FinalSpeed>,
        target_tolerance_master: Option<f64>,
        target_tolerance: Option<f64>,
    },
    /// ActivateControllerAction (1.0 directly under PrivateAction, 1.1+ under ControllerAction).
    ActivateController {
        lateral: Option<bool>,
        longitudinal: Option<bool>,
        lighting: Option<bool>,
        animation: Option<bool>,
        /// `controllerRef` (before 1.3).
        controller_ref: Option<String>,
        /// `objectControllerRef` (1.3).
        object_controller_ref: Option<String>,
    },
    AssignController {
        /// None: the action names no controller (e.g. an empty ObjectController).
        controller: Option<Controller>,
        /// The `name` of the ObjectController that wraps the controller (OpenSCENARIO 1.3);
        /// None when there is no wrapper or it has no name.
        object_controller_name: Option<String>,
        activate_lateral: Option<bool>,
        activate_longitudinal: Option<bool>,
        activate_lighting: Option<bool>,
        activate_animation: Option<bool>,
    },
    OverrideControllerValue(Vec<OverrideValue>),
    Teleport(Position),
    AssignRoute(Route),
    FollowTrajectory {
        trajectory: Trajectory,
        time_reference: TimeReference,
        following_mode: FollowingMode,
        initial_distance_offset: Option<f64>,
    },
    AcquirePosition(Position),
    /// RandomRouteAction (1.3): no content.
    RandomRoute,
    LightState {
        light_type: LightType,
        state: LightState,
        transition_time: Option<f64>,
    },
    Animation {
        animation_type: String,
        loop_: Option<bool>,
        duration: Option<f64>,
        state: Option<f64>,
    },
    ConnectTrailer {
        trailer: String,
    },
    DisconnectTrailer,
}

crate::xml_enum! {
    ModifyKind { Add = "add", Multiply = "multiply" }
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModifyRule {
    pub kind: ModifyKind,
    pub value: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum GlobalAction {
    Environment(Environment),
    AddEntity {
        entity: String,
        position: Position,
    },
    DeleteEntity {
        entity: String,
    },
    ParameterSet {
        parameter: String,
        value: String,
    },
    ParameterModify {
        parameter: String,
        rule: ModifyRule,
    },
    VariableSet {
        variable: String,
        value: String,
    },
    VariableModify {
        variable: String,
        rule: ModifyRule,
    },
    TrafficSignalState {
        name: String,
        state: String,
    },
    TrafficSignalController {
        controller: String,
        phase: String,
    },
    TrafficSource {
        position: Position,
        radius: f64,
        rate: f64,
        velocity: Option<f64>,
        definition: String,
    },
    TrafficSink {
        position: Position,
        radius: f64,
        rate: Option<f64>,
        definition: String,
    },
    TrafficSwarm {
        central_entity: String,
        inner_radius: f64,
        semi_major_axis: f64,
        semi_minor_axis: f64,
        offset: f64,
        number_of_vehicles: u32,
        velocity: Option<f64>,
        definition: String,
    },
    TrafficArea {
        continuous: bool,
        number_of_entities: u32,
    },
    TrafficStop {
        name: Option<String>,
    },
    SetMonitor {
        monitor: String,
        value: bool,
    },
}

impl ActionKind {
    /// The schema element name of the action (for messages and outlines).
    pub fn element_name(&self) -> &str {
        match self {
            ActionKind::Private(p) => p.element_name(),
            ActionKind::Global(g) => g.element_name(),
            ActionKind::CustomCommand { .. } => "CustomCommandAction",
            ActionKind::Unsupported { element } => element,
        }
    }
}

impl PrivateAction {
    pub fn element_name(&self) -> &'static str {
        match self {
            PrivateAction::Speed { .. } => "SpeedAction",
            PrivateAction::SpeedProfile { .. } => "SpeedProfileAction",
            PrivateAction::LongitudinalDistance { .. } => "LongitudinalDistanceAction",
            PrivateAction::LaneChange { .. } => "LaneChangeAction",
            PrivateAction::LaneOffset { .. } => "LaneOffsetAction",
            PrivateAction::LateralDistance { .. } => "LateralDistanceAction",
            PrivateAction::Visibility { .. } => "VisibilityAction",
            PrivateAction::Synchronize { .. } => "SynchronizeAction",
            PrivateAction::ActivateController { .. } => "ActivateControllerAction",
            PrivateAction::AssignController { .. } => "AssignControllerAction",
            PrivateAction::OverrideControllerValue(_) => "OverrideControllerValueAction",
            PrivateAction::Teleport(_) => "TeleportAction",
            PrivateAction::AssignRoute(_) => "AssignRouteAction",
            PrivateAction::FollowTrajectory { .. } => "FollowTrajectoryAction",
            PrivateAction::AcquirePosition(_) => "AcquirePositionAction",
            PrivateAction::RandomRoute => "RandomRouteAction",
            PrivateAction::LightState { .. } => "LightStateAction",
            PrivateAction::Animation { .. } => "AnimationAction",
            PrivateAction::ConnectTrailer { .. } => "ConnectTrailerAction",
            PrivateAction::DisconnectTrailer => "DisconnectTrailerAction",
        }
    }
}

impl GlobalAction {
    pub fn element_name(&self) -> &'static str {
        match self {
            GlobalAction::Environment(_) => "EnvironmentAction",
            GlobalAction::AddEntity { .. } => "AddEntityAction",
            GlobalAction::DeleteEntity { .. } => "DeleteEntityAction",
            GlobalAction::ParameterSet { .. } => "ParameterSetAction",
            GlobalAction::ParameterModify { .. } => "ParameterModifyAction",
            GlobalAction::VariableSet { .. } => "VariableSetAction",
            GlobalAction::VariableModify { .. } => "VariableModifyAction",
            GlobalAction::TrafficSignalState { .. } => "TrafficSignalStateAction",
            GlobalAction::TrafficSignalController { .. } => "TrafficSignalControllerAction",
            GlobalAction::TrafficSource { .. } => "TrafficSourceAction",
            GlobalAction::TrafficSink { .. } => "TrafficSinkAction",
            GlobalAction::TrafficSwarm { .. } => "TrafficSwarmAction",
            GlobalAction::TrafficArea { .. } => "TrafficAreaAction",
            GlobalAction::TrafficStop { .. } => "TrafficStopAction",
            GlobalAction::SetMonitor { .. } => "SetMonitorAction",
        }
    }
}
