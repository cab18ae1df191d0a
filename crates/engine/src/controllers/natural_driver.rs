//! NaturalDriver, as esmini 3.6 has it (ControllerNaturalDriver): a longitudinal driver model
//! (IDM: acceleration `a·(1 − (v/v0)⁴) − a·(s*/s)²`, desired gap `s* = s0 + max(0, v·T +
//! v·Δv/(2√(a·b)))`, deceleration clipped at `maxDec`) that also decides lane changes the MOBIL
//! way and performs them by injecting a LaneChangeAction (sinusoidal over `laneChangeDuration`)
//! that starts on the next frame, as esmini's player server does.
//!
//! Each frame, after every other entity moved (esmini steps controllers last): it finds the
//! closest vehicles ahead and behind in its lane and the two lanes beside it (within
//! `lookAheadDistance`, straight-line, then along the roads); while driving it takes the IDM
//! acceleration behind its leader and, unless a lane change is cooling down, tries the left then
//! the right driving lane. A change is possible when the new follower would not brake harder than
//! `maxImposedBraking`; into the `route` lane also when it itself would not; into any other lane
//! only when its gain plus `politeness` × the followers' gains exceeds `laneChangeAccGain`. From
//! the injection the speed is held for `laneChangeDuration`, and no new change is tried before
//! `laneChangeDuration + laneChangeDelay` have passed. The speed never exceeds `desiredSpeed`;
//! the entity moves along its lane by speed·dt (during a lane change the action's own move
//! counts, esmini restoring the action's position each frame). No randomness is involved.
//!
//! Like esmini: the speed jumps down to `desiredSpeed` when above it, a second NaturalDriver
//! changing into the same lane close by aborts the change, a positive `maxDec` is a lower bound
//! of the acceleration (ControllerNaturalDriver::Step clips from below at it), and a change found
//! worth it while standing still is injected towards lane 0 (the reference line) without leaving
//! the driving state. In the additive `mode` the default controller moves the entity by its speed
//! before the driver moves it again, as in esmini.

pub(crate) mod distance_cache;
pub(crate) mod state;
pub(crate) mod view;

use state::{Mode, NaturalDriverRt, NdParams};

use self::view::{adjacent_lanes, desired_gap, freespace, Vois, FOLLOWING, LEAD, LEFT_FOLLOW, LEFT_LEAD, RIGHT_FOLLOW, RIGHT_LEAD, SMALL_NUMBER};
use super::state::ControllerRt;
use crate::actions::lane_change::state::LaneChangeRt;
use crate::dynamics::{sign, Transition};
use crate::roads::lane_geometry::lane_center_t;
use crate::roads::{move_along_route_drawing, LanePos, MoveStatus};
use crate::sim::Sim;
use crate::trace::StoryboardEvent;
use openscenario::{Controller, DynamicsDimension, DynamicsShape};

impl NdParams {
    fn from_properties(c: &Controller) -> NdParams {
        let num = |n: &str, d: f64| c.properties.get(n).map_or(d, strtod);
        let int = |n: &str, d: i32| c.properties.get(n).map_or(d, strtoi);
        NdParams {
            desired_distance: num("desiredDistance", 20.0),
            desired_speed: num("desiredSpeed", 15.0).max(SMALL_NUMBER),
            // A double, as ControllerNaturalDriver keeps it: its lane-change cooldown
            // (duration + delay, counted down by dt each step) ends on the step the double
            // says; the lane change it injects runs over the duration as a float.
            lane_change_duration: num("laneChangeDuration", 3.0),
            lookahead: num("lookAheadDistance", 115.0),
            // As given: esmini clips the acceleration from below at `maxDec`, so a positive
            // value makes the car speed up at least that hard, and the desired gap's √(−a·b)
            // is then NaN, which std::max(0, NaN) (and f64::max) turn into 0.
            max_dec: num("maxDec", -3.0),
            max_acc: num("maxAcc", 3.0),
            lane_change_delay: num("laneChangeDelay", 1.0),
            thw: num("thw", 2.0),
            max_imposed_braking: num("maxImposedBraking", 3.0),
            politeness: num("politeness", 0.5),
            lane_change_acc_gain: num("laneChangeAccGain", 0.2),
            route: int("route", -1),
        }
    }
}

