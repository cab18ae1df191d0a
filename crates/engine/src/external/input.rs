//! What the caller gives an external entity for one step, and the checks that keep a wrong
//! value out of the run (a non-finite number, a pedal outside [0, 1]).

/// The state an external entity is to have at the end of the step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalState {
    /// Reference point in the road network's frame, m.
    pub x: f64,
    pub y: f64,
    /// Heading, rad.
    pub h: f64,
    /// Signed speed along the heading, m/s.
    pub speed: f64,
    /// Height, m; `None`: on the road surface (or kept without a road network).
    pub z: Option<f64>,
    /// Pitch and roll, rad; `None`: the road's, as for any entity.
    pub pitch: Option<f64>,
    pub roll: Option<f64>,
    /// Yaw rate, rad/s; `None`: derived from the heading change, as for any entity.
    pub yaw_rate: Option<f64>,
}

impl ExternalState {
    /// A state on the road surface, rates derived.
    pub fn new(x: f64, y: f64, h: f64, speed: f64) -> ExternalState {
        ExternalState { x, y, h, speed, z: None, pitch: None, roll: None, yaw_rate: None }
    }
}

/// Pedals and steering for esmini's vehicle model (`driver_vehicle`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriverInput {
    /// Throttle pedal, 0..=1.
    pub throttle: f64,
    /// Brake pedal, 0..=1.
    pub brake: f64,
    /// Steering input, rad, −π/2..=π/2: esmini turns the wheels at 5 · steering rad/s (less
    /// at speed) and lets them return towards straight ahead.
    pub steering: f64,
}

/// One external entity's input for one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Input {
    /// Put the entity in this state.
    State(ExternalState),
    /// Drive esmini's vehicle model with these pedals and steering.
    Driver(DriverInput),
    /// Move on at the speed and heading of the last state given (esmini's UDP driver dead
    /// reckoning); stay like `Hold` when no state was given yet.
    DeadReckon,
    /// Stay where it is, standing (speed 0, as esmini derives it for an entity nobody moves).
    Hold,
}

impl Input {
    /// `Err` naming what is wrong with the values.
    pub fn check(&self) -> Result<(), String> {
        let finite = |name: &str, v: f64| if v.is_finite() { Ok(()) } else { Err(format!("{name} is {v}, not a finite number")) };
        match self {
            Input::State(s) => {
                for (name, v) in [("x", s.x), ("y", s.y), ("h", s.h), ("speed", s.speed)] {
                    finite(name, v)?;
                }
                for (name, v) in [("z", s.z), ("pitch", s.pitch), ("roll", s.roll), ("yaw_rate", s.yaw_rate)] {
                    if let Some(v) = v {
                        finite(name, v)?;
                    }
                }
                Ok(())
            }
            Input::Driver(d) => {
                for (name, v) in [("throttle", d.throttle), ("brake", d.brake)] {
                    finite(name, v)?;
                    if !(0.0..=1.0).contains(&v) {
                        return Err(format!("{name} is {v}, outside 0..=1"));
                    }
                }
                finite("steering", d.steering)?;
                if d.steering.abs() > std::f64::consts::FRAC_PI_2 {
                    return Err(format!("steering is {}, outside -pi/2..=pi/2", d.steering));
                }
                Ok(())
            }
            Input::DeadReckon | Input::Hold => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrong_values_are_named() {
        let mut s = ExternalState::new(1.0, 2.0, 0.0, f64::NAN);
        assert_eq!(Input::State(s).check(), Err("speed is NaN, not a finite number".into()));
        s.speed = 3.0;
        s.roll = Some(f64::INFINITY);
        assert_eq!(Input::State(s).check(), Err("roll is inf, not a finite number".into()));
        s.roll = None;
        assert_eq!(Input::State(s).check(), Ok(()));
        let d = DriverInput { throttle: 1.2, brake: 0.0, steering: 0.0 };
        assert_eq!(Input::Driver(d).check(), Err("throttle is 1.2, outside 0..=1".into()));
        let d = DriverInput { throttle: 0.5, brake: 0.0, steering: 2.0 };
        assert_eq!(Input::Driver(d).check(), Err("steering is 2, outside -pi/2..=pi/2".into()));
    }
}
