//! A client written from esmini's protocol description drives `Ego` of `one_car.xosc` on
//! 127.0.0.1 in every input mode. Synchronous mode goes in lockstep, so where Ego is at each
//! step follows from the messages exactly (the Init frame reads the first datagram, as
//! esmini's does; step k reads frame k). In asynchronous mode the newest datagram of a step
//! drives it; the checks there hold whichever step a datagram lands in.

use crate::common::*;
use udp::{serve, Outcome, Pace};

const EGO: u32 = 0;

fn run(exec: &str, duration: f64, script: &mut Lockstep) -> Outcome {
    let port = free_port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", exec.into())], duration);
    let outcome = serve(&fixture("one_car.xosc"), &o, script).expect("serves");
    assert_eq!(script.listening.len(), 1, "one port opened");
    assert_eq!(script.listening[0].address.port(), port);
    assert!(outcome.bytes().is_some(), "converted: {:?}", outcome.failure);
    assert!(script.rejections.is_empty(), "{:?}", script.rejections);
    outcome
}

#[test]
fn driver_input_drives_esminis_vehicle_model_step_by_step() {
    // frame 0 (read with the Init frame) brakes; every later one is full throttle
    let frames = (0..=100).map(|k| if k == 0 { driver(EGO, 0, 0.0, 1.0, 0.0) } else { driver(EGO, k, 1.0, 0.0, 0.0) }).collect();
    let outcome = run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames));
    // step k was driven by frame k: 20 m/s² from 10 m/s, at most 30 m/s (esmini's UDP driver)
    let speed = |k: usize| (10.0 + 0.2 * k as f64).min(30.0);
    for k in [1usize, 50, 100] {
        let s = at(&outcome, "Ego", k as f64 * 0.01);
        let x = 50.0 + (1..=k).map(|j| 0.01 * speed(j)).sum::<f64>();
        assert!(close(s.speed, speed(k), 1e-9) && close(s.x, x, 1e-9) && close(s.y, -1.75, 1e-12), "step {k}: {s:?}, expected x {x}");
    }
    let ego = outcome.entity("Ego").expect("served");
    assert_eq!((ego.accepted, ego.rejected, ego.steps_without_message), (ego.datagrams, 0, 0));
    // the others go on as the scenario says
    assert!(outcome.entity("Target").is_none());

    // steering left turns it left
    let frames = (0..=100).map(|k| driver(EGO, k, 0.0, 0.0, 0.3)).collect();
    let s = at(&run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames)), "Ego", 1.0);
    assert!(s.y > -1.75 + 0.1 && s.h > 0.01 && s.h < 1.0, "{s:?}");
}

#[test]
fn an_xyzhpr_state_puts_it_where_it_says_height_included() {
    let frames = (0..=100).map(|k| xyzhpr(EGO, k, [60.0 + 0.5 * k as f64, -1.75 + 0.01 * k as f64, 1.0, 0.1, 0.05, 0.0, 50.0, 0.0], 0)).collect();
    let outcome = run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames));
    for k in [1usize, 50, 100] {
        let s = at(&outcome, "Ego", k as f64 * 0.01);
        assert!(close(s.x, 60.0 + 0.5 * k as f64, 1e-9) && close(s.y, -1.75 + 0.01 * k as f64, 1e-9), "step {k}: {s:?}");
        assert!(close(s.z, 1.0, 1e-12) && close(s.h, 0.1, 1e-12) && s.speed == 50.0, "step {k}: {s:?}");
    }
    // osc2cr records the Init frame before any datagram is read (esmini shows frame 0's state there)
    assert!(close(at(&outcome, "Ego", 0.0).x, 50.0, 1e-12));
}

#[test]
fn an_xyh_state_puts_it_on_the_road_and_every_size_is_read() {
    // packed (57 bytes), esmini's C struct (64) and whole DMMessage (88) in turn
    let frames = (0..=100u32)
        .map(|k| {
            let m = xyh(EGO, k, 60.0 + 0.2 * k as f64, -1.75, 0.0, 20.0, 0);
            match k % 3 {
                0 => m,
                1 => padded(m, 64),
                _ => padded(m, 88),
            }
        })
        .collect();
    let outcome = run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames));
    for k in [1usize, 2, 3, 100] {
        let s = at(&outcome, "Ego", k as f64 * 0.01);
        assert!(close(s.x, 60.0 + 0.2 * k as f64, 1e-9) && close(s.y, -1.75, 1e-12) && s.z == 0.0 && s.speed == 20.0, "step {k}: {s:?}");
        assert_eq!(s.road.map(|r| r.lane_id), Some(-1));
    }
}

