//! No datagram can stop the server: any bytes are either a message that passes every check or
//! a rejection (property tests over random bytes and over random values in well-formed
//! headers), and a run fed random datagrams among good ones goes to its end.

use crate::common::*;
use proptest::prelude::*;
use udp::frame_order::FrameOrder;
use udp::{accept, serve, InputMode};

fn check(bytes: &[u8]) {
    let mut order = FrameOrder::default();
    if let Ok((m, _)) = accept(bytes, 0, &mut order) {
        assert_eq!((m.header.version, m.header.object_id), (1, 0));
        assert!(m.mode.accepted_sizes().contains(&bytes.len()));
        assert!(m.body.numbers().iter().all(|(_, v)| v.is_finite()));
        assert_eq!(order.newest(), Some(m.header.frame_number));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn any_bytes_are_a_message_or_a_rejection(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        check(&bytes);
    }

    #[test]
    fn any_values_in_a_well_formed_header_are_a_message_or_a_rejection(
        version in 0u32..3, mode in 0u32..6, object_id in 0u32..3, frame in any::<u32>(),
        body in proptest::collection::vec(any::<u8>(), 72), size in 0usize..4,
    ) {
        let mut bytes: Vec<u8> = [version, mode, object_id, frame].iter().flat_map(|v| v.to_le_bytes()).collect();
        bytes.extend(body);
        let sizes = InputMode::from_code(mode).map(|m| m.accepted_sizes()).unwrap_or_else(|| vec![40, 57, 88]);
        bytes.truncate(sizes.get(size).copied().unwrap_or(33));
        check(&bytes);
    }
}

#[test]
fn a_run_fed_random_datagrams_goes_to_its_end() {
    // a fixed pseudo-random sequence: the same datagrams each run
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let frames: Vec<Vec<Vec<u8>>> = (0..=100u32)
        .map(|k| {
            let noise: Vec<u8> = (0..(next() % 100) as usize).map(|_| next() as u8).collect();
            let good = driver(0, k, 0.3, 0.0, 0.05);
            let mut frame = vec![noise, good];
            if k % 7 == 0 {
                // a good header over random values
                let mut b = driver(0, k, 0.0, 0.0, 0.0);
                for x in &mut b[16..] {
                    *x = next() as u8;
                }
                frame.insert(1, b);
            }
            frame
        })
        .collect();
    let port = free_port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", "asynchronous".into())], 1.0);
    let mut client = Lockstep::new(vec![("Ego", frames)]);
    let outcome = serve(&fixture("one_car.xosc"), &o, &mut client).expect("serves");
    assert_eq!(outcome.steps, 100);
    assert!(outcome.bytes().is_some());
    let ego = outcome.entity("Ego").expect("served");
    assert_eq!(ego.datagrams, ego.accepted + ego.superseded + ego.rejected, "{ego:?}");
    assert!(ego.rejected >= 101, "{ego:?}");
}
