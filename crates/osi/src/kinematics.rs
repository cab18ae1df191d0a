//! What esmini reports of an object's motion, derived from its states as
//! `ScenarioEngine::prepareGroundTruth` derives it: the velocity is the reference point's
//! displacement over the step, in the world frame (at the first frame, where there is no step,
//! the speed along the heading); the acceleration the change of that velocity over the step; the
//! yaw rate the heading's change (the short way) over the step and the yaw acceleration the
//! change of the rate. A jump no speed explains (esmini's teleport, for which it takes the speed
//! along the heading) is told by its length: farther than the speed covers in the step plus
//! half a metre. The pitch is the road's (its elevation slope along the heading; nose down
//! positive, as esmini's): the engine keeps none of its own. Roll is 0 (superelevation is not
//! applied to positions).

use engine::Sample;
use opendrive::RoadNetwork;

/// One object's motion in one frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Motion {
    /// Reference point.
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Heading in −π..π, pitch.
    pub yaw: f64,
    pub pitch: f64,
    pub velocity: (f64, f64, f64),
    pub acceleration: (f64, f64, f64),
    pub yaw_rate: f64,
    pub yaw_acceleration: f64,
}

/// esmini's GetAngleInIntervalMinusPIPlusPI.
pub fn angle_pi(a: f64) -> f64 {
    let tau = 2.0 * std::f64::consts::PI;
    let mut b = a % tau;
    if b < -std::f64::consts::PI {
        b += tau;
    } else if b > std::f64::consts::PI {
        b -= tau;
    }
    b
}

impl Motion {
    /// Vector (x, y, z) of the object's frame in the world frame (esmini's `RotateVec3d` with
    /// heading and pitch).
    pub fn rotate(&self, x: f64, y: f64, z: f64) -> (f64, f64, f64) {
        let (sh, ch) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        (ch * cp * x - sh * y + ch * sp * z, sh * cp * x + ch * y + sh * sp * z, -sp * x + cp * z)
    }
}

/// The road's pitch under an object heading `h` at `sample`'s road position (0 off the road).
pub fn road_pitch(net: Option<&RoadNetwork>, sample: &Sample) -> f64 {
    let (Some(net), Some(rp)) = (net, sample.road) else { return 0.0 };
    let Some(road) = net.roads.get(rp.road as usize) else { return 0.0 };
    let slope = road.elevation_slope_at(rp.s) * (sample.h - road.reference_pose(rp.s).hdg).cos();
    let p = -slope.atan();
    if p == 0.0 {
        0.0
    } else {
        p
    }
}

/// The motion of one object from frame to frame.
#[derive(Debug, Clone, Default)]
pub struct Tracker {
    last: Option<Motion>,
}

impl Tracker {
    /// The motion at `sample` (pitch `pitch`), `dt` seconds after the previous frame (0: the
    /// first frame, or none before).
    pub fn next(&mut self, sample: &Sample, pitch: f64, dt: f64) -> Motion {
        let yaw = angle_pi(sample.h);
        let mut m = Motion { x: sample.x, y: sample.y, z: sample.z, yaw, pitch, ..Motion::default() };
        match self.last {
            Some(last) if dt > 1e-9 && (m.x - last.x).hypot(m.y - last.y) <= sample.speed.abs() * dt + 0.5 => {
                m.velocity = ((m.x - last.x) / dt, (m.y - last.y) / dt, (m.z - last.z) / dt);
                m.acceleration = ((m.velocity.0 - last.velocity.0) / dt, (m.velocity.1 - last.velocity.1) / dt, (m.velocity.2 - last.velocity.2) / dt);
                m.yaw_rate = angle_pi(yaw - last.yaw) / dt;
                m.yaw_acceleration = angle_pi(m.yaw_rate - last.yaw_rate) / dt;
            }
            last => {
                m.velocity = (sample.speed * sample.h.cos(), sample.speed * sample.h.sin(), 0.0);
                if let (Some(l), true) = (last, dt > 1e-9) {
                    // a teleport: esmini's velocity along the heading, its change the acceleration
                    m.acceleration = ((m.velocity.0 - l.velocity.0) / dt, (m.velocity.1 - l.velocity.1) / dt, (m.velocity.2 - l.velocity.2) / dt);
                    m.yaw_rate = angle_pi(yaw - l.yaw) / dt;
                    m.yaw_acceleration = angle_pi(m.yaw_rate - l.yaw_rate) / dt;
                } else if let Some(l) = last {
                    // a frame without a step keeps what the last one derived
                    (m.acceleration, m.yaw_rate, m.yaw_acceleration) = (l.acceleration, l.yaw_rate, l.yaw_acceleration);
                }
            }
        }
        self.last = Some(m);
        m
    }

    /// The object left the run: the next frame it is in starts afresh.
    pub fn reset(&mut self) {
        self.last = None;
    }
}
