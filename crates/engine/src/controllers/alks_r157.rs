//! ALKS_R157SM_Controller, as esmini's UN R157 ALKS safety models. Each step the model scans the
//! entities ahead (same or neighbour lane, pedestrians anywhere; within its range), picks the one
//! to focus on (closest threat: same lane = deceleration / cut-out, neighbour lane intruding =
//! cut-in), decides whether the situation is critical and then brakes; otherwise a simple cruise
//! control (if `cruise`) keeps the set speed (the speed at activation) or follows the target.
//!
//! Models: `Regulation` (reaction time 0.35 s, brakes at 6 m/s² once TTC < dv/12 + 0.45 s; a
//! cut-in when the intruder's front wheel is 0.3 m inside the ego lane) and `ReferenceDriver`
//! (perceive 0.4 s, react 0.75 s with 0.4 m/s² release deceleration, then brake with a jerk
//! limited ramp to 0.774 g; AEB at `aebTTC` to 0.85 g; cut-in perception on the lateral
//! wandering threshold 0.375 m or `lateralTrigDistance`); `RSS` and `FSM` (safe-distance
//! formulas, in `distance_models.rs`). Distances are free space in road coordinates (s, t).

mod distance_models;
mod overlap;
pub(crate) mod state;

use state::{AlksR157Rt, Info, Mode, Model, Phase, Scen, Trigger};

use crate::angles::wrap;
use crate::entities::EntityKind;
use crate::roads::move_along_route_drawing;
use crate::roads::road_follow::{at_unlinked_road_end, MoveStatus};
use crate::sim::Sim;
use openscenario::{Controller, EntityObject, VehicleCategory};

// CommonMini's SMALL_NUMBER (1e-6), every tolerance of ControllerALKS_R157SM
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL;
const LARGE: f64 = 1e10;

impl Info {
    fn empty() -> Info {
        Info { obj: None, dist_long: LARGE, dist_lat: LARGE, dv_s: 0.0, dv_t: 0.0, ttc: LARGE, thw: LARGE, dlane: 0, action: Scen::None }
    }
}

/// Road-frame state of one entity for the model.
#[derive(Debug, Clone, Copy)]
struct Frame {
    s: f64,
    t: f64,
    lane: i32,
    road: usize,
    offset: f64,
    /// heading relative to the road
    hrel: f64,
    v_s: f64,
    v_t: f64,
    acc_s: f64,
    lane_width: f64,
}

