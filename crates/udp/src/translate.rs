//! From messages to the engine's inputs, step by step, as `ControllerUDPDriver::Step` moves its
//! object (esmini 3.6.0):
//!
//! - a message received in the step: driver input drives esmini's vehicle model (the engine's
//!   `Input::Driver`); an XYZHPR state puts the entity where it says, height, pitch and roll
//!   included; an XYH state puts it on the road surface at x, y; an H state turns it where it
//!   is — and, with its dead-reckoning flag, moves it on at once by speed · dt along the new
//!   heading (esmini dead-reckons an H state also in the step it arrives);
//! - no message: the last driver input drives again; after an XYH or XYZHPR state with dead
//!   reckoning, and after an H state with it, the entity moves on at that state's speed and
//!   heading (`Input::DeadReckon`); otherwise it stays where it is, and since nothing gave it a
//!   speed esmini derives one from its displacement: 0. Before any message it stays too.
//!
//! Two esmini details are kept. Its test for dead reckoning after an XYZHPR state reads the
//! flag at the XYH state's offset in the union (`lastMsg.message.stateXYH.deadReckon`), which in
//! an XYZHPR message is the lowest byte of the roll `r` in memory: such a state dead-reckons
//! when that byte is not 0, whatever its own flag says. And a message read in the Init frame
//! (time step 0) moves nothing then: driver input is kept for the next step, a state is
//! applied in the next step if no newer message comes (esmini shows it at time 0 already;
//! osc2cr's row at time 0 is recorded before any datagram can be read).

use engine::{DriverInput, ExternalState, Input, Sample};

use crate::message::Body;

/// What the messages so far leave for the next steps of one entity.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Driving {
    /// The last message accepted (esmini's `lastMsg`).
    last: Option<Body>,
    /// It is a state read in a frame without a time step and not yet applied.
    unapplied: bool,
}

/// Whether esmini dead-reckons after state `b` when no message comes.
pub fn dead_reckons(b: &Body) -> bool {
    match *b {
        Body::StateH { dead_reckon, .. } | Body::StateXyh { dead_reckon, .. } => dead_reckon != 0,
        // esmini reads the XYH struct's flag, at byte 40 of the union: the lowest byte of `r`
        Body::StateXyzhpr { r, .. } => r.to_bits() & 0xFF != 0,
        Body::DriverInput { .. } => false,
    }
}

/// The state a message puts the entity in, from where it is (`now`), moved on by dead
/// reckoning over `dr_time` seconds; `speed` replaces the message's speed when given.
fn state(b: &Body, now: &Sample, dr_time: f64, speed: Option<f64>) -> Option<ExternalState> {
    let on = |x: f64, y: f64, h: f64, v: f64| (x + v * dr_time * h.cos(), y + v * dr_time * h.sin());
    let s = match *b {
        Body::StateXyzhpr { x, y, z, h, p, r, speed: v, .. } => {
            let (x, y) = on(x, y, h, v);
            ExternalState { z: Some(z), pitch: Some(p), roll: Some(r), ..ExternalState::new(x, y, h, v) }
        }
        Body::StateXyh { x, y, h, speed: v, .. } => {
            let (x, y) = on(x, y, h, v);
            ExternalState::new(x, y, h, v)
        }
        Body::StateH { h, speed: v, .. } => {
            let (x, y) = on(now.x, now.y, h, v);
            ExternalState::new(x, y, h, v)
        }
        Body::DriverInput { .. } => return None,
    };
    Some(ExternalState { speed: speed.unwrap_or(s.speed), ..s })
}

fn driver(b: &Body) -> Option<Input> {
    match *b {
        Body::DriverInput { throttle, brake, steering_angle } => Some(Input::Driver(DriverInput { throttle, brake, steering: steering_angle })),
        _ => None,
    }
}

impl Driving {
    pub fn new() -> Driving {
        Driving::default()
    }

    /// The last message accepted.
    pub fn last(&self) -> Option<&Body> {
        self.last.as_ref()
    }

    /// A message read in a frame without a time step (the Init frame): kept, applied later.
    pub fn read_without_step(&mut self, b: Body) {
        self.unapplied = !matches!(b, Body::DriverInput { .. });
        self.last = Some(b);
    }

