//! SpeedProfileAction entries whose slope exceeds the acceleration limit take the time they
//! need at the limit (esmini's LongSpeedProfileAction::Start), on the straight fixture road.

use crate::common::*;

#[test]
fn an_entry_too_steep_for_the_limit_is_stretched_to_it() {
    // From rest, 10 m/s "in 2 s" (5 m/s²) with maxAcceleration 1: the vertex moves to 10 s at
    // 1 m/s². In follow mode the acceleration ramps up at the jerk limit 2 m/s³ for 0.5 s
    // (v = 0.25 m/s), then stays at 1 m/s²: v(τ) = 0.25 + (τ − 0.5) until the ramp down.
    let c = r#"<DynamicConstraints maxAcceleration="1.0" maxAccelerationRate="2.0" maxDecelerationRate="1.0"/>"#;
    let action = format!(
        r#"<PrivateAction><LongitudinalAction><SpeedProfileAction followingMode="follow">{c}<SpeedProfileEntry speed="10.0" time="2.0"/><SpeedProfileEntry speed="10.0" time="10.0"/></SpeedProfileAction></LongitudinalAction></PrivateAction>"#
    );
    let init = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>{action}</Private>{}"#,
        lane_pos(10.0, -1),
        teleport("Target", 500.0, 1)
    );
    let stop = stop_at(14.0);
    let run = run(&xosc(&init, "", &stop));
    assert!(close(at(&run, "Ego", 0.5).speed, 0.25, 1e-9), "{}", at(&run, "Ego", 0.5).speed);
    assert!(close(at(&run, "Ego", 1.0).speed, 0.75, 1e-9));
    assert!(close(at(&run, "Ego", 5.0).speed, 4.75, 1e-9));
    assert!(close(at(&run, "Ego", 13.0).speed, 10.0, 1e-9));
    // esmini 3.6.0 on this scenario (run by hand): x = 21.315425 at 5 s, 9.71875 m/s and
    // x = 57.587662 at 10 s (ramping down), x = 87.51875 at 13 s.
    assert!(close(at(&run, "Ego", 5.0).x, 21.315425, 1e-5));
    assert!(close(at(&run, "Ego", 10.0).speed, 9.71875, 1e-9) && close(at(&run, "Ego", 10.0).x, 57.587662, 1e-5));
    assert!(close(at(&run, "Ego", 13.0).x, 87.51875, 1e-5));
}

#[test]
fn a_profile_starts_from_the_acceleration_along_the_heading() {
    // A sinusoidal LaneOffsetAction turns the car at a constant 10 m/s when a follow-mode
    // SpeedProfileAction starts at 0.5 s: esmini's LongSpeedProfileAction::Start reads its initial
    // acceleration from Position::GetAccLong (the world acceleration's part along the heading,
    // here negative), not from the speed's rate (zero). esmini 3.6.0's speeds (run by hand).
    let run = run_straight_fixture("speed_profile_initial_acc_of_turning.xosc", 6.0);
    for (t, v, x) in [
        (0.51, 6.295706, 15.062957),
        (0.52, 6.251950, 15.125477),
        (1.0, 5.033667, 17.758843),
        (2.0, 7.537035, 23.623598),
        (4.0, 15.537035, 46.737668),
        (6.0, 19.986604, 83.603977),
    ] {
        let s = at(&run, "Ego", t);
        assert!(close(s.speed, v, 1e-5) && close(s.x, x, 1e-5), "t {t}: {} {} (esmini {v} {x})", s.speed, s.x);
    }
}
