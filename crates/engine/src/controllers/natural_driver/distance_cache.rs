//! Which other entities a NaturalDriver counts as near (ControllerNaturalDriver::
//! FilterSurroundingVehicles): esmini asks ScenarioEngine::GetDistance, which keeps the last
//! measurement of each ordered pair of entities and measures again only when it is due, or
//! when either entity was teleported this step. A pair measured more than twice the
//! look-ahead apart (ahead: the distance is signed by the side of the asker's heading it lies
//! on) is due again only after 3 s, and a pair more than 500 m apart holds both orders for
//! 3 s. Only a pair measured in this call counts: one held is not near, however close it has
//! come since.

use crate::sim::Sim;

/// UpdateDistance: how long a far pair is held, and beyond which squared distance a pair is
/// held both ways without a measurement (500 m).
const HOLD: f64 = 3.0;
const FAR_SQUARED: f64 = 2.5e5;

impl Sim<'_> {
    /// GetDistance from entity `a` to `b` with the tracking limit `limit`: the signed
    /// straight-line distance when measured now, `None` when held (or either is inactive).
    pub(super) fn nd_cached_distance(&mut self, a: usize, b: usize, limit: f64) -> Option<f64> {
        let (ea, eb) = (self.entities.get(a)?, self.entities.get(b)?);
        let cache = &mut self.nd_distances;
        if !ea.active || !eb.active {
            cache.remove(a, b);
            cache.remove(b, a);
            return None;
        }
        let due = cache.get(a, b).is_none_or(|next| self.clock > next) || ea.teleported || eb.teleported;
        if !due {
            return None;
        }
        // UpdateDistance creates both orders' entries (due at once, next_update_ 0).
        if cache.get(b, a).is_none() {
            cache.set(b, a, 0.0);
        }
        let (dx, dy) = (eb.x - ea.x, eb.y - ea.y);
        if dx * dx + dy * dy > FAR_SQUARED {
            cache.set(a, b, self.clock + HOLD);
            cache.set(b, a, self.clock + HOLD);
            return None;
        }
        // Position::getRelativeDistance: negative unless strictly ahead of a's heading.
        let ahead = dx * ea.h.cos() + dy * ea.h.sin();
        let d = if ahead > 0.0 { 1.0 } else { -1.0 } * dx.hypot(dy);
        cache.set(a, b, if d > limit { self.clock + HOLD } else { self.clock });
        Some(d)
    }
}
