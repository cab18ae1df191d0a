//! Pitch and roll of an entity as esmini's AngleCondition reads them (TrigByAngle, with
//! Position's road pitch and roll). On a road the entity lies on the surface: the road's
//! pitch (−atan of the elevation slope, nose down positive) and roll (the superelevation),
//! both turned around when it faces against s. Following a polyline trajectory whose vertices
//! give their own heights, it pitches with the path instead (esmini's trajectory vertex
//! pitch, corner-blended). esmini composes road and relative angles as full rotations
//! (R0R12EulerAngles) and adds a pitch offset on banked roads; those second-order terms are
//! not reproduced.

use crate::actions::state::ActionRt;
use crate::entities::Entity;
use crate::roads::banking::roll_at;
use crate::roads::road_follow::wrap;
use crate::roads::LanePos;
use crate::sim::Sim;
use opendrive::RoadNetwork;
use std::f64::consts::FRAC_PI_2;

/// The road's pitch and roll along its s direction at `lp`.
pub(crate) fn road_pitch_roll(net: &RoadNetwork, lp: &LanePos) -> (f64, f64) {
    let Some(road) = net.roads.get(lp.road) else { return (0.0, 0.0) };
    let s = lp.s.clamp(0.0, road.length);
    (-road.elevation_slope_at(s).atan(), roll_at(road, s).0)
}

/// Pitch and roll of entity `e` lying on the road surface where it is (turned around when it
/// faces against s); (0, 0) off the road.
pub(crate) fn surface_pitch_roll(net: &RoadNetwork, e: &Entity) -> (f64, f64) {
    let Some(lp) = e.lane else { return (0.0, 0.0) };
    let (p, r) = road_pitch_roll(net, &lp);
    let facing = lp.pose(net).map_or(1.0, |q| if wrap(e.h - q.road_heading).abs() <= FRAC_PI_2 { 1.0 } else { -1.0 });
    (p * facing, r * facing)
}

impl<'a> Sim<'a> {
    /// World pitch and roll of entity `idx`.
    pub(crate) fn pitch_roll(&self, idx: usize) -> (f64, f64) {
        let Some(e) = self.entities.get(idx) else { return (0.0, 0.0) };
        let (mut pitch, roll) = self.net.map_or((0.0, 0.0), |net| surface_pitch_roll(net, e));
        let on_path = self.actions.iter().filter(|a| a.running).flat_map(|a| a.instances.iter()).find_map(|inst| match &inst.rt {
            ActionRt::FollowTrajectory(f) if inst.entity == Some(idx) && f.elevated => Some(f.path.pitch_at(f.s) * f.heading_sign),
            _ => None,
        });
        if let Some(p) = on_path {
            pitch = p;
        }
        // what the outside gave (external/)
        let (p, r) = self.external_attitude(idx);
        (p.unwrap_or(pitch), r.unwrap_or(roll))
    }
}
