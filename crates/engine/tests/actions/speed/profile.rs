//! SpeedProfileAction in position mode (speed linear between entries) and follow mode (jerk
//! limited), checked against hand computations.

use crate::common::*;

fn profile(mode: &str, constraints: &str, entries: &[(f64, f64)]) -> String {
    let e: String = entries.iter().map(|(v, t)| format!(r#"<SpeedProfileEntry speed="{v}" time="{t}"/>"#)).collect();
    format!(
        r#"<PrivateAction><LongitudinalAction><SpeedProfileAction followingMode="{mode}">{constraints}{e}</SpeedProfileAction></LongitudinalAction></PrivateAction>"#
    )
}

fn run_profile(action: &str, stop: f64) -> engine::Run {
    let init = format!(r#"{}<Private entityRef="Ego">{action}</Private>"#, teleport("Ego", 10.0, -1));
    run(&xosc(&init, "", &stop_at(stop)))
}

#[test]
fn position_mode_is_linear_between_entries() {
    // From rest: 10 m/s after 2 s (5 m/s²), then 4 m/s 3 s later (−2 m/s²).
    let run = run_profile(&profile("position", "", &[(10.0, 2.0), (4.0, 3.0)]), 7.0);
    assert!(close(at(&run, "Ego", 1.0).speed, 5.0, 1e-9));
    assert!(close(at(&run, "Ego", 2.0).speed, 10.0, 1e-9));
    assert!(close(at(&run, "Ego", 3.5).speed, 7.0, 1e-9));
    assert!(close(at(&run, "Ego", 6.0).speed, 4.0, 1e-9));
    assert!(run.trace.events.iter().any(|e| e.element.contains("SpeedProfileAction") && e.to == "complete"));
}

#[test]
fn follow_mode_single_target_is_a_jerk_limited_s_curve_arriving_on_time() {
    // 0 → 10 m/s in 4 s with jerk ±4 m/s³: the acceleration ramps up for τ, stays at 4τ, and
    // ramps down for τ, where 10 = 4τ (4 − τ), i.e. τ = 2 − √1.5.
    let c = r#"<DynamicConstraints maxAcceleration="5" maxDeceleration="5" maxAccelerationRate="4" maxDecelerationRate="4" maxSpeed="50"/>"#;
    let run = run_profile(&profile("follow", c, &[(0.0, 0.0), (10.0, 4.0)]), 6.0);
    let tau = 2.0 - 1.5f64.sqrt();
    let a = 4.0 * tau;
    let v = |t: f64| {
        if t <= tau {
            2.0 * t * t
        } else if t <= 4.0 - tau {
            2.0 * tau * tau + a * (t - tau)
        } else {
            10.0 - 2.0 * (4.0 - t).powi(2)
        }
    };
    for t in [0.5, 1.0, 2.0, 3.0, 3.5] {
        assert!(close(at(&run, "Ego", t).speed, v(t), 1e-6), "t = {t}: {} vs {}", at(&run, "Ego", t).speed, v(t));
    }
    assert!(close(at(&run, "Ego", 5.0).speed, 10.0, 1e-9));
}
