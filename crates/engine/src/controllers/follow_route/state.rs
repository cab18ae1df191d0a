//! What a FollowRoute controller remembers: the route's waypoints, the path to the next one and
//! a running lane change.

use crate::actions::lane_change::state::LaneChangeRt;
use crate::controllers::lane_router::LaneSpot;
use routing::Strategy;

#[derive(Debug, Clone)]
pub(crate) struct FollowRouteRt {
    pub active: bool,
    /// Activated on the longitudinal domain (ActivateControllerAction's `longitudinal`).
    pub(super) longitudinal: bool,
    pub(super) lane_change_time: f64,
    pub(super) min_dist_for_collision: f64,
    pub(super) min_lane_width: f64,
    pub(super) test_mode: bool,
    /// The route's scenario waypoints with their strategies (set by AssignRouteAction).
    pub(super) scenario: Vec<(LaneSpot, Strategy)>,
    /// The road of each of esmini's detailed route waypoints: the scenario waypoints and one
    /// per road in between.
    pub(super) route_roads: Vec<usize>,
    pub(super) path_calculated: bool,
    pub(super) waypoints: Vec<LaneSpot>,
    pub(super) current: usize,
    pub(super) scenario_index: usize,
    pub(super) changing_lane: bool,
    pub(super) lane_change: Option<LaneChangeRt>,
    /// The lane change has put the entity on its internal position (a Step at speed): only
    /// then is esmini's entity on the change's target lane.
    pub(super) lane_change_placed: bool,
}
