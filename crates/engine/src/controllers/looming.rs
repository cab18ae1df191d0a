//! LoomingController, esmini's driver model that steers by the looming of the road and the car
//! ahead (ControllerLooming::Step), stepped after the default controller, in frame 0 too:
//! - throttle: the lead vehicle (nearest in the lane within 130 m along the road, lateral
//!   offset below 5 m, gap between the bounding boxes) gives `distFactor − distFactor·dvSet −
//!   (1 − distFactor)·dvMin`, without one `setSpeed − speed`, clamped to ±1;
//! - steering: `(1.8·near + 1.3·near' + 1.5·far') / (π/4)`, clamped to ±1, from the angle to
//!   the near point (lane centre 10 m ahead) and to the far point: the tangent point of the
//!   lane's inner edge within 80 m (`looming/view.rs`), else the lead vehicle within 80 m
//!   (esmini's angle from the lead to the entity), else the lane centre 80 m ahead;
//! - esmini's vehicle model (vehicle::Vehicle::DrivingControlAnalog) moves the entity: speed
//!   by max acceleration or deceleration times the throttle, an engine drag of 0.1 % per step
//!   at zero throttle, a handbrake when braking through zero; the wheel turned by the steering
//!   and the kinematic bicycle of `kinematic_vehicle.rs`.

pub(crate) mod state;
pub(crate) mod view;

use state::LoomingRt;

use super::analog_vehicle::AnalogVehicle;
use crate::entities::position_heading;
use crate::roads::road_follow::at_dead_end;
use crate::roads::{move_along_route_drawing, move_along_s};
use crate::sim::Sim;
use openscenario::Controller;

/// Minimum gap to the lead vehicle, m (ControllerLooming::Step `minDist`).
const MIN_DIST: f64 = 3.0;
/// How far along the road a lead vehicle is looked for, m.
const LOOKAHEAD: f64 = 130.0;
/// Largest lateral offset of a lead vehicle, m.
const MIN_LATERAL_DIST: f64 = 5.0;
/// vehicle.cpp: MAX_SPEED_DEFAULT.
const VEHICLE_MAX_SPEED: f64 = 70.0;
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
const LARGE: f64 = 1e10;
/// ControllerLooming's steering rate.
const STEERING_RATE: f64 = 4.0;
/// ControllerLooming::Step: near and far point distances, m; steering gains.
const NEAR_POINT: f64 = 10.0;
const FAR_POINT: f64 = 80.0;
const K0: f64 = 1.8;
const K1: f64 = 1.3;
const K2: f64 = 1.5;

/// What the run says about a LoomingController on roads whose superelevation changes.
pub(crate) const APPROXIMATION: &str =
    "LoomingController: the OSI points of its far tangent point leave out the shorter spacing esmini uses where the road's superelevation changes";

impl LoomingRt {
    /// ControllerLooming's constructor: `timeGap` (1.5 s) and `setSpeed` properties; the mode
    /// is esmini's Controller default, override, unless `mode` says additive.
    pub(crate) fn new(c: &Controller) -> LoomingRt {
        let num = |n: &str| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok());
        LoomingRt {
            active: false,
            time_gap: num("timeGap").unwrap_or(1.5),
            set_speed: num("setSpeed").unwrap_or(0.0),
            set_speed_given: num("setSpeed").is_some(),
            override_mode: c.properties.get("mode") != Some("additive"),
            vehicle: None,
            prev_near: 0.0,
            prev_far: 0.0,
            steering: 0.0,
            osi: Default::default(),
            end_of_road: false,
            placed_at: None,
            placed_h: None,
        }
    }

    /// ControllerLooming::Activate: the vehicle model starts at the entity's speed; the set
    /// speed is the entity's speed unless given in override mode. The controller operates on
    /// the longitudinal domain only.
    /// `h` is the heading esmini's position holds ([`position_heading`]).
    pub(crate) fn activate(&mut self, en: &crate::entities::Entity, longitudinal: bool, h: f64) {
        let (speed, max_acc, max_dec) = (en.speed, en.max_acc, en.max_dec);
        if !longitudinal {
            return;
        }
        self.active = true;
        if !self.override_mode || !self.set_speed_given {
            self.set_speed = speed;
        }
        // vehicle_.SetPos(..., object_->pos_.GetH())
        let car = super::kinematic_vehicle::KinematicVehicle::new(en.x, en.y, h, speed, en.bbox[3], VEHICLE_MAX_SPEED);
        self.vehicle = Some(AnalogVehicle::new(car, max_acc, max_dec, STEERING_RATE));
    }

    /// The speed of its vehicle model (0 before it is activated).
    fn speed(&self) -> f64 {
        self.vehicle.map_or(0.0, |v| v.car.speed)
    }
}