impl AlksR157Rt {
    /// The runtime state, and a note when the model is not one of the two modelled.
    pub(crate) fn new(c: &Controller) -> (AlksR157Rt, Option<String>) {
        let p = |n: &str| c.properties.get(n).map(|s| s.trim().to_string());
        let num = |n: &str| p(n).and_then(|v| v.parse::<f64>().ok());
        let name = p("model").unwrap_or_default();
        let (model, note) = match name.as_str() {
            "Regulation" => (Model::Regulation, None),
            "ReferenceDriver" => (Model::ReferenceDriver, None),
            "RSS" => (Model::Rss, None),
            "FSM" => (Model::Fsm, None),
            other => (Model::ReferenceDriver, Some(format!("ALKS_R157SM model `{other}` is not modelled; ReferenceDriver drives"))),
        };
        let (rt, mut max_dec, max_range) = match model {
            Model::Regulation => (0.35, 6.0, 46.0),
            Model::ReferenceDriver | Model::Rss => (0.75, 0.774 * 9.81, 100.0),
            // FSM's detection range is the Regulation's (ControllerALKS_R157SM::FSM::FSM)
            Model::Fsm => (0.75, 0.774 * 9.81, 46.0),
        };
        // the ReferenceDriver's braking properties (ControllerALKS_R157SM's constructor reads
        // them for that model only; a negative deceleration has its sign swapped)
        let reference = model == Model::ReferenceDriver;
        if let Some(d) = num("driverDeceleration").filter(|_| reference) {
            max_dec = d.abs();
        }
        let lat_trig = num("lateralTrigDistance");
        let trigger = match lat_trig {
            Some(th) => Trigger { wandering: false, base: th, threshold: th, active: false, obj: None, t0: 0.0 },
            None => Trigger { wandering: true, base: 0.375, threshold: 0.375, active: false, obj: None, t0: 0.0 },
        };
        let rt_ = AlksR157Rt {
            active: false,
            longitudinal: true,
            lateral: true,
            override_mode: p("mode").as_deref() != Some("additive"),
            model,
            rt,
            max_dec,
            max_range,
            set_speed: 0.0,
            acc: 0.0,
            cruise: !matches!(p("cruise").as_deref(), Some("false") | Some("False")),
            full_stop: p("fullStop").as_deref() == Some("true"),
            always_trig: p("alwaysTrigOnScenario").as_deref() == Some("true"),
            mode: Mode::NoTarget,
            scen: Scen::None,
            focus: Info::empty(),
            phase: Phase::Inactive,
            timer: 0.0,
            time_mode: p("cutInPerceptionDelayMode").as_deref() == Some("Time"),
            perception_t: 0.0,
            perception_dist: 0.72,
            perception_time: 0.4,
            ped_eval_time: num("pedestrianRiskEvaluationTime").unwrap_or(0.4),
            aeb_ttc: num("aebTTC").unwrap_or(1.5),
            aeb_active: false,
            aeb_dec: num("aebDeceleration").filter(|_| reference).map_or(0.85 * 9.81, f64::abs),
            aeb_available: !(reference && p("aebAvailable").as_deref() == Some("false")),
            overlap_tol: num("overlapTolerance").unwrap_or(0.1),
            trigger,
            speed_now: 0.0,
            dt: 0.0,
            at_end: false,
            rt_counter: 0.0,
            cfs: 0.0,
            pfs: 0.0,
        };
        (rt_, note)
    }

    /// ControllerALKS_R157SM::Activate: it operates on both domains, so it is active on either
    /// one asked for, and steps (moving the entity in override mode) whichever it is; only when
    /// it holds the longitudinal one does the default controller leave the entity alone
    /// (ScenarioEngine::defaultController: `IsControllerModeOnDomains(MODE_OVERRIDE, LONG)`).
    pub(crate) fn activate(&mut self, speed: f64, lateral: bool, longitudinal: bool) {
        self.set_speed = speed;
        if lateral || longitudinal {
            self.active = true;
            self.longitudinal = longitudinal;
            self.lateral = lateral;
        }
    }

    /// Model::MinDist: the gap the cruise control keeps at ego speed `v` behind a lead at
    /// `lead_speed` (only FSM's formula uses the lead's speed).
    fn min_dist(&self, v: f64, lead_speed: f64) -> f64 {
        match self.model {
            Model::Regulation => {
                let tg = if v * 3.6 < 10.0 { 1.0 + (v.max(2.0) - 2.0) / 7.8 } else { 1.0 + v * 3.6 / 100.0 };
                (v * tg).max(2.0)
            }
            Model::ReferenceDriver => 2.0 + v * 2.0,
            Model::Rss => distance_models::rss_min_dist(self, v),
            Model::Fsm => distance_models::fsm_min_dist(self, v, lead_speed),
        }
    }

    fn reset(&mut self) {
        self.phase = Phase::Inactive;
        self.scen = Scen::None;
    }
}

// esmini's SIGN: 1 for zero
use distance_models::esmini_sign as sign;

impl<'a> Sim<'a> {
    fn alks_frame(&self, i: usize) -> Option<Frame> {
        let net = self.net?;
        let en = self.entities.get(i)?;
        let lp = en.lane?;
        let pose = lp.pose(net)?;
        let hrel = wrap(en.h - pose.road_heading);
        let (c, s) = (pose.road_heading.cos(), pose.road_heading.sin());
        let v_s = en.vel.0 * c + en.vel.1 * s;
        let v_t = -en.vel.0 * s + en.vel.1 * c;
        let lane_width = pose.lane.map(|(a, b)| (b - a).abs()).unwrap_or(0.0);
        Some(Frame { s: lp.s, t: pose.t, lane: lp.lane_id, road: lp.road, offset: lp.offset, hrel, v_s, v_t, acc_s: en.accel * hrel.cos(), lane_width })
    }