/// C's strtod: the longest leading number, 0 when there is none.
fn strtod(text: &str) -> f64 {
    let t = text.trim_start();
    (1..=t.len()).rev().filter(|&k| t.is_char_boundary(k)).find_map(|k| t[..k].parse::<f64>().ok()).unwrap_or(0.0)
}

/// C's strtol in base 10: the leading integer, 0 when there is none.
fn strtoi(text: &str) -> i32 {
    let t = text.trim_start();
    let end = t.char_indices().find(|&(i, ch)| !(ch.is_ascii_digit() || (i == 0 && (ch == '-' || ch == '+')))).map_or(t.len(), |(i, _)| i);
    t[..end].parse::<i64>().map_or(0, |v| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32)
}

impl NaturalDriverRt {
    pub(crate) fn new(c: &Controller) -> NaturalDriverRt {
        let p = NdParams::from_properties(c);
        let cooldown = p.lane_change_duration + p.lane_change_delay;
        NaturalDriverRt {
            active: false,
            override_mode: c.properties.get("mode") != Some("additive"),
            p,
            current_speed: 0.0,
            mode: Mode::Drive,
            lane_change_injected: false,
            cooldown,
            target_lane: 0,
            pending: None,
            lane_change: None,
            injections: 0,
            action_yaw: None,
        }
    }

    /// The controller works on the longitudinal domain only.
    pub(crate) fn activate(&mut self, speed: f64, longitudinal: bool) {
        if longitudinal {
            self.active = true;
            self.current_speed = speed;
        }
    }
}

impl<'a> Sim<'a> {
    /// Before the default controller: start or step the injected lane change, and keep the
    /// default controller off the entity in override mode or while that lane change steps. In
    /// additive mode esmini's default controller moves the entity by its speed first and
    /// ControllerNaturalDriver::Step moves it again (its MoveAlongS whatever the mode), so
    /// it advances twice per step; a stepping LatLaneChangeAction marks the longitudinal
    /// motion as done (its dirty bits), a starting one does not.
    pub(super) fn step_natural_driver_action(&mut self, e: usize, nd: &mut NaturalDriverRt, dt: f64) {
        let time = self.time - dt;
        // No lane change of its own stepped yet: the move keeps the heading relative to the
        // road (the driver acts on the longitudinal domain only, so nothing aligns the heading;
        // Position::MoveAlongS keeps h_relative).
        nd.action_yaw = None;
        let mut stepped = false;
        if let Some((lane, name)) = nd.pending.take() {
            if let Some(rt) = self.nd_start_lane_change(e, lane, nd.p.lane_change_duration as f32 as f64) {
                self.nd_event(time, &name, "init", "start", "running");
                nd.lane_change = Some((rt, name));
            }
        } else if let Some((mut lc, name)) = nd.lane_change.take() {
            stepped = true;
            if self.step_lane_change(e, &mut lc) {
                nd.action_yaw = Some(0.0);
                self.nd_event(time, &name, "running", "end", "complete");
            } else {
                nd.action_yaw = Some(self.entities.get(e).map_or(0.0, |en| en.yaw_offset));
                nd.lane_change = Some((lc, name));
            }
        }
        // In override mode the default controller leaves the entity to the driver; in additive
        // mode it moves it by its speed first, and the driver's own MoveAlongS adds its step
        // (ScenarioEngine::defaultController, ControllerNaturalDriver::Step): twice the way,
        // unless a stepping lane change has marked the longitudinal motion done.
        if let Some(en) = self.entities.get_mut(e).filter(|_| nd.override_mode || stepped) {
            en.moved_by_action = true;
        }
    }

