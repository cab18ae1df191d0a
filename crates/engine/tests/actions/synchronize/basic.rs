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
    let init = format!(
        "{}{}{}{}",
        teleport("Ego", 10.0, -1),
        init_speed("Ego", "step", "time", 0.0, 10.0),
        teleport("Target", 50.0, -2),
        init_speed("Target", "step", "time", 0.0, target_speed)
    );
    let stories =
        story("Target", &event("Sync", "overwrite", &synchronize(110.0, 150.0, final_speed), &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &format!("<ConditionGroup>{}</ConditionGroup>", sim_time(15.0, "greaterThan", "none", 0.0)))
}

#[test]
fn same_speed_same_distance_keeps_the_speed() {
    let run = run(&scenario(10.0, ""));
    for t in [1.0, 5.0, 9.0] {
        let (e, g) = (at(&run, "Ego", t), at(&run, "Target", t));
        assert!(close(g.speed, 10.0, 1e-6), "t={t}: {}", g.speed);
        assert!(close(g.x - e.x, 40.0, 1e-6));
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