impl<'a> Sim<'a> {
    /// Whether entity `e`'s position is locked on its lane: a looming controller has driven it
    /// (ControllerLooming::Step sets the lock and nothing clears it; its Activate does not, so
    /// a lane change stepped in the frame it is activated attaches the position unlocked).
    pub(crate) fn lane_locked(&self, e: usize) -> bool {
        self.controllers_of(e).any(|c| matches!(c, super::state::ControllerRt::Looming(l) if l.placed_h.is_some()))
    }

    /// Controller::Activate of a controller that aligns to the road on activation (the
    /// looming one), asked for the lateral domain, operated or not: the entity turns to the
    /// road's heading in its lane's driving direction (AlignToRoadHeading:
    /// Position::GetHRoadInDrivingDirection), after ControllerLooming::Activate has set its
    /// vehicle up with the heading it had.
    pub(crate) fn align_to_road_heading(&mut self, e: usize) {
        let Some(net) = self.net else { return };
        let Some(en) = self.entities.get_mut(e) else { return };
        let Some(lp) = en.lane else { return };
        let (Some(road), Some(pose)) = (net.roads.get(lp.road), lp.pose(net)) else { return };
        let against = !opendrive::drives_along_s(road.rule, lp.lane_id);
        let h = pose.road_heading + if against { std::f64::consts::PI } else { 0.0 };
        en.set_world(Some(net), en.x, en.y, Some(en.z), h);
    }

    /// ControllerLooming::GetProbeInfo(distance, LOOKAHEADMODE_AT_LANE_CENTER).relative_h: the
    /// angle, from the entity's heading, to the lane centre `distance` ahead along the road
    /// (and its point). The probe is a copy of the position without its route moved by
    /// Position::MoveAlongS with junction selector angle 0: at a junction whose arms turn
    /// alike (the two arms of a T) MoveToConnectingRoad draws from esmini's global generator,
    /// so every probe across such a junction takes its arm by a draw and moves the sequence on.
    fn looming_probe(&mut self, e: usize, distance: f64, h: f64) -> Option<(f64, f64, f64)> {
        let net = self.net?;
        let en = self.entities.get(e)?;
        let mut lp = en.lane?;
        lp.offset = 0.0;
        if distance.abs() > SMALL_NUMBER {
            move_along_route_drawing(net, &mut lp, distance, None, &mut self.random, false);
        }
        let en = self.entities.get(e)?;
        let p = lp.pose(net)?;
        let (dx, dy) = (p.x - en.x, p.y - en.y);
        // Position::CalcProbeInfo turns by GetH().
        let (sn, cs) = (-h).sin_cos();
        let rx = dx * cs - dy * sn;
        let ry = dx * sn + dy * cs;
        let rel_h = if rx.abs() < SMALL_NUMBER && ry.abs() < SMALL_NUMBER {
            h
        } else {
            let dot = rx / (rx * rx + ry * ry).sqrt();
            (if ry < 0.0 { -1.0 } else { 1.0 }) * dot.clamp(-1.0, 1.0).acos()
        };
        Some((rel_h, p.x, p.y))
    }

