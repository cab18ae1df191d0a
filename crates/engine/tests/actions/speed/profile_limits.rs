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
