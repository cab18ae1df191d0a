//! Road geometry the engine applies to lane positions: superelevation (banking). The fixture
//! banked.xodr is the straight road (along +x) with a roll growing 0.01 rad per metre of s.

use crate::common::*;
use engine::Settings;

fn run_banked(text: &str) -> engine::Run {
    run_on(text, "banked.xodr", &Settings { step: 0.01, max_time: 1.0 })
}

#[test]
fn a_banked_lane_lies_along_the_tilted_surface() {
    // Lane −1's centre is t = −1.75 along the surface. At s = 50 the roll is 0.5 rad (rate
    // 0.01 /m): horizontally t·cos 0.5 from the reference line, t·sin 0.5 in height, and the
    // horizontal offset changing by −t·sin(roll)·rate per metre turns the heading by atan of
    // it. (A positive roll lowers the right side, t < 0, as in OpenDRIVE.)
    let stop = stop_at(0.5);
    let run = run_banked(&xosc(&teleport("Ego", 50.0, -1), "", &stop));
    let e = at(&run, "Ego", 0.0);
    let (t, roll, rate) = (-1.75f64, 0.5f64, 0.01f64);
    assert!(close(e.x, 50.0, 1e-9), "{e:?}");
    assert!(close(e.y, t * roll.cos(), 1e-9), "{e:?}");
    assert!(close(e.z, t * roll.sin(), 1e-9), "{e:?}");
    assert!(close(e.h, (-t * roll.sin() * rate).atan(), 1e-9), "{e:?}");
}