    /// esmini's Model::Process: measurements of `info.obj` from the ego `e`. false: not relevant.
    fn alks_process(&self, e: usize, a: &AlksR157Rt, info: &mut Info) -> bool {
        let Some(o) = info.obj else { return false };
        if o == e || !self.entities.get(o).is_some_and(|x| x.active) {
            return false;
        }
        let (Some(fe), Some(fo)) = (self.alks_frame(e), self.alks_frame(o)) else { return false };
        let Some(net) = self.net else { return false };
        let dir = if fe.hrel.abs() > std::f64::consts::FRAC_PI_2 { -1.0 } else { 1.0 };
        let (ds_ref, mut dlane) = if fe.road == fo.road {
            // Position::Delta's dLaneId is the plain difference of the lane ids (the road's
            // frame, not the ego's), less the centre lane between them (below)
            (((fo.s - fe.s) * dir), fo.lane - fe.lane)
        } else {
            // on another road: Position::Delta forward along the road path, within the range
            let (Some(la), Some(lb)) = (self.entities[e].lane, self.entities[o].lane) else { return false };
            let Some(d) = crate::controllers::forward_delta::forward_delta(net, &la, self.entities[e].h, &lb, a.max_range) else { return false };
            (d.ds, d.d_lane)
        };
        if ds_ref.abs() > a.max_range {
            return false;
        }
        if dlane == 2 && fo.lane == 1 && fe.lane == -1 {
            dlane = 1;
        } else if dlane == -2 && fo.lane == -1 && fe.lane == 1 {
            dlane = -1;
        }
        let ped = self.entities[o].kind == EntityKind::Pedestrian;
        if !(ds_ref > SMALL && (ped || (dlane > -2 && dlane < 2))) {
            return false;
        }
        info.dlane = dlane;
        // Object::FreeSpaceDistanceObjectRoadLane: corners off the ego's road are measured
        // along the road path
        let (ego, other) = (&self.entities[e], &self.entities[o]);
        let gap = crate::conditions::free_space::free_space_road(net, ego, other, fe.road, dir)
            .or_else(|| crate::conditions::free_space::free_space_roads(net, ego, other, fe.road));
        let Some(gap) = gap else { return false };
        info.dist_lat = gap.dt;
        info.dist_long = gap.ds;
        info.dv_s = (fe.v_s - fo.v_s) * dir;
        info.dv_t = (fe.v_t - fo.v_t) * sign(fo.t - fe.t);
        // the headway is measured whenever the ego moves along s, whatever the closing speed
        info.thw = if fe.v_s > 0.0 { info.dist_long / fe.v_s } else { LARGE };
        info.ttc = if info.dv_s > 0.0 { info.dist_long / info.dv_s } else { LARGE };
        true
    }

    fn alks_trigger_update(&self, a: &mut AlksR157Rt, info: &Info, fe: &Frame) {
        let tr = &mut a.trigger;
        let Some(o) = info.obj.filter(|_| info.dv_t >= SMALL) else {
            if tr.active {
                tr.active = false;
                tr.obj = None;
                tr.t0 = 0.0;
            }
            return;
        };
        if Some(o) != tr.obj {
            let Some(fo) = self.alks_frame(o) else { return };
            tr.obj = Some(o);
            tr.active = true;
            tr.t0 = fo.t;
            if tr.wandering {
                // WanderingTrigger::Update: a motorbike already on the ego's side of its lane
                // centre keeps the plain threshold
                let motorbike =
                    matches!(self.scenario.entities.get(o).map(|x| &x.object), Some(EntityObject::Vehicle(v)) if v.category == VehicleCategory::Motorbike);
                tr.threshold = tr.base;
                if (fo.t > fe.t && fo.offset > 0.0) || (fo.t < fe.t && fo.offset < 0.0) {
                    tr.threshold += fo.offset.abs();
                } else if !motorbike {
                    tr.threshold = (tr.threshold - fo.offset.abs()).max(0.0);
                }
            }
        }
    }

