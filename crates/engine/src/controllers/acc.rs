//! ACCController, as esmini's adaptive cruise control: the entity cruises at a set speed and
//! follows the nearest vehicle ahead in its lane (linked through roads, within a look-ahead of
//! max(50 m, twice the stopping distance), lateral offset below `lateralDist`) at a distance of
//! 3 m + `timeGap` × speed, blending a distance term and a speed term into an acceleration
//! clipped to the vehicle's limits. Another action changing the speed sets a new set speed. In
//! `override` mode it moves the entity itself; otherwise (additive) it only sets the speed.
//!
//! esmini steps its controllers after the default controller has moved every entity: so the
//! controller sees the others where they are at the end of the step, and in additive mode the
//! entity moves by the speed the controller set one step earlier. `Sim::step_acc`
//! runs after the default controller; before it, `hold_for_override` keeps the default controller off
//! an entity the controller moves itself (override mode).

pub(crate) mod state;

use state::AccRt;

use super::forward_delta::forward_delta;
use crate::conditions::distance::between;
use crate::roads::road_follow::at_unlinked_road_end;
use crate::roads::{move_along_route_drawing, MoveStatus};
use crate::sim::Sim;
use openscenario::{Controller, CoordinateSystem, RelativeDistanceType};

const LARGE: f64 = 1e10;
/// Minimum gap to the lead vehicle, m.
const MIN_DIST: f64 = 3.0;
const ACCELERATION_FACTOR: f64 = 0.7;

impl AccRt {
    /// Active in override mode: it owns the longitudinal domain (esmini's
    /// IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)).
    pub(crate) fn overrides_longitudinal(&self) -> bool {
        self.active && self.override_mode
    }

    pub(crate) fn new(c: &Controller) -> AccRt {
        let num = |n: &str| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok());
        AccRt {
            active: false,
            time_gap: num("timeGap").unwrap_or(1.5),
            set_speed: num("setSpeed").unwrap_or(0.0),
            set_speed_given: num("setSpeed").is_some(),
            lateral_dist: num("lateralDist").unwrap_or(5.0),
            current_speed: 0.0,
            override_mode: c.properties.get("mode") == Some("override"),
            moved_by_action: false,
            at_end: false,
            end_seen: false,
        }
    }

    pub(crate) fn activate(&mut self, speed: f64, longitudinal: bool) {
        if !longitudinal {
            return;
        }
        self.active = true;
        self.current_speed = speed;
        if !self.override_mode || !self.set_speed_given {
            self.set_speed = speed;
        }
    }
}

impl<'a> Sim<'a> {
    /// esmini's ScenarioEngine::step, before it steps any controller: an entity at the end of
    /// its road since the step before whose velocity is zero gets speed 0 (which
    /// its ACC then takes as its set speed and brakes to; a controller stepping before that ACC
    /// sees the 0). The default controller's entities get this in `default_controller`; the ACC
    /// moves its own in override mode.
    pub(crate) fn acc_stop_at_road_end(&mut self, e: usize, a: &mut AccRt) {
        // An action that placed the entity by a world point this step (a trajectory) left the
        // status its XYZ2TrackPos found, which the engine's check reads before the ACC moves.
        if let Some(st) = self.entities.get_mut(e).and_then(|en| en.placed_end_status.take()) {
            a.at_end = st;
        }
        if a.override_mode {
            // ...and notes the end of the road (the EndOfRoadCondition's time stamp) from the
            // status of that last move: one step after the arrival, where the default
            // controller's move is noted in its own step.
            if let Some(en) = self.entities.get_mut(e) {
                en.at_road_end = a.at_end;
            }
            if !a.at_end {
                a.end_seen = false;
            } else if !a.end_seen {
                a.end_seen = true;
            } else if let Some(en) = self.entities.get_mut(e).filter(|en| en.standing_still()) {
                // The entity's velocity, not the ACC's own move: a lateral action's move counts.
                en.speed = 0.0;
            }
        }
    }