    /// ControllerLooming::Step.
    pub(super) fn step_looming(&mut self, e: usize, l: &mut LoomingRt, dt: f64) {
        let Some(me) = self.entities.get(e) else { return };
        let current = me.speed;
        // GetH(): what its last step left, else the heading composed as esmini's position does.
        let h_me = match l.placed_h {
            Some((h, composed)) if h == me.h => composed,
            _ => position_heading(self.net, me),
        };
        let mut far_dist = FAR_POINT;
        let near = self.looming_probe(e, NEAR_POINT, h_me).map_or(0.0, |p| p.0);
        let Some(me) = self.entities.get(e) else { return };
        // The far tangent point on the lane edges.
        let mut far = None;
        let mut intersection = false;
        let mut searched = 0.0;
        if let (Some(net), Some(lp)) = (self.net, me.lane) {
            let h_road = lp.pose(net).map_or(me.h, |p| p.road_heading);
            let forward = lp.dir > 0.0;
            let lp = if l.placed_at == Some((lp.road, lp.s)) { view::at_last_osi_point(net, lp) } else { lp };
            let t = view::far_tangent(net, &mut l.osi, view::Viewpoint { lane: lp, x: me.x, y: me.y, h_road, forward }, far_dist);
            far = t.point;
            intersection = t.intersection;
            searched = t.dist;
        }
        let mut far_angle = far.map_or(0.0, |f| f.2);
        let mut has_lead_far = false;
        let Some(me) = self.entities.get(e) else { return };
        let mut min_gap = LARGE;
        let mut lead: Option<usize> = None;
        for (i, p) in self.entities.iter().enumerate() {
            if i == e || !p.active {
                continue;
            }
            let (Some(net), Some(la), Some(lb)) = (self.net, me.lane, p.lane) else { continue };
            // ControllerLooming::Step: Position::Delta forward only, as the ACC's (reference
            // point to reference point), then the bounding boxes.
            let Some(d) = super::forward_delta::forward_delta(net, &la, me.h, &lb, LOOKAHEAD) else { continue };
            let (ds, same_lane, dt_lat) = (d.ds, d.d_lane == 0, d.dt);
            if ds.abs() > LOOKAHEAD {
                continue;
            }
            let dh = crate::angles::wrap(me.h - p.h).abs();
            let front = me.bbox[3] / 2.0 + me.bbox[0];
            let back = if dh < std::f64::consts::FRAC_PI_2 { p.bbox[3] / 2.0 - p.bbox[0] } else { p.bbox[3] / 2.0 + p.bbox[0] };
            let gap = ds - front - back;
            if same_lane && gap > 0.0 && gap < min_gap && dt_lat.abs() < MIN_LATERAL_DIST {
                min_gap = gap;
                lead = Some(i);
                if min_gap <= far_dist {
                    if intersection && searched < min_gap {
                        far_dist = 0.0;
                        break;
                    }
                    if far.is_some_and(|f| f.3 < min_gap) {
                        break;
                    }
                    has_lead_far = true;
                    far_angle = crate::angles::angle_pi((me.y - p.y).atan2(me.x - p.x) - h_me);
                }
            }
        }
        if far.is_none() && !has_lead_far {
            far_angle = self.looming_probe(e, far_dist, h_me).map_or(0.0, |p| p.0);
        }
        let acc = match lead.and_then(|i| self.entities.get(i)) {
            Some(_) if min_gap < 1.0 => 0.0,
            Some(ld) => {
                let follow = MIN_DIST + l.time_gap * current.max(ld.speed).abs();
                let dist_factor = ((min_gap - follow) / follow).min(1.0);
                let dv_min = current - l.set_speed.min(ld.speed);
                let dv_set = current - l.set_speed;
                dist_factor - dist_factor * dv_set - (1.0 - dist_factor) * dv_min
            }
            None => l.set_speed - current,
        };
        if dt > SMALL_NUMBER {
            let near_dot = (near - l.prev_near) / dt;
            let far_dot = (far_angle - l.prev_far) / dt;
            let steer = (K0 * near + K1 * near_dot + K2 * far_dot) / std::f64::consts::FRAC_PI_4;
            l.steering = steer.clamp(-1.0, 1.0);
        }
        l.prev_near = near;
        l.prev_far = far_angle;
        if let Some(v) = l.vehicle.as_mut() {
            v.drive(dt, acc.clamp(-1.0, 1.0), l.steering);
        }
        let net = self.net;
        let Some(en) = self.entities.get_mut(e) else { return };
        // ControllerLooming::Step places the entity where its vehicle drove whatever an action
        // did this step: a lateral action (the controller leaves that domain to them) only
        // changes the lane the position is locked on, which the near point then steers to.
        if l.override_mode {
            if let Some(v) = l.vehicle.map(|v| v.car) {
                let before = en.lane;
                // Locate it first on the road its lane leads to (esmini keeps the connecting
                // road it is on where junction roads overlap); entering a junction, on the
                // connecting road XYZ2TrackPos prefers (`junction_entry`).
                if let (Some(net), Some(mut lp), Some(b)) = (net, en.lane, before) {
                    move_along_s(net, &mut lp, l.speed() * dt);
                    if lp.road != b.road {
                        if let Some(p) = crate::roads::junction_entry::entry_connector(net, b.road, b.lane_id, v.x, v.y) {
                            lp = crate::roads::LanePos { road: p.road, lane_id: p.lane_id, s: p.s, offset: p.offset, dir: lp.dir };
                        }
                    }
                    en.lane = Some(lp);
                }
                // Position::SetLockOnLane(true), then SetInertiaPos, whose EvaluateHPR composes
                // the heading with the road's (`position_heading`); the vehicle keeps its own.
                // The entity keeps the vehicle's heading (what reads it applies esmini's guard
                // where it matters); the controller's own probes take the composed one.
                en.set_world_lane_locked(net, v.x, v.y, v.h, before);
                l.placed_h = Some((en.h, position_heading(net, en)));
                // ScenarioEngine::step reads the position's end-of-road status before it steps
                // the controllers: what this move finds is seen in the next step.
                l.placed_at = en.lane.map(|lp| (lp.road, lp.s));
                en.at_road_end = l.end_of_road;
                l.end_of_road = match (net, before, en.lane) {
                    (Some(net), Some(_), Some(lp)) => at_dead_end(net, &lp),
                    _ => false,
                };
            }
            en.moved_by_action = true;
        }
        en.speed = l.speed();
    }
}