    fn alks_trigger_eval(&self, a: &AlksR157Rt) -> bool {
        let tr = &a.trigger;
        match (tr.active, tr.obj) {
            (true, Some(o)) => self.alks_frame(o).is_some_and(|f| (f.t - tr.t0).abs() > tr.threshold),
            _ => false,
        }
    }

    /// CheckSafety: true when the object is no threat; sets `info.action`.
    fn alks_check_safety(&self, e: usize, a: &mut AlksR157Rt, info: &mut Info) -> bool {
        let Some(o) = info.obj else { return true };
        if info.dist_lat == LARGE {
            return true;
        }
        let (Some(fe), Some(fo)) = (self.alks_frame(e), self.alks_frame(o)) else { return true };
        let oe = &self.entities[o];
        match a.model {
            Model::Regulation => {
                if info.dlane == 0 {
                    info.action = Scen::Deceleration;
                    return false;
                }
                if info.dist_lat > -SMALL {
                    let x = match self.scenario.entities.get(o).map(|x| &x.object) {
                        Some(EntityObject::Vehicle(v)) if oe.kind == EntityKind::Vehicle => v.axles.front.map(|f| f.position_x).unwrap_or(oe.bbox[3] / 2.0),
                        _ => oe.bbox[3] / 2.0,
                    };
                    let y = -sign(info.dlane as f64) * oe.bbox[4] / 2.0;
                    let yr = x * fo.hrel.sin() + y * fo.hrel.cos();
                    let offset = (fo.offset + yr) * -sign(info.dlane as f64);
                    if offset > fo.lane_width / 2.0 + 0.3 {
                        info.action = Scen::CutIn;
                        return false;
                    }
                }
                true
            }
            Model::Rss => distance_models::rss_check_safety(info, &fo, a),
            Model::Fsm => distance_models::fsm_check_safety(info, &fo, self.entities[e].speed, oe.speed),
            Model::ReferenceDriver => {
                let c_lane_offset = fo.offset + oe.bbox[0] * oe.h.sin();
                self.alks_trigger_update(a, info, &fe);
                if oe.kind == EntityKind::Pedestrian {
                    if info.dv_t > SMALL {
                        info.action = Scen::CutIn;
                        return false;
                    }
                } else if info.dlane == 0 {
                    if c_lane_offset.abs() > 0.375 && info.dv_t < -SMALL {
                        info.action = Scen::CutOut;
                    } else if -sign(fo.lane as f64) * fo.acc_s < -5.0 + SMALL {
                        info.action = Scen::Deceleration;
                    }
                    return false;
                } else if self.alks_trigger_eval(a) {
                    info.action = Scen::CutIn;
                    return false;
                } else if info.action == Scen::CutIn {
                    info.action = Scen::None;
                }
                true
            }
        }
    }

    fn alks_detect(&self, e: usize, a: &mut AlksR157Rt) {
        let mut cand = Info::empty();
        let is_vehicle = |i: Option<usize>| i.is_some_and(|i| self.entities[i].kind == EntityKind::Vehicle);
        // Model::Detect's scratch record starts empty in every call and carries over from one
        // entity to the next (Process leaves it alone for entities it skips)
        let mut tmp = Info::empty();
        for i in 0..self.entities.len() {
            tmp.obj = Some(i);
            let ok = self.alks_process(e, a, &mut tmp);
            if ok && !self.alks_check_safety(e, a, &mut tmp) {
                let cand_cutout = is_vehicle(cand.obj) && cand.action == Scen::CutOut;
                if tmp.dist_long < cand.dist_long || (tmp.dlane == 0 && cand_cutout) {
                    if is_vehicle(tmp.obj) && tmp.action == Scen::CutOut && cand.obj.is_some() && cand.dlane == 0 {
                        if tmp.ttc < cand.ttc {
                            cand = tmp;
                        }
                    } else if tmp.dlane == 0 && cand_cutout {
                        if tmp.ttc < cand.ttc {
                            cand = tmp;
                            cand.action = Scen::CutOut;
                        }
                    } else {
                        cand = tmp;
                    }
                }
            }
        }
        if cand.obj.is_some() && cand.action != Scen::None && (cand.obj != a.focus.obj || cand.action != a.focus.action) {
            a.scen = cand.action;
        }
        a.focus = cand;
    }

