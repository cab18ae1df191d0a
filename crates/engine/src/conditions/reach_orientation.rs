//! The orientation test of esmini's ReachPositionCondition. When the position element carries
//! an Orientation child (ScenarioReader sets `checkOrientation_`), TrigByReachPosition also
//! asks that the entity's heading, pitch and roll each differ from the position's by less
//! than 0.05 rad — as plain differences of angles in [0, 2π), so a wanted heading of −0.02
//! (6.263) is never met by an entity at 0.

use crate::angles::{wrap, wrap_2pi};
use crate::positions::Placement;
use crate::sim::Sim;
use opendrive::RoadNetwork;
use openscenario::Position;

/// TrigByReachPosition's angularTolerance_.
const ANGULAR_TOLERANCE: f64 = 0.05;

/// Whether esmini checks the orientation: the position element has an Orientation child. A
/// WorldPosition gives its angles as attributes and never has one; the positions the engine
/// cannot place never get here (the condition warns and stays false before).
pub(super) fn has_orientation(position: &Position) -> bool {
    match position {
        Position::RelativeWorld { orientation, .. }
        | Position::RelativeObject { orientation, .. }
        | Position::Road { orientation, .. }
        | Position::RelativeRoad { orientation, .. }
        | Position::Lane { orientation, .. }
        | Position::RelativeLane { orientation, .. }
        | Position::Route { orientation, .. }
        | Position::Trajectory { orientation, .. } => orientation.is_some(),
        _ => false,
    }
}

/// The heading, pitch and roll the resolved position holds, each in [0, 2π): on a sloped or
/// banked road its pitch and roll are the road's rotation composed with its heading from the
/// road (Position::EvaluateHPR); elsewhere level.
pub(super) fn position_attitude(net: Option<&RoadNetwork>, placement: &Placement) -> [f64; 3] {
    let tilt = net.zip(placement.lane).and_then(|(net, lp)| {
        let road = net.roads.get(lp.road)?;
        let s = lp.s.clamp(0.0, road.length);
        let t = lp.pose(net)?.t;
        let h_ref = crate::roads::pose_memo::reference_pose(road, s).hdg;
        crate::attitude::on_road(road, s, t, wrap(placement.h - h_ref), 0.0).map(|[_, p, r]| (p, r))
    });
    let (p, r) = tilt.unwrap_or((0.0, 0.0));
    [wrap_2pi(placement.h), wrap_2pi(p), wrap_2pi(r)]
}

impl Sim<'_> {
    /// Whether entity `idx` faces as `wanted` within TrigByReachPosition's tolerance.
    pub(super) fn faces_as(&self, idx: usize, wanted: [f64; 3]) -> bool {
        let Some(e) = self.entities.get(idx) else { return false };
        let (p, r) = self.net.map_or((0.0, 0.0), |net| crate::attitude::surface_pitch_roll(net, e));
        let own = [wrap_2pi(e.h), wrap_2pi(p), wrap_2pi(r)];
        own.iter().zip(wanted).all(|(a, b)| (a - b).abs() < ANGULAR_TOLERANCE)
    }
}
