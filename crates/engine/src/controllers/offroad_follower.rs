//! OffroadFollower, as esmini's ControllerOffroadFollower: the entity drives straight at another
//! entity (`followEntity`), off the road if need be, on esmini's analog vehicle model
//! (`analog_vehicle`, steering rate `steeringRate`): steering is the angle from its heading to
//! the other's reference point (limited to ±1), throttle 0.5 · (distance − `targetDistance`)
//! − 0.5 · (own speed − the other's) (limited to ±1), its top speed 1.2 × the road's speed
//! limit (esmini's Position::GetSpeedLimit: the road type's, else 120 km/h with more than one
//! driving lane on its side, 60 km/h with one, 70 km/h off any road), at most the vehicle's.
//! It operates on both domains in override mode (the Controller base's defaults) and steps
//! after the default controller has moved the one it follows. Active on the lateral domain
//! only, the default controller moves the entity along its lane first
//! (ScenarioEngine::defaultController: the longitudinal domain is not overridden); the model
//! then measures direction and distance from there but drives on from its own pose, which it
//! writes back (ControllerOffroadFollower::Step ignores its domains).

pub(crate) mod state;

use state::OffroadFollowerRt;

use super::analog_vehicle::AnalogVehicle;
use super::kinematic_vehicle::KinematicVehicle;
use crate::actions::lat_distance::entity_frame::angle_of_vector;
use crate::angles::angle_difference;
use crate::entities::esmini_reported_heading;
use crate::sim::Sim;
use openscenario::Controller;

impl OffroadFollowerRt {
    pub(crate) fn new(c: &Controller) -> OffroadFollowerRt {
        let num = |n: &str, d: f64| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok()).filter(|v| v.is_finite()).unwrap_or(d);
        OffroadFollowerRt {
            active: false,
            lateral: false,
            longitudinal: false,
            follow: c.properties.get("followEntity").map(str::trim).filter(|s| !s.is_empty()).map(str::to_string),
            target_distance: num("targetDistance", 20.0),
            steering_rate: num("steeringRate", 4.0),
            vehicle: None,
        }
    }

    /// Switched on (ControllerOffroadFollower::Activate) on the given domains: the model starts
    /// from the entity's pose and speed.
    pub(crate) fn activate(&mut self, en: &crate::entities::Entity, lateral: bool, longitudinal: bool) {
        self.active = lateral || longitudinal;
        (self.lateral, self.longitudinal) = (lateral, longitudinal);
        let car = KinematicVehicle::new(en.x, en.y, esmini_reported_heading(en.h), en.speed, en.bbox[3], en.max_speed);
        self.vehicle = Some(AnalogVehicle::new(car, en.max_acc, en.max_dec, self.steering_rate));
    }
}

impl OffroadFollowerRt {
    /// Whether it holds the longitudinal domain: then esmini's default controller leaves the
    /// entity alone (`IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)`).
    pub(crate) fn holds_longitudinal(&self) -> bool {
        self.active && self.longitudinal
    }

    /// Whether it holds the lateral domain (lane changes and offsets wait).
    pub(crate) fn holds_lateral(&self) -> bool {
        self.active && self.lateral
    }
}

impl<'a> Sim<'a> {
    /// esmini's Position::GetSpeedLimit where entity `e` is.
    fn speed_limit(&self, e: usize) -> f64 {
        let (Some(net), Some(lp)) = (self.net, self.entities.get(e).and_then(|en| en.lane)) else { return 70.0 / 3.6 };
        let Some(road) = net.roads.get(lp.road) else { return 70.0 / 3.6 };
        if let Some(v) = road.type_at(lp.s).and_then(|t| t.speed.as_ref()).and_then(|s| s.max_mps).filter(|v| *v > 1e-10) {
            return v;
        }
        let Some(sec) = road.section_at(lp.s) else { return 60.0 / 3.6 };
        let side = if lp.lane_id > 0 { &sec.left } else { &sec.right };
        let driving = side.iter().filter(|l| l.kind.is_any_driving()).count();
        if driving > 1 {
            120.0 / 3.6
        } else {
            60.0 / 3.6
        }
    }

    /// One step of OffroadFollower `e` (after the default controller).
    pub(super) fn step_offroad_follower(&mut self, e: usize, f: &mut OffroadFollowerRt, dt: f64) {
        let Some(lead) = f.follow.as_deref().and_then(|n| self.entities.iter().find(|o| o.name == n)) else { return };
        let (Some(me), Some(mut v)) = (self.entities.get(e), f.vehicle) else { return };
        v.car.max_speed = (1.2 * self.speed_limit(e)).min(me.max_speed);
        let (dx, dy) = (lead.x - me.x, lead.y - me.y);
        // GetAngleDifference(GetAngleOfVector(dx, dy), h): a lead exactly behind is +π (the
        // direction's x nudged off zero), which turns left; along a road heading ±π/2 the
        // heading esmini reports decides which side of π the lead lies.
        let direction = angle_difference(angle_of_vector(dx, dy), esmini_reported_heading(me.h));
        let dist = dx.hypot(dy);
        let steering = direction.clamp(-1.0, 1.0);
        let throttle = (0.5 * (dist - f.target_distance) - 0.5 * (me.speed - lead.speed)).clamp(-1.0, 1.0);
        v.drive(dt, throttle, steering);
        if self.place_driven(e, &v.car) {
            // ControllerOffroadFollower::Step sets the roll absolute (0): no banking turns the
            // heading the model drives with (set_world composed it, as a plain SetInertiaPos).
            let net = self.net;
            if let Some(en) = self.entities.get_mut(e) {
                if let (Some(net), Some(lp), Some(mut a)) = (net, en.lane, en.placed_attitude) {
                    let h = crate::angles::wrap_2pi(v.car.h);
                    let h = net.roads.get(lp.road).and_then(|r| crate::attitude::heading_roll_absolute(r, lp.s, h)).map_or(h, crate::angles::wrap_2pi);
                    en.h = h;
                    a.pose.2 = h;
                    a.roll = 0.0;
                    en.placed_attitude = Some(a);
                }
            }
            f.vehicle = Some(v);
        }
    }
}