    fn alks_cruise(&self, _e: usize, a: &mut AlksR157Rt, v: f64) -> f64 {
        if a.cruise {
            if a.focus.obj.is_none() {
                a.mode = Mode::NoTarget;
                a.acc = if (v - a.set_speed).abs() < SMALL {
                    0.0
                } else if v > a.set_speed {
                    -2.0
                } else {
                    2.0
                };
                return crate::dynamics::esmini_clamp(v + a.acc * a.dt, 0.0, a.set_speed);
            } else if a.focus.dist_long > 0.0 && a.focus.ttc > a.focus.dv_s / 12.0 + 0.35 {
                a.mode = Mode::TargetInSight;
                a.acc =
                    if v.abs() < SMALL { 0.0 } else { (2.0 * -a.focus.dv_s + (a.focus.dist_long - a.min_dist(v, self.alks_focus_speed(a)))).clamp(-4.0, 3.0) };
                return crate::dynamics::esmini_clamp(v + a.acc * a.dt, 0.0, a.set_speed);
            }
        }
        a.acc = 0.0;
        v
    }

    /// The speed of the object in focus (Object::GetSpeed), 0 without one.
    fn alks_focus_speed(&self, a: &AlksR157Rt) -> f64 {
        a.focus.obj.and_then(|o| self.entities.get(o)).map(|en| en.speed).unwrap_or(0.0)
    }

    fn alks_check_critical(&self, e: usize, a: &mut AlksR157Rt, v: f64) -> bool {
        let dt = a.dt;
        match a.model {
            Model::Regulation => {
                if a.focus.obj.is_none() {
                    a.mode = Mode::NoTarget;
                    return false;
                } else if a.mode == Mode::Critical && a.full_stop {
                    return true;
                } else if a.focus.dv_s > 0.0 && a.focus.dist_long > 0.0 && a.focus.ttc < a.focus.dv_s / (2.0 * a.max_dec) + a.rt + 0.1 {
                    a.mode = Mode::Critical;
                    return true;
                }
                a.mode = Mode::TargetInSight;
                false
            }
            Model::Rss => distance_models::rss_check_critical(a, v, self.alks_focus_speed(a)),
            Model::Fsm => {
                let acc_s = self.alks_frame(e).map(|f| f.acc_s).unwrap_or(0.0);
                distance_models::fsm_check_critical(a, v, self.alks_focus_speed(a), acc_s)
            }
            Model::ReferenceDriver => {
                if a.phase == Phase::Inactive || a.phase == Phase::Perceive {
                    if self.alks_check_perception(a) {
                        a.phase = Phase::React;
                        a.timer = a.rt;
                    }
                } else if a.phase == Phase::React {
                    a.timer -= dt;
                }
                if a.mode == Mode::NoTarget && a.focus.obj.is_some() {
                    a.mode = Mode::TargetInSight;
                }
                if a.full_stop && a.mode == Mode::Critical {
                    if v < SMALL {
                        a.reset();
                        a.mode = if a.focus.obj.is_some() { Mode::TargetInSight } else { Mode::NoTarget };
                    }
                } else if a.focus.obj.is_none() {
                    a.reset();
                    a.mode = Mode::NoTarget;
                } else if (v > SMALL && a.focus.dist_long > 0.0) || a.full_stop {
                    self.alks_check_critical_condition(a);
                }
                // ReferenceDriver::UpdateAEB
                if let Some(o) = a.focus.obj {
                    if a.aeb_available
                        && !a.aeb_active
                        && a.focus.ttc < a.aeb_ttc
                        && overlap::covers_or_inside_front(&self.entities[e], &self.entities[o], a.overlap_tol)
                    {
                        a.aeb_active = true;
                    }
                }
                a.mode == Mode::Critical || a.aeb_active
            }
        }
    }

