//! TeleportAction: put the entity at a position (speed unchanged).

use crate::positions::resolve_with_route;
use crate::roads::road_follow::wrap;
use crate::sim::Sim;
use openscenario::Position;

impl<'a> Sim<'a> {
    pub(super) fn teleport(&mut self, slot: usize, e: usize, pos: &Position) {
        // esmini's TeleportAction::Start does nothing while a controller in override mode owns
        // the entity's lateral or longitudinal motion (controllers/mod.rs `overrides_motion`)
        if self.overrides_motion(e) {
            self.warn_action(slot, "TeleportAction: ignored, as esmini does, while the entity's controller in override mode drives it".into());
            return;
        }
        self.put_at(slot, e, pos);
    }

    /// Put entity `e` at `pos` (esmini's Position::TeleportTo), whatever drives it: the
    /// TeleportAction's placement once the override test passed, and AddEntityAction's, which
    /// has no such test (AddEntityAction::Start).
    pub(super) fn put_at(&mut self, slot: usize, e: usize, pos: &Position) {
        if let Some(note) = crate::route_position::esmini_deviation(pos, self.net, &self.entities) {
            self.warn_action(slot, format!("TeleportAction: {note}"));
        }
        let own_route = self.entities.get(e).and_then(|en| en.route.clone());
        let placement = match resolve_with_route(pos, self.net, &self.entities, own_route.as_deref(), Some(&mut self.random)) {
            Ok(p) => p,
            Err(msg) => {
                self.warn_action(slot, format!("TeleportAction: {msg}; the entity stays where it is"));
                return;
            }
        };
        let net = self.net;
        let Some(en) = self.entities.get_mut(e) else { return };
        en.at_road_end = false;
        match (placement.lane, net) {
            (Some(lp), Some(net)) => {
                if let Some(pose) = lp.pose(net) {
                    // The heading relative to the lane leaves out the lane's drift, which moving adds
                    // back (esmini keeps h_relative without GetHOffset).
                    en.yaw_offset = wrap(placement.h - lp.facing_heading(&pose) - crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s));
                }
                en.set_lane_pos(net, lp);
                en.h = crate::entities::wrap_2pi(placement.h);
            }
            _ => en.set_world_snapping(net, placement.x, placement.y, placement.z, placement.h, false),
        }
        // esmini records a teleported entity where it was put: it does not move on this step.
        en.moved_by_action = true;
        en.teleported = true;
    }
}
