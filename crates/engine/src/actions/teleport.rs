//! TeleportAction: put the entity at a position (speed unchanged).

use crate::angles::wrap;
use crate::positions::resolve_with_route;
use crate::sim::Sim;
use openscenario::Position;

impl<'a> Sim<'a> {
    /// Whether the entity was moved (false: esmini ignores the action, see below).
    pub(super) fn teleport(&mut self, slot: usize, e: usize, pos: &Position) -> bool {
        // esmini's TeleportAction::Start does nothing while a controller in override mode owns
        // the entity's lateral or longitudinal motion (controllers/mod.rs `overrides_motion`)
        if self.overrides_motion(e) {
            self.warn_action(slot, "TeleportAction: ignored, as esmini does, while the entity's controller in override mode drives it".into());
            return false;
        }
        // Nor does it move a trailer that is being towed ("position controlled by tow
        // vehicle"): a trailer connected in the Init before its own TeleportAction stays where
        // it was made, at the origin, and the first pull puts it on the line from the hitch
        // towards there (ScenarioEngine::step's trailer update).
        if self.is_towed(e) {
            self.warn_action(slot, "TeleportAction: ignored, as esmini does, while the trailer is towed (its tow vehicle places it)".into());
            return false;
        }
        // A teleport handed over to a ghost relative to its entity is relative to the ghost.
        match self.action_ref_position(slot, pos) {
            Some(pos) => self.put_at(slot, e, &pos, "TeleportAction"),
            None => self.put_at(slot, e, pos, "TeleportAction"),
        }
    }

    /// Put entity `e` at `pos` (esmini's Position::TeleportTo), whatever drives it: the
    /// TeleportAction's placement once the override test passed, and AddEntityAction's, which
    /// has no such test (AddEntityAction::Start). `action` names the action in warnings.
    /// Whether the entity was moved.
    pub(super) fn put_at(&mut self, slot: usize, e: usize, pos: &Position, action: &str) -> bool {
        if let Some(note) = crate::route_position::esmini_deviation(pos, self.net, &self.entities) {
            self.warn_action(slot, format!("{action}: {note}"));
        }
        // A RoutePosition FromCurrentEntity (esmini 3.6: "not implemented"), or a road-relative
        // position from an entity so placed, leaves esmini's position unset: the origin,
        // heading 0, on no road (TeleportAction::Start copies it as it is).
        // So does a ghost's copy of an Init teleport to a TrajectoryPosition: the copy
        // (TeleportAction's copy constructor, Position::Duplicate = CopyConfig, CopyLocation,
        // CopyState) has no trajectory, so TeleportTo evaluates nothing and copies the
        // location the position had when copied, before any evaluation: the origin.
        let trajectory_lost = matches!(pos, Position::Trajectory { .. }) && self.actions.get(slot).is_some_and(|a| a.ghost_copy);
        if trajectory_lost || self.unset_position(pos) {
            if let Some(en) = self.entities.get_mut(e) {
                en.place_nowhere();
            }
            return true;
        }
        let own_route = self.entities.get(e).and_then(|en| en.route.clone());
        let placement = match resolve_with_route(pos, self.net, &self.entities, own_route.as_deref(), Some(&mut self.random)) {
            Ok(p) => p,
            Err(msg) => {
                self.warn_action(slot, format!("{action}: {msg}; the entity stays where it is"));
                return false;
            }
        };
        let net = self.net;
        let asked = self.relation_asked_orientation(pos, placement.h);
        let Some(en) = self.entities.get_mut(e) else { return false };
        // The position status (end of road) is not the target's: esmini's Position::TeleportTo
        // copies the location only (CopyLocation leaves `status_`), so the entity keeps the
        // status of its last move until its next one (motion.rs).
        en.roadless = false;
        match (placement.lane, net) {
            (Some(lp), Some(net)) => {
                if let Some(pose) = lp.pose(net) {
                    // The heading relative to the lane leaves out the lane's drift, which moving adds
                    // back (esmini keeps h_relative without GetHOffset).
                    en.yaw_offset = wrap(placement.h - lp.facing_heading(&pose) - crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s));
                }
                en.set_lane_pos(net, lp);
                en.h = crate::angles::wrap_2pi(placement.h);
                if let Some(h) = relative_heading_twice_composed(net, pos, &lp, en.yaw_offset) {
                    en.h = h;
                    if let Some(pose) = lp.pose(net) {
                        en.yaw_offset = wrap(h - lp.facing_heading(&pose) - crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s));
                    }
                }
                if placement.world_left {
                    if let (Some(rel), Some(pose)) = (placement.h_rel, lp.pose(net)) {
                        en.yaw_offset =
                            wrap(rel - (lp.facing_heading(&pose) - pose.road_heading) - crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s));
                    }
                    (en.x, en.y, en.z) = (placement.x, placement.y, placement.z.unwrap_or(0.0));
                }
            }
            _ => {
                // A world position without h faces the road's reference direction where it lies
                // (esmini's OSCPositionWorld: heading relative to the road, 0), absolute 0 beyond
                // the road's last OSI point (`held_heading`).
                let h = match (pos, net) {
                    (Position::World { h: None, .. }, Some(n)) => {
                        crate::trajectory_position::held_heading(n, placement.x, placement.y, None).unwrap_or(placement.h)
                    }
                    _ => placement.h,
                };
                en.set_world_snapping(net, placement.x, placement.y, placement.z, h, false);
                if let (Some(abs), Some(net)) = (asked, net) {
                    orient_as_relation(en, net, abs);
                }
            }
        }
        // esmini records a teleported entity where it was put: it does not move on this step.
        en.moved_by_action = true;
        en.teleported = true;
        true
    }

    /// The absolute orientation a RelativeObject- or RelativeWorldPosition asks for (esmini's
    /// Position::EvaluateRelation passes SetInertiaPosMode the entity's heading, pitch and roll,
    /// each turned by the position's own unless that one is absolute); `h`: the heading the
    /// position resolved to. `None` for every other position.
    fn relation_asked_orientation(&self, pos: &Position, h: f64) -> Option<[f64; 3]> {
        let (entity, orientation) = match pos {
            Position::RelativeObject { entity, orientation, .. } | Position::RelativeWorld { entity, orientation, .. } => (entity, orientation.as_ref()),
            _ => return None,
        };
        let anchor = self.entity_index(entity)?;
        let (pitch, roll) = self.pitch_roll(anchor);
        let absolute = orientation.is_some_and(|o| o.reference == Some(openscenario::ReferenceContext::Absolute));
        let turn = |own: Option<f64>, of_anchor: f64| match own {
            Some(v) if absolute => v,
            Some(v) => of_anchor + v,
            None => of_anchor,
        };
        Some([h, turn(orientation.and_then(|o| o.p), pitch), turn(orientation.and_then(|o| o.r), roll)])
    }

    /// Whether esmini leaves `pos` unset: a RoutePosition FromCurrentEntity, or a position
    /// measured along the road from an entity that has no road.
    fn unset_position(&self, pos: &Position) -> bool {
        match pos {
            Position::Route { in_route: openscenario::InRoutePosition::FromCurrentEntity { .. }, .. } => true,
            Position::RelativeRoad { entity, .. } | Position::RelativeLane { entity, .. } => self.entities.iter().any(|en| &en.name == entity && en.roadless),
            _ => false,
        }
    }
}

