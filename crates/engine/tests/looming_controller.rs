//! esmini's LoomingController on a straight road (fixture `looming_straight.xosc`): Ego, set
//! speed 25 m/s and time gap 1 s, starts at 20 m/s behind a car 180 m ahead at 15 m/s. The
//! expected samples are esmini 3.6.0's (`--fixed_timestep 0.01`): the throttle rule
//! accelerates it to the set speed (5 m/s² at full throttle), then one m/s above it once the
//! car ahead is within 130 m (distance factor 1), and brakes as the gap closes. On a straight
//! road esmini's steering only wobbles (under 3 cm): osc2cr keeps the lane centre.

mod common;
use common::*;
use engine::{Run, Settings};

fn run_fixture() -> Run {
    let loaded = openscenario::load(&fixtures().join("looming_straight.xosc"), &Default::default()).expect("fixture scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("not a scenario") };
    let net = opendrive::load(fixtures().join("straight.xodr")).expect("fixture road loads").network;
    engine::simulate(&scenario, Some(&net), &Settings { step: 0.01, max_time: 20.0 }).expect("simulate")
}

#[test]
fn the_speed_follows_esmini_looming_rule() {
    let r = run_fixture();
    // (time, x, speed) from esmini's trace
    let expected = [
        (0.0, 20.0, 20.0),
        (0.01, 20.2005, 20.05),
        (0.02, 20.4015, 20.1),
        (1.0, 42.4981, 24.6415),
        (5.0, 142.4250, 25.0),
        (6.0, 167.9597, 25.9751),
        (10.0, 271.9493, 25.9753),
        (12.0, 323.5627, 24.6959),
        (13.0, 347.1849, 22.6210),
        (15.0, 388.9906, 19.4071),
    ];
    for (t, x, v) in expected {
        let s = at(&r, "Ego", t);
        assert!(close(s.x, x, 2e-3) && close(s.speed, v, 2e-4), "at {t} s: {s:?}, esmini x {x} speed {v}");
        assert!(close(s.y, -1.75, 0.05), "at {t} s: {s:?}");
    }
    assert!(close(at(&r, "Target", 15.0).x, 200.0 + 15.0 * 15.0, 1e-9));
}

#[test]
fn the_unmodelled_steering_is_a_positioned_warning() {
    let r = run_fixture();
    let w = r.warnings.iter().find(|w| w.message.contains("LoomingController")).expect("a warning on the looming controller");
    assert!(w.message.contains("steering") && w.line > 0 && w.col > 0, "{w:?}");
}