#[test]
fn a_lane_change_over_a_distance_counts_distance_along_the_road() {
    // On the straight fixture road: 10 m/s, a sinusoidal lane change from lane −1 to −2 over
    // 30 m. esmini measures the 30 m along the road (the path itself is longer by about
    // (1.75·π)² / (4·30) ≈ 0.26 m), so the car advances 30 m in x while changing lanes.
    let init = format!("{}{}", teleport("Ego", 100.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let action = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="30" dynamicsDimension="distance"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Change", "overwrite", action, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(6.0);
    let run = run(&xosc(&init, &stories, &stop));
    let t0 = event_time(&run, "ChangeAction", "start").expect("started");
    let t1 = event_time(&run, "ChangeAction", "end").expect("ended");
    let (a, b) = (at(&run, "Ego", t0), at(&run, "Ego", t1));
    assert!(close(b.x - a.x, 30.0, 0.08), "{a:?} {b:?}");
    assert!(close(b.y, -5.25, 1e-3), "{b:?}");
}

#[test]
fn a_teleported_entity_does_not_move_on_the_step_of_the_teleport() {
    // Ego drives at 10 m/s; at t > 1 s a story TeleportAction puts it at s = 500 on lane −1. The
    // row after the teleport shows it exactly there (esmini does not move it that step), the
    // next one 0.1 m further.
    let init = format!("{}{}", teleport("Ego", 100.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let action = format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(500.0, -1));
    let stories = story("Ego", &event("Jump", "overwrite", &action, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(3.0);
    let run = run(&xosc(&init, &stories, &stop));
    let t = event_time(&run, "JumpAction", "start").expect("teleported");
    let (a, b) = (at(&run, "Ego", t + 0.01), at(&run, "Ego", t + 0.02));
    assert!(close(a.x, 500.0, 1e-9), "{a:?}");
    assert!(close(b.x, 500.1, 1e-9), "{b:?}");
}

/// esmini's rows (time, x, y, speed) of `banked_world_position.xosc` (banked.xodr): Ego placed
/// by a WorldPosition 3 m right of the reference line at s = 50 (roll 0.5 rad), Ahead by a
/// RelativeRoadPosition 30 m ahead of it.
const EGO: [(f64, f64, f64, f64); 3] = [(0.0, 50.0, -3.0, 10.0), (1.0, 60.0, -2.821395, 10.0), (2.0, 70.0, -2.614599, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 3] = [(0.0, 80.0, -2.381679, 5.0), (1.0, 85.0, -2.25614, 5.0), (2.0, 90.0, -2.124962, 5.0)];

#[test]
fn a_world_point_on_a_banked_road_has_its_t_along_the_tilted_surface() {
    // esmini's Position::XYZ2TrackPos divides the horizontal distance from the reference line
    // by cos(roll): t = −3 / cos 0.5 = −3.42, so Ego keeps that t (lane offset −1.67) as the
    // roll grows, and Ahead, at the same t 30 m on, lies −3.42·cos 0.8 = −2.38 m out. Measured
    // horizontally (t = −3) both would sit 0.3 m further in. Found by crates/difftest
    // (m6006/s6006_00227, m4004/s4004_00045); expected values: esmini 3.6.0 on the fixture.
    let run = run_fixture_on("banked_world_position.xosc", "banked.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-3);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-3);
    // the point's height is the banked surface's, t·sin(roll) below the reference line, from
    // the start (esmini's z: −1.638907 at 0 s, −1.641907 at 0.01 s), so the first step's
    // vertical speed is the climb's alone (found by crates/difftest: s26026_00317 on
    // velodrome.xodr, a vertical SpeedCondition)
    for (t, z) in [(0.0, -1.638907), (0.01, -1.641907)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.z, z, 1e-5), "at {t}: {e:?}, esmini z {z}");
    }
}

/// esmini's rows (time, x, y, speed) of `relative_object_banked.xosc` (banked.xodr): Ego on
/// lane −1 at s = 50 (roll 0.5 rad), Beside placed by a RelativeObjectPosition 10 m behind and
/// 3.5 m to the left of it.
const BANKED_EGO: [(f64, f64, f64, f64); 2] = [(0.0, 50.0, -1.535769, 10.0), (2.0, 70.0, -1.338474, 10.0)];
const BESIDE: [(f64, f64, f64, f64); 2] = [(0.0, 40.001531, 1.45188, 5.0), (2.0, 50.001531, 1.383342, 5.0)];

#[test]
fn a_relative_object_position_turns_with_the_entity_s_roll() {
    // esmini's Position::EvaluateRelation (RELATIVE_OBJECT) turns (dx, dy, dz) by the entity's
    // heading, pitch and roll (RotateVec3d): rolled 0.5 rad, dy = 3.5 reaches 3.5·cos 0.5 =
    // 3.07 m across, not 3.5 m. Ego's pitch is not the level road's 0 but the road's roll
    // composed with the pitch GetPOffset adds where the roll changes, atan(tan 0.01 · 1.75)
    // (Position::EvaluateHPR, R0R12EulerAngles): 0.02 rad, which moves Beside 0.03 m along x.
    // Found by crates/difftest (m5005/s5005_00182, velodrome.xodr); expected values: esmini
    // 3.6.0 on the fixture.
    let run = run_fixture_on("relative_object_banked.xosc", "banked.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &BANKED_EGO, 1e-3);
    assert_esmini_rows(&run, "Beside", &BESIDE, 1e-3);
}

/// esmini's rows (time, x, y, speed) of `banked_world_heading.xosc` (banked.xodr): Ego placed
/// by a WorldPosition 3 m right of the reference line at s = 50 facing 0.1 rad (absolute),
/// Beside by a RelativeObjectPosition 20 m behind and 2 m right of Ego, OnSpline by a
/// TrajectoryPosition 40 m along a straight clothoid spline starting at a WorldPosition
/// (20, −4) facing 0.
const WORLD_EGO: [(f64, f64, f64, f64); 3] = [(0.0, 50.0, -3.0, 10.0), (1.0, 60.0, -2.821395, 10.0), (2.0, 70.0, -2.614599, 10.0)];
const WORLD_BESIDE: [(f64, f64, f64, f64); 3] = [(0.0, 30.311202, -6.825216, 5.0), (1.0, 35.311202, -6.710002, 5.0), (2.0, 40.311202, -6.578016, 5.0)];
const ON_SPLINE: [(f64, f64, f64, f64); 2] = [(0.0, 59.998685, -3.675664, 0.0), (2.0, 59.998685, -3.675664, 0.0)];

#[test]
fn a_world_position_on_a_banked_road_holds_the_heading_composed_with_the_road_s_rotation() {
    // esmini's Position::EvaluateHPR composes the road's rotation (roll 0.5 rad at s = 50)
    // with the position's own: the absolute heading less the road's (0.1) and the pitch
    // GetPOffset adds where the roll changes, atan(tan 0.01 · 3.42) with t = −3.42 along the
    // surface (R0R12EulerAngles). The position then faces 0.1041, not 0.1, and is pitched
    // 0.034 rad: Beside, turned by that heading, pitch and roll, lands 0.2 m further left
    // than by the road's roll alone; the spline starts along 0.0081 rad (roll 0.2 and pitch
    // 0.041 at s = 20, heading 0), so 40 m on it lies 0.32 m left of its start line. Found by
    // crates/difftest
    // (s31031_00999, s31031_00657 on pitch_by_super_elevation.xodr); expected values: esmini
    // 3.6.0 on the fixture.
    let run = run_fixture_on("banked_world_heading.xosc", "banked.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &WORLD_EGO, 1e-3);
    assert_esmini_rows(&run, "Beside", &WORLD_BESIDE, 1e-3);
    assert_esmini_rows(&run, "OnSpline", &ON_SPLINE, 1e-3);
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.h, 0.104146, 1e-5), "{e:?}");
}
