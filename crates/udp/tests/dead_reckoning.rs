//! When no message comes — a stale frame turned away, or none within the synchronous wait —
//! Ego goes on as esmini's controller step has it: after a state with dead reckoning at that
//! state's speed and heading, after one without it stays where it is with speed 0.

use crate::common::*;
use std::time::Duration;
use udp::{serve, Outcome, Reason};

fn run(frames: Vec<Vec<u8>>, duration: f64, timeout: Option<Duration>) -> (Outcome, Lockstep) {
    let port = free_port();
    let mut o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into())], duration);
    if let Some(t) = timeout {
        o.synchronous_timeout = t;
    }
    let mut script = Lockstep::one_each("Ego", frames);
    let outcome = serve(&fixture("one_car.xosc"), &o, &mut script).expect("serves");
    (outcome, script)
}

/// XYH states at 10 m/s along lane -1 (x = 60 + 0.1 k at frame k) up to frame 20, then frame 0
/// again at every step: stale, so no message.
fn states_then_stale(dead_reckon: u8) -> Vec<Vec<u8>> {
    (0..=100u32).map(|k| if k <= 20 { xyh(0, k, 60.0 + 0.1 * k as f64, -1.75, 0.0, 10.0, dead_reckon) } else { xyh(0, 0, 0.0, 0.0, 0.0, 0.0, 0) }).collect()
}

#[test]
fn after_a_state_with_dead_reckoning_it_moves_on_at_its_speed() {
    let (outcome, script) = run(states_then_stale(1), 1.0, None);
    for k in [20usize, 21, 60, 100] {
        let s = at(&outcome, "Ego", k as f64 * 0.01);
        assert!(close(s.x, 60.0 + 0.1 * k as f64, 1e-9) && close(s.y, -1.75, 1e-12) && close(s.speed, 10.0, 1e-9), "step {k}: {s:?}");
    }
    assert_eq!(script.rejections.len(), 80);
    assert!(script.rejections.iter().all(|r| matches!(r.reason, Reason::OutOfOrder { frame: 0, newest: 20 })));
    assert_eq!(outcome.entity("Ego").map(|e| e.steps_without_message), Some(80));
}

#[test]
fn after_a_state_without_it_stays_and_its_speed_is_zero() {
    let (outcome, _) = run(states_then_stale(0), 1.0, None);
    assert!(close(at(&outcome, "Ego", 0.2).speed, 10.0, 1e-12));
    let s = at(&outcome, "Ego", 1.0);
    assert!(close(s.x, 62.0, 1e-9) && s.speed == 0.0, "{s:?}");
}

#[test]
fn a_synchronous_port_waits_for_its_datagram_then_goes_on_without() {
    // ten frames, then nothing: each of the last ten steps waits (20 ms here) and dead-reckons
    let frames = (0..=10u32).map(|k| xyh(0, k, 60.0 + 0.1 * k as f64, -1.75, 0.0, 10.0, 1)).collect();
    let (outcome, _) = run(frames, 0.2, Some(Duration::from_millis(20)));
    assert!(close(at(&outcome, "Ego", 0.2).x, 62.0, 1e-9));
    let ego = outcome.entity("Ego").expect("served");
    assert_eq!((ego.accepted, ego.steps_without_message, outcome.steps), (11, 10, 20));
}