/// A relative lane or road position facing relatively (no absolute heading, no pitch or roll
/// of its own) on a sloped or banked road: the heading esmini's Position::EvaluateRelation
/// leaves, the road's rotation composed twice (`attitude::relative_position_heading`).
/// `yaw_offset`: the entity's turn from the way it faces along the lane, as placed.
fn relative_heading_twice_composed(net: &opendrive::RoadNetwork, pos: &Position, lp: &crate::roads::LanePos, yaw_offset: f64) -> Option<f64> {
    let orientation = match pos {
        Position::RelativeLane { orientation, .. } | Position::RelativeRoad { orientation, .. } => orientation.as_ref(),
        _ => return None,
    };
    if let Some(o) = orientation {
        let absolute = o.reference == Some(openscenario::ReferenceContext::Absolute) && o.h.is_some();
        if absolute || o.p.is_some() || o.r.is_some() {
            return None;
        }
    }
    let h_rel = yaw_offset + if lp.dir < 0.0 { std::f64::consts::PI } else { 0.0 };
    let drift = crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s);
    crate::attitude::relative_position_heading(net, lp, h_rel, drift)
}

/// The orientation an entity teleported to a RelativeObject- or RelativeWorldPosition takes
/// on a sloped or banked road (`attitude::relation_orientation`, from the absolute orientation
/// `abs` the position asked for); the turn from the lane that moving keeps stays the plain
/// difference `set_world_snapping` found (EvaluateHPR's relative heading is the heading's
/// difference from the road's again).
fn orient_as_relation(en: &mut crate::entities::Entity, net: &opendrive::RoadNetwork, abs: [f64; 3]) {
    let Some(lp) = en.lane else { return };
    let Some(road) = net.roads.get(lp.road) else { return };
    let past_end = crate::roads::past_end::past_road_end(net, lp.road, lp.s, en.x, en.y);
    let Some(t) = lp.pose(net).map(|p| p.t) else { return };
    let drift = crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s);
    if let Some([h, pitch, roll]) = crate::attitude::relation_orientation(road, lp.s.clamp(0.0, road.length), t, drift, abs, past_end) {
        en.h = h;
        en.placed_attitude = Some(crate::entities::PlacedAttitude { pose: (en.x, en.y, h), pitch, roll });
    }
}