    fn alks_check_perception(&self, a: &mut AlksR157Rt) -> bool {
        let dt = a.dt;
        let ped = a.focus.obj.is_some_and(|o| self.entities[o].kind == EntityKind::Pedestrian);
        match a.scen {
            Scen::CutIn => {
                if a.phase == Phase::Inactive {
                    if ped && a.focus.dv_s > SMALL {
                        a.timer = a.ped_eval_time;
                        a.phase = Phase::Perceive;
                    } else if self.alks_trigger_eval(a) {
                        a.perception_t = a.focus.obj.and_then(|o| self.alks_frame(o)).map(|f| f.t).unwrap_or(0.0);
                        if a.time_mode {
                            a.timer = a.perception_time;
                        } else {
                            a.perception_dist = 0.72;
                        }
                        a.phase = Phase::Perceive;
                    }
                } else if a.phase == Phase::Perceive {
                    if ped {
                        if a.focus.dv_s > SMALL {
                            a.timer -= dt;
                            if a.timer < SMALL {
                                a.phase = Phase::React;
                            }
                        }
                    } else if a.time_mode {
                        a.timer -= dt;
                        if a.timer < SMALL {
                            a.phase = Phase::React;
                        }
                    } else if let Some(o) = a.focus.obj {
                        let to = self.alks_frame(o).map(|f| f.t).unwrap_or(0.0);
                        if (to - a.perception_t).abs() > a.perception_dist {
                            a.phase = Phase::React;
                        }
                    }
                    if a.phase == Phase::React {
                        a.timer = a.rt;
                        return true;
                    }
                }
                false
            }
            Scen::CutOut | Scen::Deceleration => {
                if a.phase == Phase::Inactive {
                    let start = if a.scen == Scen::CutOut {
                        a.focus.dv_s > SMALL
                    } else {
                        a.focus.obj.and_then(|o| self.alks_frame(o)).is_some_and(|f| f.acc_s < -5.0)
                    };
                    if start {
                        a.phase = Phase::Perceive;
                        a.timer = a.perception_time;
                    }
                } else if a.phase == Phase::Perceive {
                    a.timer -= dt;
                    return a.timer < SMALL;
                }
                false
            }
            Scen::None => false,
        }
    }

    fn alks_check_critical_condition(&self, a: &mut AlksR157Rt) {
        let crit = match a.scen {
            Scen::CutIn => a.focus.ttc < 2.0,
            Scen::CutOut | Scen::Deceleration => a.focus.thw < 2.0,
            Scen::None => return,
        };
        if a.always_trig || crit {
            if a.phase == Phase::React && a.timer < SMALL {
                a.mode = Mode::Critical;
            }
        } else if a.phase == Phase::React {
            a.reset();
        } else if a.mode == Mode::Critical && a.focus.dist_long > a.min_dist(a.speed_now, 0.0) {
            // critical until out of the minimum distance
            a.mode = if a.focus.obj.is_some() { Mode::TargetInSight } else { Mode::NoTarget };
            if a.focus.dv_s < SMALL {
                a.reset();
            }
        }
    }