    /// After every other entity moved: the driver's decision and move (esmini's Step).
    pub(super) fn step_natural_driver(&mut self, e: usize, nd: &mut NaturalDriverRt, dt: f64) {
        let around = self.nd_in_radius(e, nd.p.lookahead);
        let vois = self.nd_vois(e, &around, nd.p.lookahead);
        let mut acc = 0.0;
        let mut initiate = false;
        if nd.mode == Mode::Drive {
            acc = self.nd_idm(&nd.p, Some(e), lead(&vois, LEAD)).max(nd.p.max_dec);
            let moving = self.entities.get(e).is_some_and(|en| en.speed > 0.0);
            let lanes = match (self.net, self.entities.get(e).and_then(|en| en.lane)) {
                (Some(net), Some(lp)) if !nd.lane_change_injected => adjacent_lanes(net, &lp),
                _ => None,
            };
            for (k, &lane) in lanes.iter().flatten().enumerate() {
                if lane == 0 {
                    continue;
                }
                initiate = self.nd_lane_change_possible(e, nd, &vois, lane, k == 0);
                if initiate && moving {
                    nd.target_lane = lane;
                    nd.mode = Mode::ChangeLane;
                    break;
                }
            }
            // Standing still, esmini keeps the flag of the last lane checked and injects all the
            // same (ControllerNaturalDriver::Step): towards the target it has, 0 while driving,
            // so the car slides onto the reference line and stays in DRIVE, accelerating.
        }
        if initiate {
            if self.nd_abort_lane_change(e, nd, &around, &vois) {
                nd.target_lane = 0;
                nd.mode = Mode::Drive;
            } else {
                self.nd_inject(nd);
            }
        }
        if nd.lane_change_injected {
            nd.cooldown -= dt;
            if nd.mode == Mode::ChangeLane && nd.cooldown <= nd.p.lane_change_delay {
                nd.target_lane = 0;
                nd.mode = Mode::Drive;
            }
            if nd.cooldown < 0.0 {
                nd.cooldown = nd.p.lane_change_delay + nd.p.lane_change_duration;
                nd.lane_change_injected = false;
            }
        }
        let max_speed = self.entities.get(e).map_or(f64::INFINITY, |en| en.max_speed);
        nd.current_speed += acc * dt;
        if nd.current_speed >= nd.p.desired_speed {
            nd.current_speed = nd.p.desired_speed;
        } else if nd.current_speed > max_speed {
            nd.current_speed = max_speed;
        } else if nd.current_speed < 0.0 {
            nd.current_speed = 0.0;
        }
        self.nd_move(e, nd.current_speed, dt, nd.action_yaw);
    }

    /// MOBIL check of the lane on the `left` (else right) side (esmini's CheckLaneChangePossible).
    fn nd_lane_change_possible(&self, e: usize, nd: &NaturalDriverRt, v: &Vois, lane: i32, left: bool) -> bool {
        let p = &nd.p;
        let (adj_lead, adj_follow) = if left { (LEFT_LEAD, LEFT_FOLLOW) } else { (RIGHT_LEAD, RIGHT_FOLLOW) };
        let new_follow_acc = self.nd_idm(p, lead(v, adj_follow), lead(v, adj_lead));
        let new_follow_pred = self.nd_idm(p, lead(v, adj_follow), Some(e));
        if new_follow_pred < -p.max_imposed_braking {
            return false;
        }
        let pred_new = self.nd_idm(p, Some(e), lead(v, adj_lead));
        if lane == p.route {
            return pred_new >= -p.max_imposed_braking;
        }
        let now = self.nd_idm(p, Some(e), lead(v, LEAD));
        let old_follow_acc = self.nd_idm(p, lead(v, FOLLOWING), Some(e));
        let old_follow_pred = self.nd_idm(p, lead(v, FOLLOWING), lead(v, LEAD));
        let gain = pred_new - now + p.politeness * (new_follow_pred - new_follow_acc + old_follow_pred - old_follow_acc);
        gain > p.lane_change_acc_gain + SMALL_NUMBER
    }

    /// Another active NaturalDriver close by already changes into the same lane (esmini's
    /// AbortLaneChange).
    fn nd_abort_lane_change(&self, e: usize, nd: &NaturalDriverRt, around: &[usize], v: &Vois) -> bool {
        let Some(me) = self.entities.get(e) else { return false };
        around.iter().any(|&i| {
            let Some(other) = self.controllers_of(i).find_map(|c| if let ControllerRt::NaturalDriver(x) = c { Some(x) } else { None }) else { return false };
            let Some(o) = self.entities.get(i) else { return false };
            if !other.active {
                return false;
            }
            let ds = v.iter().flatten().find(|(k, _)| *k == i).map_or_else(|| self.nd_delta(e, i, true, nd.p.lookahead).0, |&(_, d)| d);
            let free = freespace(me, o, ds);
            let gap = desired_gap(&nd.p, o.speed, nd.current_speed);
            free >= 0.0
                && free < gap
                && other.lane_change_injected
                && other.target_lane == nd.target_lane
                && o.lane.map(|l| l.lane_id) != me.lane.map(|l| l.lane_id)
        })
    }

