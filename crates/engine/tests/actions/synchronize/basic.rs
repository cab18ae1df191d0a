//! SynchronizeAction on the straight fixture road, against hand computations (see `common`).

use crate::common::*;

fn lane(s: f64, lane: i32) -> String {
    format!(r#"<LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/>"#)
}

fn synchronize(master_s: f64, target_s: f64, final_speed: &str) -> String {
    format!(
        r#"<PrivateAction><SynchronizeAction masterEntityRef="Ego"><TargetPositionMaster>{}</TargetPositionMaster><TargetPosition>{}</TargetPosition>{final_speed}</SynchronizeAction></PrivateAction>"#,
        lane(master_s, -1),
        lane(target_s, -2)
    )
}

fn scenario(target_speed: f64, final_speed: &str) -> String {
    // Ego at s = 10 drives 10 m/s towards s = 110; Target at s = 50 (lane -2) must reach s = 150
    // at the same time: 100 m each (esmini 3.6's default tolerance is 0 m).
    let init = format!("{}{}", placed("Ego", 10.0, -1, 10.0), placed("Target", 50.0, -2, target_speed));
    let stories =
        story("Target", &event("Sync", "overwrite", &synchronize(110.0, 150.0, final_speed), &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &stop_at(15.0))
}

#[test]
fn a_master_without_velocity_yet_stops_the_actor_first() {
    // Same speed, same distance, but started with the run: in its first step the master's
    // velocity (esmini's GetVelS, derived from the motion of the step before) is still 0, so
    // esmini stops the Target ("Waiting for master to move"), then covers the 100 m in the
    // master's 10 s from standstill: 2 m/s². Values of esmini 3.6.0's log of this scenario.
    let run = run(&scenario(10.0, ""));
    for (t, x, v) in [(0.0, 50.0, 0.0), (0.01, 50.0002, 0.02), (1.0, 51.009965, 1.999894), (5.0, 75.044309, 9.996143)] {
        let g = at(&run, "Target", t);
        assert!(close(g.x, x, 2e-6) && close(g.speed, v, 2e-6), "t={t}: {} {}", g.x, g.speed);
    }
}

#[test]
fn without_final_speed_accelerates_constantly_to_arrive_together() {
    // 100 m in 10 s from 5 m/s: constant acceleration a = 2·(100 − 5·10)/10² = 1 m/s²
    // (final speed 15 m/s); the action ends when the master arrives.
    let run = run(&scenario(5.0, ""));
    let v5 = at(&run, "Target", 5.0).speed;
    assert!(close(v5, 5.0 + 5.0 * 1.0, 0.05), "{v5}");
    let end = event_time(&run, "SyncAction", "end").expect("sync ends");
    assert!(close(end, 10.0, 0.05), "{end}");
    let g = at(&run, "Target", end);
    assert!(close(g.x, 150.0, 0.3), "target at {} when the master arrives", g.x);
}

#[test]
fn final_speed_is_reached_on_arrival() {
    // From 5 m/s, final speed 10 m/s: two constant-acceleration phases; on arrival the Target is at
    // its target position (within the tolerance) and moves at 10 m/s.
    let fin = r#"<FinalSpeed><AbsoluteSpeed value="10"/></FinalSpeed>"#;
    let run = run(&scenario(5.0, fin));
    let end = event_time(&run, "SyncAction", "end").expect("sync ends");
    assert!(close(end, 10.0, 0.05), "{end}");
    let g = at(&run, "Target", end + 0.01);
    assert!(close(g.x, 150.0, 0.5), "{}", g.x);
    assert!(close(g.speed, 10.0, 1e-9));
    // Average speed 10 from 5 and back to 10: the profile rises above 10 on the way (convex).
    let peak = (1..1000).map(|k| at(&run, "Target", k as f64 * 0.01).speed).fold(0.0, f64::max);
    assert!(peak > 12.0, "{peak}");
}

#[test]
fn steady_state_holds_the_final_speed_over_the_last_distance() {
    // Steady state over the last 30 m at 10 m/s (3 s): from t ≈ 7 s the speed stays 10 m/s.
    let fin = r#"<FinalSpeed><AbsoluteSpeed value="10"><TargetDistanceSteadyState distance="30"/></AbsoluteSpeed></FinalSpeed>"#;
    let run = run(&scenario(5.0, fin));
    for t in [7.2, 8.0, 9.5] {
        assert!(close(at(&run, "Target", t).speed, 10.0, 1e-9), "t={t}");
    }
    let end = event_time(&run, "SyncAction", "end").expect("sync ends");
    assert!(close(at(&run, "Target", end).x, 150.0, 0.6));
}