    /// One step of the ACC (or ALKS) controller of entity `e`, after the default controller
    /// (`step_controllers_in_order`).
    pub(super) fn step_acc(&mut self, e: usize, a: &mut AccRt, dt: f64) {
        let Some(me) = self.entities.get(e) else { return };
        // A speed another action (or controller) set becomes the new set speed, in either mode
        // (esmini's ControllerACC::Step: its additive-only test is commented out). In override
        // mode most longitudinal actions end or idle (LongSpeedAction::Start, LongDistanceAction
        // ::Step, SynchronizeAction), but a SpeedProfileAction still sets the speed.
        if (me.speed - a.current_speed).abs() > 1e-3 {
            a.set_speed = me.speed;
        }
        let lookahead = (2.0 * MIN_DIST + a.current_speed.powi(2) / me.max_dec).max(50.0);
        let mut min_gap = LARGE;
        let mut lead: Option<usize> = None;
        for (i, p) in self.entities.iter().enumerate() {
            if i == e || !p.active {
                continue;
            }
            if let (Some(net), Some(la), Some(lb)) = (self.net, me.lane, p.lane) {
                // ControllerACC::Step: Position::Delta forward only (RoadPath::Calculate), which
                // reaches a lead on any junction branch; dLaneId 0 is "in my lane".
                if let Some(d) = forward_delta(net, &la, me.h, &lb, lookahead) {
                    let (ds, same_lane, dt_lat) = (d.ds, d.d_lane == 0, d.dt);
                    let dh = crate::angles::wrap(me.h - p.h).abs();
                    let front = me.bbox[3] / 2.0 + me.bbox[0];
                    let back = if dh < std::f64::consts::FRAC_PI_2 { p.bbox[3] / 2.0 - p.bbox[0] } else { p.bbox[3] / 2.0 + p.bbox[0] };
                    let gap = ds - front - back;
                    if same_lane && gap > 0.0 && gap < min_gap && dt_lat.abs() < a.lateral_dist {
                        min_gap = gap;
                        lead = Some(i);
                    }
                }
            }
            if lead != Some(i) {
                // Also a vehicle right in front, whatever the lanes say.
                let x = between(self.net, me, p, CoordinateSystem::Entity, RelativeDistanceType::Longitudinal, true);
                let y = between(self.net, me, p, CoordinateSystem::Entity, RelativeDistanceType::Lateral, true);
                if x > 0.0 && x < 1.0 + p.bbox[3] + 0.5 * (a.current_speed - p.speed).max(0.0) && y < 0.2 && y > -0.5 {
                    min_gap = x;
                    lead = Some(i);
                }
            }
        }
        let (max_acc, max_dec) = (me.max_acc, me.max_dec);
        match lead.and_then(|i| self.entities.get(i)) {
            Some(l) => {
                if min_gap < 1.0 {
                    a.current_speed = 0.0;
                } else {
                    let follow = MIN_DIST + a.time_gap * a.current_speed.max(l.speed).abs();
                    let dist_factor = ((min_gap - follow) / follow).min(1.0);
                    let dv_min = a.current_speed - a.set_speed.min(l.speed);
                    let dv_set = a.current_speed - a.set_speed;
                    let acc = (2.5 * dist_factor - dist_factor * dv_set - (1.0 - dist_factor) * dv_min).clamp(-max_dec, max_acc);
                    // Never faster than the set speed when following.
                    a.current_speed = (a.current_speed + acc * dt).max(0.0).min(a.set_speed);
                }
            }
            None => {
                let acc = ((a.set_speed - a.current_speed) * ACCELERATION_FACTOR * max_acc).clamp(-max_dec, ACCELERATION_FACTOR * max_acc);
                let v = a.current_speed + acc * dt;
                a.current_speed = if (v - a.set_speed).abs() > (a.current_speed - a.set_speed).abs() { a.set_speed } else { v };
            }
        }
        let net = self.net;
        let random = &mut self.random;
        let Some(en) = self.entities.get_mut(e) else { return };
        // In override mode esmini's ACC moves the entity along s whether or not an action moved
        // it this step (ControllerACC::Step: MoveAlongS); an action that keeps its own position
        // (a lane change: LatLaneChangeAction::Step restores `internal_pos_`) starts from there
        // again next step, so the log shows the ACC's move on top. That move is Object::MoveAlongS,
        // the default controller's own: it follows an assigned route (Position::MoveAlongS with
        // updateRoute, MoveRouteDS) and takes a junction arm by the object's drawn selector angle.
        if a.override_mode {
            match (net, en.lane) {
                (Some(net), Some(mut lp)) => {
                    let pedestrian = en.kind == crate::entities::EntityKind::Pedestrian;
                    let status = move_along_route_drawing(net, &mut lp, a.current_speed * dt, en.route.as_deref(), random, pedestrian);
                    // Position::MoveAlongS flags the end of the road when no connection
                    // continues the lane, and after any move that ends at a road end without
                    // a road link (one of 0 m too: a stopped ACC stays at the end).
                    a.at_end = status == MoveStatus::EndOfRoad || at_unlinked_road_end(net, &lp);
                    en.set_lane_pos(net, lp);
                }
                // Off every road (no road network, or a position esmini never placed on one):
                // Position::MoveAlongS returns an error without moving (track_idx_ undefined).
                _ => a.at_end = false,
            }
            en.moved_by_action = true;
        }
        en.speed = a.current_speed;
        // Controller::Step marks the longitudinal domain as driven; an active entity's marks are
        // cleared after the step, a deleted one keeps it, so the default controller does not
        // move it in the step it is added back.
        if !en.active {
            en.moved_by_action = true;
        }
    }
}