#[test]
fn an_h_state_turns_it_where_it_is_and_dead_reckons_at_once_when_asked() {
    let (h, v) = (0.2f64, 10.0);
    let frames = (0..=100).map(|k| state_h(EGO, k, h, v, 1)).collect();
    let outcome = run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames));
    for k in [1usize, 50, 100] {
        let s = at(&outcome, "Ego", k as f64 * 0.01);
        let (x, y) = (50.0 + k as f64 * 0.01 * v * h.cos(), -1.75 + k as f64 * 0.01 * v * h.sin());
        assert!(close(s.x, x, 1e-9) && close(s.y, y, 1e-9) && close(s.h, h, 1e-12) && s.speed == v, "step {k}: {s:?}, expected ({x}, {y})");
    }
    // without the flag it turns on the spot
    let frames = (0..=100).map(|k| state_h(EGO, k, h, v, 0)).collect();
    let s = at(&run("synchronous", 1.0, &mut Lockstep::one_each("Ego", frames)), "Ego", 1.0);
    assert!(close(s.x, 50.0, 1e-9) && close(s.y, -1.75, 1e-9) && close(s.h, h, 1e-12) && s.speed == v, "{s:?}");
}

#[test]
fn asynchronous_ports_take_the_newest_datagram_of_each_step() {
    // two datagrams a step, the second newer: only it counts
    let frames = (0..60).map(|k| vec![xyh(EGO, 2 * k, 500.0, -1.75, 0.0, 0.0, 0), xyh(EGO, 2 * k + 1, 90.0, -5.25, 0.1, 0.0, 0)]).collect();
    let mut script = Lockstep::new(vec![("Ego", frames)]);
    let outcome = run("asynchronous", 0.5, &mut script);
    let last = outcome.entity("Ego").and_then(|e| e.states.last()).map(|(_, s)| *s).expect("states");
    assert!(close(last.x, 90.0, 1e-9) && close(last.y, -5.25, 1e-9) && close(last.h, 0.1, 1e-12), "{last:?}");
    assert_eq!(last.road.map(|r| r.lane_id), Some(-2));
    let ego = outcome.entity("Ego").expect("served");
    assert!(ego.superseded > 0 && ego.datagrams == ego.accepted + ego.superseded, "{ego:?}");
    assert!(outcome.pace.contains("as fast as possible"));
}

#[test]
fn asynchronous_ports_serve_every_input_mode_in_real_time() {
    let last = |o: &Outcome| o.entity("Ego").and_then(|e| e.states.last()).map(|(_, s)| *s).expect("states");
    let async_run = |frame: Vec<u8>, pace: Pace| {
        let port = free_port();
        let mut o = options(&[("Port", port.to_string()), ("ExecMode", "asynchronous".into())], 0.3);
        o.pace = Some(pace);
        let mut script = Lockstep::new(vec![("Ego", vec![vec![frame]; 40])]);
        let outcome = serve(&fixture("one_car.xosc"), &o, &mut script).expect("serves");
        assert!(script.rejections.is_empty(), "{:?}", script.rejections);
        outcome
    };
    // driver input: full brake stops it (20 m/s² from 10 m/s: within 0.5 s)
    let o = async_run(driver(EGO, 0, 0.0, 1.0, 0.0), Pace::RealTime(4.0));
    assert!(o.pace.contains("real time"));
    let s = last(&o);
    assert!(s.speed < 10.0 - 3.0 && s.x < 50.0 + 0.3 * 10.0, "{s:?}");
    // states that do not dead-reckon leave it where the last one put it
    let s = last(&async_run(xyzhpr(EGO, 0, [80.0, -1.75, 0.5, 0.0, 0.0, 0.0, 3.0, 0.0], 0), Pace::AsFastAsPossible));
    assert!(close(s.x, 80.0, 1e-9) && close(s.z, 0.5, 1e-12), "{s:?}");
    let s = last(&async_run(xyh(EGO, 0, 90.0, -1.75, 0.0, 3.0, 0), Pace::AsFastAsPossible));
    assert!(close(s.x, 90.0, 1e-9) && s.z == 0.0, "{s:?}");
    // an H state turns it where it was held (nothing moves it before its first message)
    let s = last(&async_run(state_h(EGO, 0, 0.3, 0.0, 0), Pace::AsFastAsPossible));
    assert!(close(s.x, 50.0, 1e-9) && close(s.y, -1.75, 1e-9) && close(s.h, 0.3, 1e-12), "{s:?}");
}