    /// Queue a lane change to `nd.target_lane`, unless one is queued already (it starts in the
    /// next frame). esmini's player server ends an injected lane change of the entity still
    /// running (PlayerServer::AddAction: "already ongoing …, stopping it") and lists the new one.
    fn nd_inject(&mut self, nd: &mut NaturalDriverRt) {
        if nd.pending.is_none() {
            if let Some((_, name)) = nd.lane_change.take() {
                let time = self.time;
                self.nd_event(time, &name, "running", "end", "complete");
            }
            let n: u32 = self
                .controllers
                .iter()
                .filter_map(|c| c.rt.as_ref())
                .map(|c| if let ControllerRt::NaturalDriver(x) = c { x.injections } else { 0 })
                .sum::<u32>()
                + nd.injections;
            nd.pending = Some((nd.target_lane, format!("LaneChangeAction_{n}")));
            nd.injections += 1;
        }
        nd.lane_change_injected = true;
    }

    /// esmini's LaneChangeAction start with absolute target `lane`, sinusoidal over `duration`.
    fn nd_start_lane_change(&mut self, e: usize, lane: i32, duration: f64) -> Option<LaneChangeRt> {
        let net = self.net?;
        let en = self.entities.get_mut(e)?;
        let lp = en.lane?;
        let road = net.roads.get(lp.road)?;
        let s = lp.s.clamp(0.0, road.length);
        let offset = lane_center_t(road, lp.lane_id, s)? + lp.offset - lane_center_t(road, lane, s)?;
        let mut t = Transition::new(DynamicsShape::Sinusoidal, DynamicsDimension::Time, duration);
        let lane_sign = sign(f64::from(lane));
        t.set_start(lane_sign * offset);
        t.set_target(0.0);
        en.yaw_offset = 0.0;
        Some(LaneChangeRt { transition: t, internal: LanePos { lane_id: lane, offset, ..lp }, missing_lane_sign: None })
    }

    fn nd_event(&mut self, time: f64, name: &str, from: &str, transition: &str, to: &str) {
        self.events.push(StoryboardEvent { time, element: name.to_string(), from: from.into(), transition: transition.into(), to: to.into() });
    }

    /// Move along the lane by speed·dt (straight on without a road), showing `yaw` off the lane
    /// where given (else the turn from the road the entity holds).
    fn nd_move(&mut self, e: usize, speed: f64, dt: f64, yaw: Option<f64>) {
        let net = self.net;
        let random = &mut self.random;
        let Some(en) = self.entities.get_mut(e) else { return };
        match (net, en.lane) {
            (Some(net), Some(mut lp)) => {
                // Object::MoveAlongS, the default controller's own move: a junction tie is
                // broken by a draw from esmini's generator.
                let pedestrian = en.kind == crate::entities::EntityKind::Pedestrian;
                let status = move_along_route_drawing(net, &mut lp, speed * dt, en.route.as_deref(), random, pedestrian);
                if let Some(yaw) = yaw {
                    en.yaw_offset = yaw;
                }
                en.set_lane_pos(net, lp);
                en.at_road_end = status == MoveStatus::EndOfRoad;
            }
            _ => {
                en.x += speed * dt * en.h.cos();
                en.y += speed * dt * en.h.sin();
            }
        }
        en.speed = speed;
        en.moved_by_action = true;
    }
}

fn lead(v: &Vois, slot: usize) -> Option<usize> {
    v.get(slot).copied().flatten().map(|(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::{strtod, strtoi};

    #[test]
    fn numbers_are_read_as_c_reads_them() {
        assert_eq!(strtoi("-3"), -3);
        assert_eq!(strtoi("0.3"), 0);
        assert_eq!(strtoi("x"), 0);
        assert_eq!(strtod("2.5"), 2.5);
        assert_eq!(strtod(" 1e2 m"), 100.0);
        assert_eq!(strtod("abc"), 0.0);
    }
}