    /// The input of a step of `dt` seconds that received `received` (or nothing), the entity
    /// being at `now` when the step begins (`None`: it is not in the run now).
    pub fn input(&mut self, received: Option<Body>, now: Option<&Sample>, dt: f64) -> Input {
        let Some(now) = now else {
            if let Some(b) = received {
                self.last = Some(b);
                self.unapplied = !matches!(b, Body::DriverInput { .. });
            }
            return Input::Hold;
        };
        if let Some(b) = received {
            self.last = Some(b);
            self.unapplied = false;
            if let Some(d) = driver(&b) {
                return d;
            }
            // only an H state dead-reckons in the step it arrives
            let dr = if matches!(b, Body::StateH { .. }) && dead_reckons(&b) { dt } else { 0.0 };
            return state(&b, now, dr, None).map_or(Input::Hold, Input::State);
        }
        let Some(last) = self.last else { return Input::State(held(now, None)) };
        if let Some(d) = driver(&last) {
            return d;
        }
        if std::mem::take(&mut self.unapplied) {
            // read with the Init frame: where esmini put it then, and this step's dead reckoning
            let (dr, speed) = if dead_reckons(&last) { (dt, None) } else { (0.0, Some(0.0)) };
            return state(&last, now, dr, speed).map_or(Input::Hold, Input::State);
        }
        if dead_reckons(&last) {
            Input::DeadReckon
        } else {
            Input::State(held(now, Some(&last)))
        }
    }
}

/// Where the entity is, with speed 0 (esmini derives the speed of an entity nothing gave one
/// from its displacement); after an XYZHPR state its height, pitch and roll stay as given.
pub fn held(now: &Sample, last: Option<&Body>) -> ExternalState {
    let s = ExternalState::new(now.x, now.y, now.h, 0.0);
    match last {
        Some(Body::StateXyzhpr { p, r, .. }) => ExternalState { z: Some(now.z), pitch: Some(*p), roll: Some(*r), ..s },
        _ => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f64, y: f64, h: f64, speed: f64) -> Sample {
        Sample { x, y, z: 0.0, h, speed, acceleration: 0.0, yaw_rate: 0.0, road: None, visible: true }
    }

    fn xyh(x: f64, speed: f64, dead_reckon: u8) -> Body {
        Body::StateXyh { x, y: -1.75, h: 0.0, speed, wheel_angle: 0.0, dead_reckon }
    }

    #[test]
    fn states_dead_reckon_only_without_a_message_but_h_also_with_one() {
        let now = at(10.0, -1.75, 0.0, 5.0);
        let mut d = Driving::new();
        assert_eq!(d.input(Some(xyh(20.0, 4.0, 1)), Some(&now), 0.1), Input::State(ExternalState::new(20.0, -1.75, 0.0, 4.0)));
        assert_eq!(d.input(None, Some(&now), 0.1), Input::DeadReckon);
        let h = Body::StateH { h: 0.0, speed: 4.0, wheel_angle: 0.0, dead_reckon: 1 };
        let Input::State(s) = d.input(Some(h), Some(&now), 0.1) else { panic!("a state") };
        assert!((s.x - 10.4).abs() < 1e-12 && s.y == -1.75 && s.speed == 4.0, "{s:?}");
        assert_eq!(d.input(None, Some(&now), 0.1), Input::DeadReckon);
        // no flag: it stays, with the speed esmini derives from not moving
        d.input(Some(xyh(20.0, 4.0, 0)), Some(&now), 0.1);
        assert_eq!(d.input(None, Some(&now), 0.1), Input::State(ExternalState::new(10.0, -1.75, 0.0, 0.0)));
    }

    #[test]
    fn xyzhpr_dead_reckons_by_the_lowest_byte_of_roll_as_esmini_reads_it() {
        let m = |r: f64, dead_reckon: u8| Body::StateXyzhpr { x: 0.0, y: 0.0, z: 0.0, h: 0.0, p: 0.0, r, speed: 1.0, wheel_angle: 0.0, dead_reckon };
        assert!(!dead_reckons(&m(0.0, 1)));
        assert!(dead_reckons(&m(0.001, 0)));
        // 0.5 is 0x3FE0000000000000: its lowest byte is 0
        assert!(!dead_reckons(&m(0.5, 1)));
    }

    #[test]
    fn driver_input_repeats_and_a_state_read_at_init_is_applied_next() {
        let now = at(10.0, -1.75, 0.0, 5.0);
        let mut d = Driving::new();
        assert_eq!(d.input(None, Some(&now), 0.1), Input::State(ExternalState::new(10.0, -1.75, 0.0, 0.0)));
        let di = Body::DriverInput { throttle: 0.5, brake: 0.0, steering_angle: 0.1 };
        let expected = Input::Driver(DriverInput { throttle: 0.5, brake: 0.0, steering: 0.1 });
        assert_eq!(d.input(Some(di), Some(&now), 0.1), expected);
        assert_eq!(d.input(None, Some(&now), 0.1), expected);
        let mut d = Driving::new();
        d.read_without_step(xyh(30.0, 2.0, 1));
        let Input::State(s) = d.input(None, Some(&now), 0.1) else { panic!("a state") };
        assert!((s.x - 30.2).abs() < 1e-12 && s.speed == 2.0, "{s:?}");
        assert_eq!(d.input(None, Some(&now), 0.1), Input::DeadReckon);
        let mut d = Driving::new();
        d.read_without_step(xyh(30.0, 2.0, 0));
        assert_eq!(d.input(None, Some(&now), 0.1), Input::State(ExternalState::new(30.0, -1.75, 0.0, 0.0)));
    }
}
