//! RelativeLanePosition with `ds` (along the road's s axis) and with `dsLane` (along the
//! reference lane's driving direction), as esmini 3.6.0's Position::SetRelativePosition
//! resolves them — checked by running esmini on these scenarios. On the straight fixture road
//! (lanes 1, −1, −2, 3.5 m wide; lane 1 drives against s): Target is teleported relative to
//! Ego at t = 1, 2 and 3 with offset 0.5.
//! - `ds`: s + ds, dLane and the offset counted as lane ids and t count, facing +s.
//! - `dsLane`: s moves along the reference lane's driving direction; dLane and the offset
//!   count to the left of the road's s axis only when the reference stands on a right lane
//!   facing +s, otherwise to the other side; the entity faces its new lane's driving direction.

use crate::common::*;
use std::f64::consts::PI;

fn rel(d_lane: i32, attr: &str, v: f64) -> String {
    format!(r#"<Position><RelativeLanePosition entityRef="Ego" dLane="{d_lane}" {attr}="{v}" offset="0.5"/></Position>"#)
}

fn teleport_to(pos: &str) -> String {
    format!("<PrivateAction><TeleportAction>{pos}</TeleportAction></PrivateAction>")
}

/// Ego at s = 100 on `lane`, turned by `h` from its lane's direction; Target teleported three times.
fn scenario(lane: i32, h: f64) -> engine::Run {
    let ego =
        format!(r#"<Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="100"><Orientation type="relative" h="{h}"/></LanePosition></Position>"#);
    let init = format!(r#"<Private entityRef="Ego">{}</Private>{}"#, teleport_to(&ego), teleport("Target", 300.0, -1));
    let moves = [(1.0, rel(-1, "ds", 3.0)), (2.0, rel(1, "dsLane", 5.0)), (3.0, rel(0, "dsLane", -4.0))];
    let events: String = moves
        .iter()
        .enumerate()
        .map(|(i, (t, p))| event(&format!("E{i}"), "overwrite", &teleport_to(p), &trigger(&sim_time(*t, "greaterOrEqual", "none", 0.0))))
        .collect();
    let stop = stop_at(4.0);
    run(&xosc(&init, &story("Target", &events), &stop))
}

fn heading_is(h: f64, want: f64) -> bool {
    let d = (h - want).rem_euclid(2.0 * PI);
    d < 1e-9 || 2.0 * PI - d < 1e-9
}

fn check(run: &engine::Run, expected: &[(f64, f64, f64, f64)]) {
    for &(t, x, y, h) in expected {
        let e = at(run, "Target", t);
        assert!(close(e.x, x, 1e-9) && close(e.y, y, 1e-9) && heading_is(e.h, h), "t = {t}: {e:?}, expected ({x}, {y}, {h})");
    }
}

#[test]
fn reference_on_a_left_lane_facing_its_driving_direction() {
    // ds: lane 1 − 1 → −1, s 103, t −1.75 + 0.5. dsLane 5 along lane 1 (−s): s 95; dLane and
    // offset mirrored: lane −1, offset −0.5; faces lane −1's direction (+s). dsLane −4: s 104,
    // lane 1, offset −0.5 to the left of −s: t 1.75 − 0.5; faces π.
    check(&scenario(1, 0.0), &[(1.5, 103.0, -1.25, 0.0), (2.5, 95.0, -2.25, 0.0), (3.5, 104.0, 1.25, PI)]);
}

#[test]
fn reference_on_a_left_lane_facing_against_it_counts_the_same() {
    check(&scenario(1, PI), &[(1.5, 103.0, -1.25, 0.0), (2.5, 95.0, -2.25, 0.0), (3.5, 104.0, 1.25, PI)]);
}

#[test]
fn reference_on_a_right_lane_facing_against_it_mirrors_dlane() {
    // ds: lane −2, s 103, t −5.25 + 0.5. dsLane 5 along lane −1 (+s): s 105; Ego faces −s, so
    // dLane 1 goes to lane −2 and the offset is −0.5. dsLane −4: s 96, lane −1, t −1.75 − 0.5.
    check(&scenario(-1, PI), &[(1.5, 103.0, -4.75, 0.0), (2.5, 105.0, -5.75, 0.0), (3.5, 96.0, -2.25, 0.0)]);
}
