//! ALKS_R157SM_Controller (Regulation model) on the straight fixture road, against hand
//! computations (see `common`: cars 4.5 m long, box centre 1.5 m ahead of the reference point).

use crate::common::*;

/// Ego at s = 10 driving 20 m/s with the controller activated at init; Target at `target_s`
/// (same lane) at `target_speed`.
fn alks_scenario(target_s: f64, target_speed: f64, cruise: bool) -> String {
    let text = xosc(
        &format!(
            "{}{}<Private entityRef=\"Ego\"><PrivateAction><ActivateControllerAction longitudinal=\"true\" lateral=\"false\"/></PrivateAction></Private>",
            placed("Ego", 10.0, -1, 20.0),
            placed("Target", target_s, -1, target_speed)
        ),
        "",
        &stop_at(12.0),
    );
    let controller = format!(
        r#"<ObjectController><Controller name="ALKS_R157SM_Controller"><Properties><Property name="mode" value="override"/><Property name="model" value="Regulation"/><Property name="cruise" value="{cruise}"/><Property name="fullStop" value="true"/></Properties></Controller></ObjectController></ScenarioObject>"#
    );
    text.replacen("</ScenarioObject>", &controller, 1)
}

#[test]
fn alks_without_lead_keeps_its_set_speed() {
    // The Target is behind the Ego: nothing ahead, the cruise control keeps the speed at
    // activation (20 m/s) and the Ego covers 20 m/s × 10 s.
    let run = run_with(&alks_scenario(5.0, 20.0, true), &engine::Settings { step: 0.01, max_time: 12.0 });
    let (a, b) = (at(&run, "Ego", 0.0), at(&run, "Ego", 10.0));
    assert!(close(b.speed, 20.0, 1e-9), "{}", b.speed);
    assert!(close(b.x - a.x, 200.0, 1e-6), "{}", b.x - a.x);
}

#[test]
fn alks_regulation_brakes_at_six_for_a_standing_target() {
    // Standing Target at s = 100: free space = 100 + 1.5 - 2.25 - (s_ego + 1.5 + 2.25) =
    // 95.5 - s_ego. Regulation is critical once TTC = gap / 20 < 20 / 12 + 0.35 + 0.1 s, i.e. gap
    // < 42.33 m, but the Regulation model only sees 46 m ahead (reference point to reference
    // point), i.e. gap 41.5 m: it brakes from there at 6 m/s² (0.06 m/s per 10 ms step) to a
    // full stop, 333 steps covering 0.01 × Σ(20 − 0.06 k) = 33.23 m: stops 8.27 m short.
    let run = run_with(&alks_scenario(100.0, 0.0, false), &engine::Settings { step: 0.01, max_time: 12.0 });
    let mut braking_steps = 0;
    for k in 1..1100 {
        let (a, b) = (at(&run, "Ego", (k - 1) as f64 * 0.01).speed, at(&run, "Ego", k as f64 * 0.01).speed);
        if b < a && braking_steps == 0 {
            // Detection range 46 m between reference points: free space 41.5 m.
            let (e, g) = (at(&run, "Ego", (k - 1) as f64 * 0.01), at(&run, "Target", 0.0));
            assert!(close(g.x - e.x - 4.5, 41.5, 1e-6), "{}", g.x - e.x - 4.5);
        }
        if b < a {
            assert!(close(a - b, 0.06, 1e-9) || b == 0.0, "step {k}: {a} -> {b}");
            braking_steps += 1;
        }
    }
    assert!((333..=334).contains(&braking_steps), "{braking_steps}");
    let (e, g) = (at(&run, "Ego", 11.0), at(&run, "Target", 11.0));
    assert_eq!(e.speed, 0.0);
    let gap = g.x - e.x - 4.5;
    assert!(close(gap, 8.27, 0.01), "{gap}");
}

#[test]
fn a_speed_action_ends_at_once_under_the_controller_in_override_mode() {
    // alks_r157_speed_action.xosc: the controller active on both domains (override, the
    // default); the SpeedAction to 10 m/s at 2 s changes nothing in esmini 3.6.0
    // (LongSpeedAction::Start ends it): 20 m/s throughout, x = 20 + 20 t.
    let run = run_fixture("alks_r157_speed_action.xosc", "straight.xodr");
    for t in [2.0, 2.5, 4.0, 8.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, 20.0, 1e-9) && close(e.x, 20.0 + 20.0 * t, 1e-6), "t {t}: {e:?}");
    }
}

#[test]
fn frame_0_puts_an_entity_placed_before_the_road_start_on_the_road() {
    // alks_r157_placed_before_road_start: Ego, with an ALKS R157 controller (RSS, override),
    // is put 10 m behind Watcher (road 1, s = 5): 5 m before road 1's start. esmini steps the
    // controller in frame 0 (dt 0) and ControllerALKS_R157SM::Step's MoveAlongS(0) puts Ego
    // where its road coordinates are, s = 0. esmini: Ego at x = 0 at 0 s, 0.1 at 0.01 s, 10 at 1 s.
    let run = run_fixture("alks_r157_placed_before_road_start.xosc", "two_roads.xodr");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for (t, x) in [(0.0, 0.0), (0.01, 0.1), (1.0, 10.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-9) && close(e.y, -1.75, 1e-12), "{t}: {e:?}");
    }
}
