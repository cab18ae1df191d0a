//! A negative throttle, as esmini's `testUDPDriver-follow-trajectory.py` sends it, drives as
//! esmini's vehicle takes it — the pedal `throttle − brake` — and is counted: the example's ego
//! fed `throttle −0.3, brake 0` ends exactly where `throttle 0, brake 0.3` puts it, with every
//! such message counted as clamped and none rejected; a throttle of 1.5 drives as full throttle;
//! a throttle that is not finite is still turned away.

use std::net::UdpSocket;

/// esmini's driverInput message (version 1, mode 1), packed little-endian.
fn driver(frame: u32, throttle: f64, brake: f64, steering: f64) -> Vec<u8> {
    let mut b: Vec<u8> = [1u32, 1, 0, frame].iter().flat_map(|v| v.to_le_bytes()).collect();
    for v in [throttle, brake, steering] {
        b.extend(v.to_le_bytes());
    }
    b
}

/// The example served with `messages` queued on its synchronous port before the run (one is
/// read per step), to 1 s.
fn serve(port: u16, messages: Vec<Vec<u8>>) -> udp::Outcome {
    let example = testkit::workspace_root().join("examples/udp_driver.xosc");
    let options = udp::ServeOptions { convert: convert::ConvertOptions { max_time: 1.0, ..Default::default() }, base_port: Some(port), ..Default::default() };
    /// Queues the messages when the port opens.
    struct Send(Vec<Vec<u8>>);
    impl udp::Observer for Send {
        fn listening(&mut self, l: &udp::Listening) {
            let s = UdpSocket::bind("127.0.0.1:0").expect("socket");
            for m in std::mem::take(&mut self.0) {
                s.send_to(&m, l.address).expect("sent");
            }
        }
    }
    udp::serve(&example, &options, &mut Send(messages)).expect("served")
}

fn end(o: &udp::Outcome) -> (f64, f64, f64) {
    let s = o.entity("Ego").and_then(|e| e.states.last()).map(|(_, s)| *s).expect("the ego's states");
    (s.x, s.y, s.speed)
}

#[test]
fn a_negative_throttle_brakes_as_in_esmini_and_is_counted() {
    let _ports = crate::UDP_PORTS.lock();
    let port = UdpSocket::bind("127.0.0.1:0").and_then(|s| s.local_addr()).expect("port").port();
    // speed up for 50 steps, then brake by a negative throttle, or by the brake
    let run = |negative: bool| {
        let msgs = (0..=100u32)
            .map(|k| match (k < 50, negative) {
                (true, _) => driver(k, 1.0, 0.0, 0.0),
                (false, true) => driver(k, -0.3, 0.0, 0.0),
                (false, false) => driver(k, 0.0, 0.3, 0.0),
            })
            .collect();
        serve(port, msgs)
    };
    let (by_throttle, by_brake) = (run(true), run(false));
    let (a, b) = (by_throttle.entity("Ego").expect("served"), by_brake.entity("Ego").expect("served"));
    assert_eq!((a.rejected, b.rejected), (0, 0), "nothing turned away");
    assert_eq!((a.clamped, b.clamped), (51, 0), "each negative throttle counted");
    assert_eq!(end(&by_throttle), end(&by_brake), "a negative throttle brakes as the brake does");
    assert!(end(&by_brake).2 < end(&run_full(port)).2, "it brakes");

    // beyond full throttle: full throttle; not a number: rejected
    let over = serve(port, (0..=100u32).map(|k| driver(k, 1.5, 0.0, 0.0)).collect());
    assert_eq!(end(&over), end(&run_full(port)), "throttle 1.5 drives as 1");
    let nan = serve(port, (0..=101u32).map(|k| driver(k, if k == 0 { f64::NAN } else { 1.0 }, 0.0, 0.0)).collect());
    assert_eq!(nan.entity("Ego").map(|e| e.rejected), Some(1), "NaN is rejected");
}

fn run_full(port: u16) -> udp::Outcome {
    serve(port, (0..=100u32).map(|k| driver(k, 1.0, 0.0, 0.0)).collect())
}
