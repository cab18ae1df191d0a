//! Trailers: which vehicle tows which (Vehicle `Trailer` reference, ConnectTrailerAction,
//! DisconnectTrailerAction) and the articulated kinematics that pull a trailer behind its tow
//! vehicle. As esmini: after every move the trailer's coupler is put on the tow vehicle's hitch
//! and the trailer turns to point from where its reference point was towards the hitch — a
//! discrete tractrix, which is what a rigid trailer on a non-slipping axle does.

pub(crate) mod state;

use state::Trailers;

use crate::entities::Entity;
use crate::sim::Sim;
use openscenario::{EntityObject, Scenario, Trailer};

/// Longest chain of trailers followed (guards against reference cycles in hostile input).
const MAX_CHAIN: usize = 100;

impl Trailers {
    /// The initial tow links of `scenario`. Inline trailer entities (a vehicle model's
    /// `Trailer` element holding a whole entity) become run entities appended to `entities`,
    /// named after their tow vehicle plus `+` as esmini names them.
    pub(crate) fn build(scenario: &Scenario, entities: &mut Vec<Entity>) -> Trailers {
        let mut t = Trailers::default();
        for e in &scenario.entities {
            let (h, c) = joints(e);
            t.hitch.push(h);
            t.coupler.push(c);
            t.links.push(None);
            t.towed_by.push(None);
        }
        for (i, e) in scenario.entities.iter().enumerate() {
            let mut tow = i;
            let mut model = e;
            for _ in 0..MAX_CHAIN {
                let EntityObject::Vehicle(v) = &model.object else { break };
                match &v.trailer {
                    Some(Trailer::Ref(name)) => {
                        t.links[tow] = scenario.entities.iter().position(|o| &o.name == name).filter(|&k| k != tow);
                        if let Some(k) = t.links[tow] {
                            t.towed_by[k] = Some(tow);
                        }
                        break;
                    }
                    Some(Trailer::Entity(inner)) => {
                        let mut en = Entity::from_model(inner);
                        en.name = format!("{}+", entities.get(tow).map_or("", |x| x.name.as_str()));
                        entities.push(en);
                        let k = entities.len() - 1;
                        let (h, c) = joints(inner);
                        t.hitch.push(h);
                        t.coupler.push(c);
                        t.links.push(None);
                        t.towed_by.push(Some(tow));
                        t.links[tow] = Some(k);
                        tow = k;
                        model = inner;
                    }
                    None => break,
                }
            }
        }
        t
    }
}

/// An entity model's hitch and coupler positions.
fn joints(e: &openscenario::Entity) -> (Option<f64>, Option<f64>) {
    match &e.object {
        EntityObject::Vehicle(v) => (v.trailer_hitch, v.trailer_coupler),
        _ => (None, None),
    }
}

impl<'a> Sim<'a> {
    /// ConnectTrailerAction as esmini's ConnectTrailerAction::Start and Vehicle::ConnectTrailer:
    /// a trailer `tow` already pulls is kept; another one is disconnected first. Then the
    /// trailer's coupler names `tow` (if it has a coupler) and `tow`'s hitch the trailer (if
    /// both have theirs). A vehicle that towed the trailer before keeps it on its hitch and
    /// goes on pulling it; a trailer coupled to a vehicle without a hitch is towed by nobody
    /// (Object::TowVehicle), so the default controller moves it too.
    pub(crate) fn connect_trailer(&mut self, slot: usize, tow: usize, trailer_name: &str) {
        let Some(trailer) = self.entity_index(trailer_name) else {
            self.warn_action(slot, format!("ConnectTrailerAction: unknown trailer entity `{trailer_name}`"));
            return;
        };
        let has = |v: &[Option<f64>], e: usize| v.get(e).copied().flatten().is_some();
        let (hitch, coupler) = (has(&self.trailers.hitch, tow), has(&self.trailers.coupler, trailer));
        if trailer == tow || !hitch || !coupler {
            self.warn_action(slot, format!("ConnectTrailerAction: `{trailer_name}` needs a TrailerCoupler and the tow vehicle a TrailerHitch"));
            if trailer == tow {
                return;
            }
        }
        let current = self.trailers.trailer_of(tow);
        if current == Some(trailer) {
            return;
        }
        if current.is_some() {
            self.disconnect_trailer(tow);
        }
        if coupler {
            self.trailers.towed_by[trailer] = Some(tow);
            let slot = self.trailers.hitch_slot(tow);
            if let (true, Some(l)) = (hitch, self.trailers.links.get_mut(slot)) {
                *l = Some(trailer);
            }
        }
    }

    /// DisconnectTrailerAction: the link goes, nothing else (esmini's Vehicle::DisconnectTrailer).
    /// The trailer keeps the speed its tow vehicle last gave it, and from the next step
    /// ScenarioEngine::defaultController moves it along its lane like any entity no action
    /// moves (where there is no road it stops there, as in esmini's trailer_connect).
    pub(crate) fn disconnect_trailer(&mut self, tow: usize) {
        let slot = self.trailers.hitch_slot(tow);
        if let Some(t) = self.trailers.links.get_mut(slot).and_then(|l| l.take()) {
            if let Some(c) = self.trailers.towed_by.get_mut(t) {
                *c = None;
            }
        }
    }

