//! The lane an entity keeps on an AcquirePosition route when its lane ends: esmini puts it on
//! the centre of the nearest drivable lane as soon as its own lane has no width left (the
//! tow vehicle of esmini's trailers scenario). Road: `fixtures/merge.xodr`, 1000 m along +x,
//! lane -1 3.5 m wide (centre y = -1.75), lane -2 3.5 m wide up to s = 50, narrowing linearly
//! to nothing at s = 60, then zero wide; lane -3 a 0.3 m border.

use crate::common::*;
use engine::{Run, Settings};

fn run_merge(text: &str) -> Run {
    run_on(text, "merge.xodr", &Settings { step: 0.01, max_time: 20.0 })
}

fn acquire(s: f64, lane: i32) -> String {
    format!(r#"<PrivateAction><RoutingAction><AcquirePositionAction>{}</AcquirePositionAction></RoutingAction></PrivateAction>"#, lane_pos(s, lane))
}

fn scenario(actions: &str) -> String {
    let init = format!(
        r#"{}<Private entityRef="Ego">{}{actions}</Private>{}"#,
        teleport("Ego", 10.0, -2),
        speed_action("step", "time", 0.0, 10.0),
        teleport("Target", 500.0, -1)
    );
    xosc(&init, "", &stop_at(8.0))
}

fn lane_of(run: &Run, t: f64) -> Option<i32> {
    at(run, "Ego", t).road.map(|r| r.lane_id)
}

#[test]
fn an_ending_lane_on_an_acquire_position_route_drops_the_vehicle_into_the_next_lane() {
    // 10 m/s from s = 10: s = 10 + 10 t.
    let run = run_merge(&scenario(&acquire(300.0, -1)));
    // t = 3: s = 40, lane -2 full width: centre −3.5 − 1.75 = −5.25.
    let e = at(&run, "Ego", 3.0);
    assert!(close(e.x, 40.0, 1e-6) && close(e.y, -5.25, 1e-6), "{e:?}");
    // t = 4.5: s = 55, width 3.5 − 0.35·5 = 1.75: centre −3.5 − 0.875 = −4.375 — still lane −2
    // (a narrowing lane is kept while it has any width).
    let e = at(&run, "Ego", 4.5);
    assert!(close(e.x, 55.0, 1e-6) && close(e.y, -4.375, 1e-6), "{e:?}");
    assert_eq!(lane_of(&run, 4.5), Some(-2));
    // t = 4.99: s = 59.9, width 0.035: centre −3.5175, still lane −2.
    let e = at(&run, "Ego", 4.99);
    assert!(close(e.y, -3.5175, 1e-6), "{e:?}");
    // Past s = 60 lane −2 has no width: the nearest drivable lane is −1 (centre −1.75, 1.75 m
    // away; the border's centre −3.65 is nearer but not drivable), entered at its centre.
    for t in [5.02, 6.0, 7.5] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, 10.0 + 10.0 * t, 1e-6) && close(e.y, -1.75, 1e-9), "t = {t}: {e:?}");
        assert_eq!(lane_of(&run, t), Some(-1));
    }
}

#[test]
fn without_a_route_the_same_rule_applies() {
    // The rule belongs to moving along the road, not to the route: the default controller
    // alone drops the vehicle into lane −1 at the same place.
    let run = run_merge(&scenario(""));
    assert!(close(at(&run, "Ego", 4.5).y, -4.375, 1e-6));
    let e = at(&run, "Ego", 6.0);
    assert!(close(e.x, 70.0, 1e-6) && close(e.y, -1.75, 1e-9), "{e:?}");
}

#[test]
fn the_heading_follows_the_lane_centre_while_the_lane_narrows() {
    // Lane −2's centre is t = −3.5 − w/2 with w' = −0.35 on s = 50 … 60: the centre moves
    // towards the reference line at dt/ds = +0.175, so the vehicle (driving along +x) heads
    // atan(0.175) to the left there, and straight along the road before and after.
    let run = run_merge(&scenario(&acquire(300.0, -1)));
    assert!(at(&run, "Ego", 3.0).h.abs() < 1e-12);
    let h = at(&run, "Ego", 4.5).h;
    assert!(close(h, 0.175f64.atan(), 1e-12), "{h}");
    let h = at(&run, "Ego", 6.0).h;
    assert!(h.abs() < 1e-12 || (h - 2.0 * std::f64::consts::PI).abs() < 1e-12, "{h}");
}