    fn alks_react(&self, a: &mut AlksR157Rt, v: f64) -> f64 {
        let dt = a.dt;
        match a.model {
            Model::Regulation => {
                a.acc = -a.max_dec;
                (v + a.acc * dt).max(0.0)
            }
            Model::Rss => distance_models::rss_react(a, v, dt),
            Model::Fsm => distance_models::fsm_react(a, v, dt),
            Model::ReferenceDriver => {
                if a.phase == Phase::React && a.timer < SMALL {
                    a.phase = Phase::BrakeRef;
                }
                if (a.phase == Phase::BrakeRef || a.aeb_active) && v < SMALL {
                    a.phase = Phase::Inactive;
                    a.aeb_active = false;
                    a.timer = 0.0;
                }
                if a.phase == Phase::React {
                    a.acc = (-0.4f64).min(a.acc);
                } else if a.phase == Phase::BrakeRef {
                    a.acc -= dt * a.max_dec / 0.6;
                }
                if a.aeb_active {
                    a.acc -= dt * a.aeb_dec / 0.6;
                }
                a.acc = if a.aeb_active { a.acc.max(-a.aeb_dec) } else { a.acc.max(-a.max_dec) };
                (v + a.acc * dt).max(0.0)
            }
        }
    }

    /// Step every active ALKS R157 controller by `dt`, after the default controller: esmini's
    /// ScenarioEngine::step moves the entities first and then steps the controllers, so the
    /// model measures the others where they are after this step's move. Frame 0 steps them too
    /// (dt 0), after the Init actions: the model sees no velocities yet (none is measured before
    /// the first step), so it detects its target without closing speed and runs its cruise
    /// control, whose acceleration the reaction phase of the next steps keeps (Model::Step).
    /// Stepped by `step_controllers_in_order`.
    pub(super) fn step_alks_r157(&mut self, e: usize, a: &mut AlksR157Rt, dt: f64) {
        // ScenarioEngine::step checks every object's position status before it steps the
        // controllers, whoever moved it: the status the model's last move left is noted (the
        // EndOfRoadCondition's stamp, in `after_move`), and an entity noted there a step before
        // that did not move since gets speed 0 ("enforce zero speed"), which the model reads.
        // (Active laterally only, the default controller moves it and checks that itself.)
        if a.override_mode && a.longitudinal {
            if let Some(en) = self.entities.get_mut(e) {
                en.at_road_end = a.at_end;
                en.stop_if_stuck_at_road_end();
            }
        }
        let Some(v) = self.entities.get(e).map(|en| en.speed) else { return };
        a.speed_now = v;
        a.dt = dt;
        if a.focus.obj.is_some() && a.model == Model::ReferenceDriver && a.phase != Phase::Inactive && a.full_stop {
            let mut f = a.focus;
            self.alks_process(e, a, &mut f);
            a.focus = f;
        } else {
            self.alks_detect(e, a);
        }
        let speed = if self.alks_check_critical(e, a, v) { self.alks_react(a, v) } else { self.alks_cruise(e, a, v) };
        let net = self.net;
        let random = &mut self.random;
        let Some(en) = self.entities.get_mut(e) else { return };
        // Active on the lateral domain only, the default controller has moved the entity
        // already, and this moves it again (ControllerALKS_R157SM::Step moves it in override
        // mode). In frame 0 (dt 0) esmini's MoveAlongS(0) still puts the entity where its road
        // coordinates are: one placed before the road's start or past its end lands on it.
        // The move is Object::MoveAlongS, the default controller's and the ACC's: it follows an
        // assigned route and takes a junction arm by the object's selector angle. It is made
        // whatever moved the entity before in this step (another controller in override mode
        // beside it, an action).
        if a.override_mode {
            match (net, en.lane) {
                (Some(net), Some(mut lp)) => {
                    let status = move_along_route_drawing(net, &mut lp, speed * dt, en.route.as_deref(), random, false);
                    // As the ACC's move (`acc.rs`): Position::MoveAlongS flags the end of the
                    // road when no connection continues the lane, or a move ends at an end
                    // without a road link.
                    a.at_end = status == MoveStatus::EndOfRoad || at_unlinked_road_end(net, &lp);
                    en.set_lane_pos(net, lp);
                }
                _ => {
                    a.at_end = false;
                    en.x += speed * dt * en.h.cos();
                    en.y += speed * dt * en.h.sin();
                }
            }
        }
        en.speed = speed;
    }
}