    /// esmini's Object::TowVehicle: the vehicle `e`'s coupler names, if that one has a hitch.
    pub(crate) fn is_towed(&self, e: usize) -> bool {
        let tow = self.trailers.towed_by.get(e).copied().flatten();
        tow.is_some_and(|t| self.trailers.hitch.get(t).copied().flatten().is_some())
    }

    /// The vehicles a freespace distance from `e` measures from, in esmini's order
    /// (Object::Distance): its front-most tow vehicle (Object::TowVehicle over and over), then
    /// each one's trailer (Object::TrailerVehicle: on the hitch, with a coupler) in turn.
    pub(crate) fn towing_chain(&self, e: usize) -> Vec<usize> {
        let mut front = e;
        for _ in 0..self.entities.len() {
            match self.trailers.towed_by.get(front).copied().flatten() {
                Some(t) if self.is_towed(front) && t != e => front = t,
                _ => break,
            }
        }
        let mut chain = vec![front];
        while chain.len() <= self.entities.len() {
            let Some(&last) = chain.last() else { break };
            let has_coupler = |t: usize| self.trailers.coupler.get(t).copied().flatten().is_some();
            match self.trailers.trailer_of(last) {
                Some(t) if has_coupler(t) && !chain.contains(&t) => chain.push(t),
                _ => break,
            }
        }
        chain
    }

    /// Keep the default controller off towed trailers: their tow vehicle moves them
    /// (ScenarioEngine::step skips an entity with a TowVehicle).
    pub(crate) fn hold_trailers(&mut self) {
        for e in 0..self.entities.len() {
            if self.is_towed(e) {
                self.entities[e].moved_by_action = true;
            }
        }
    }

    /// Pull every trailer chain behind its front tow vehicle.
    /// A ghost sharing its owner's hitch pulls the owner's trailer too, after the owner
    /// (ScenarioEngine::step updates the chains of every front tow vehicle in entity order, the
    /// ghost last): during the head start the trailer follows the ghost.
    pub(crate) fn pull_trailers(&mut self) {
        for front in 0..self.trailers.links.len() {
            if self.trailers.trailer_of(front).is_none() || self.is_towed(front) {
                continue;
            }
            let mut tow = front;
            for _ in 0..MAX_CHAIN {
                let Some(trailer) = self.trailers.trailer_of(tow) else { break };
                self.pull(tow, trailer);
                tow = trailer;
            }
        }
    }

    /// Put every trailer chain straight behind its front tow vehicle (before the Init actions).
    pub(crate) fn align_trailers(&mut self) {
        for front in 0..self.trailers.links.len() {
            if self.trailers.links[front].is_some() && !self.is_towed(front) {
                self.align_chain(front);
            }
        }
    }

    /// Put the trailers behind `front` straight behind it, moving at its speed (esmini does this
    /// when it places a tow vehicle).
    pub(crate) fn align_chain(&mut self, front: usize) {
        let Some(f) = self.entities.get(front) else { return };
        let (h, speed) = (f.h, f.speed);
        let (c, s) = (h.cos(), h.sin());
        let mut tow = front;
        for _ in 0..MAX_CHAIN {
            let Some(trailer) = self.trailers.trailer_of(tow) else { break };
            let hitch = self.trailers.hitch.get(tow).copied().flatten().unwrap_or(0.0);
            let coupler = self.trailers.coupler.get(trailer).copied().flatten().unwrap_or(0.0);
            let Some(tv) = self.entities.get(tow) else { break };
            let (x, y) = (tv.x + (hitch - coupler) * c, tv.y + (hitch - coupler) * s);
            let net = self.net;
            if let Some(en) = self.entities.get_mut(trailer) {
                en.set_world(net, x, y, None, h);
                en.speed = speed;
            }
            tow = trailer;
        }
    }

    fn pull(&mut self, tow: usize, trailer: usize) {
        let (Some(hitch), Some(coupler)) = (self.trailers.hitch.get(tow).copied().flatten(), self.trailers.coupler.get(trailer).copied().flatten()) else {
            return;
        };
        let Some(tv) = self.entities.get(tow) else { return };
        let (hx, hy) = (tv.x + hitch * tv.h.cos(), tv.y + hitch * tv.h.sin());
        let speed = tv.speed;
        let net = self.net;
        let Some(en) = self.entities.get_mut(trailer) else { return };
        let (dx, dy) = (en.x - hx, en.y - hy);
        let len = (dx * dx + dy * dy).sqrt();
        // Trailer reference point on the hitch: keep its heading.
        let (ux, uy) = if len > 1e-9 { (dx / len, dy / len) } else { (-en.h.cos(), -en.h.sin()) };
        let (x, y) = (hx + ux * coupler, hy + uy * coupler);
        let h = uy.atan2(ux) + std::f64::consts::PI;
        en.set_world(net, x, y, None, h);
        en.speed = speed;
    }
}
