//! The same datagrams in synchronous mode give the same bytes: two runs of `one_car.xosc` driven
//! by the same mix of driver input and states write identical CommonRoad files, and a run with
//! one datagram changed does not.

use crate::common::*;
use udp::serve;

fn bytes(frames: Vec<Vec<u8>>) -> Vec<u8> {
    let port = free_port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into())], 1.0);
    let mut script = Lockstep::one_each("Ego", frames);
    let outcome = serve(&fixture("one_car.xosc"), &o, &mut script).expect("serves");
    outcome.bytes().expect("converted").to_vec()
}

fn frames(change_at: Option<u32>) -> Vec<Vec<u8>> {
    (0..=100u32)
        .map(|k| {
            let t = k as f64 * 0.01;
            let steering = if Some(k) == change_at { 0.4 } else { 0.1 * (3.0 * t).sin() };
            match k {
                40..=49 => xyh(0, k, 55.0 + 5.0 * t, -1.75 - t, -0.2, 6.0, 1),
                60..=64 => state_h(0, k, 0.05, 7.0, 1),
                _ => driver(0, k, (0.8 * t).sin().abs(), if k > 80 { 0.3 } else { 0.0 }, steering),
            }
        })
        .collect()
}

#[test]
fn the_same_datagrams_give_the_same_bytes() {
    let a = bytes(frames(None));
    let b = bytes(frames(None));
    assert!(a == b, "two runs with the same datagrams differ");
    let c = bytes(frames(Some(30)));
    assert!(a != c, "a changed datagram changed nothing: the comparison cannot fail");
}
