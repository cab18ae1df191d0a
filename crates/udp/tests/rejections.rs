//! Wrong datagrams — another version, an unknown input mode, another object's id, too short,
//! too long, a length no struct has, a number that is not finite, a pedal or steering angle out
//! of range, a stale frame — are each turned away with a message that says what was wrong and
//! what was expected, and the run goes on to its end as if they had not come: with the same
//! driver input throughout, a run with a wrong datagram in place of a good one every few steps
//! writes the bytes of a run without any.

use crate::common::*;
use udp::{serve, Outcome, Reason, Rejection};

const THROTTLE: f64 = 0.5;

fn run(frames: Vec<Vec<u8>>) -> (Outcome, Vec<Rejection>) {
    let port = free_port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into())], 1.0);
    let mut script = Lockstep::one_each("Ego", frames);
    let outcome = serve(&fixture("one_car.xosc"), &o, &mut script).expect("serves");
    let said = |rs: &[Rejection]| rs.iter().map(ToString::to_string).collect::<Vec<_>>();
    assert_eq!(said(&outcome.rejections), said(&script.rejections), "the outcome keeps what the observer was told");
    (outcome, script.rejections)
}

/// The wrong datagrams, each with what its rejection must say.
fn wrong(k: u32) -> Vec<(Vec<u8>, &'static str)> {
    let good = driver(0, k, THROTTLE, 0.0, 0.0);
    vec![
        (with_header_field(good.clone(), 0, 2), "message version 2; only version 1 is understood"),
        (with_header_field(good.clone(), 1, 7), "unknown inputMode 7; expected 1 driverInput, 2 stateXYZHPR, 3 stateXYH, 4 stateH"),
        (with_header_field(good.clone(), 1, 0), "unknown inputMode 0"),
        (with_header_field(good.clone(), 2, 1), "objectId 1, expected 0: port"),
        (good[..10].to_vec(), "a datagram of 10 bytes is shorter than the 16-byte header"),
        (Vec::new(), "a datagram of 0 bytes is shorter"),
        (padded(good.clone(), 48), "a driverInput message of 48 bytes; expected 40 (packed or C struct), 88 (esmini's DMMessage)"),
        (padded(good.clone(), 200), "a driverInput message of 200 bytes"),
        (xyh(0, k, 60.0, -1.75, 0.0, 5.0, 0)[..50].to_vec(), "a stateXYH message of 50 bytes; expected 57 (packed), 64 (C struct), 88"),
        (driver(0, k, f64::NAN, 0.0, 0.0), "throttle is NaN, not a finite number"),
        (xyh(0, k, f64::INFINITY, -1.75, 0.0, 5.0, 0), "x is inf, not a finite number"),
        (driver(0, 3, THROTTLE, 0.0, 0.0), "frameNumber 3 is older than frame"),
    ]
}

#[test]
fn wrong_datagrams_are_turned_away_by_name_and_change_nothing() {
    let clean: Vec<Vec<u8>> = (0..=100).map(|k| driver(0, k, THROTTLE, 0.0, 0.0)).collect();
    let (clean_outcome, none) = run(clean.clone());
    assert!(none.is_empty());

    // from frame 10 on, every fifth frame is a wrong datagram in place of the good one
    let kinds = wrong(0).len() as u32;
    let mut frames = clean.clone();
    let mut expected = Vec::new();
    for (i, k) in (10..=100).step_by(5).enumerate().take(kinds as usize) {
        let (bad, says) = wrong(k).swap_remove(i);
        frames[k as usize] = bad;
        expected.push((k, says));
    }
    assert_eq!(expected.len(), kinds as usize);
    let (outcome, rejections) = run(frames);

    assert_eq!(rejections.len(), expected.len(), "{rejections:#?}");
    for (r, (k, says)) in rejections.iter().zip(&expected) {
        let text = r.to_string();
        assert!(text.contains(says), "frame {k}: {text:?} does not say {says:?}");
        assert!(text.starts_with(&format!("port {} (`Ego`) at {:.3} s: datagram rejected: ", r.port, *k as f64 * 0.01)), "{text}");
    }
    assert!(matches!(rejections[3].reason, Reason::ObjectId { got: 1, expected: 0 }));
    assert!(rejections[3].to_string().contains("serves `Ego`, esmini object id 0"));

    // the run went on to its end, each step without a message repeating the driver input
    assert_eq!((outcome.steps, outcome.time), (clean_outcome.steps, clean_outcome.time));
    let ego = outcome.entity("Ego").expect("served");
    assert_eq!((ego.rejected, ego.steps_without_message, ego.accepted), (expected.len(), expected.len(), 101 - expected.len()));
    assert!(outcome.bytes().is_some() && outcome.bytes() == clean_outcome.bytes(), "a wrong datagram changed the run");
}

#[test]
fn a_wrong_state_leaves_the_entity_where_the_last_good_one_put_it() {
    let frames = (0..=100u32)
        .map(|k| {
            let z = if k >= 50 { f64::NAN } else { 0.5 };
            xyzhpr(0, k, [60.0 + 0.1 * k as f64, -1.75, z, 0.0, 0.0, 0.0, 10.0, 0.0], 0)
        })
        .collect();
    let (outcome, rejections) = run(frames);
    assert_eq!(rejections.len(), 51);
    assert!(rejections.iter().all(|r| matches!(r.reason, Reason::NotFinite { field: "z", value } if value.is_nan())));
    let s = at(&outcome, "Ego", 1.0);
    assert!(close(s.x, 64.9, 1e-9) && close(s.z, 0.5, 1e-12) && s.speed == 0.0, "{s:?}");
}
