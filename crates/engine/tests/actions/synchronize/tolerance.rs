//! SynchronizeAction tolerances: without `targetTolerance`/`targetToleranceMaster` esmini 3.6
//! aims at the target positions themselves; given ones shorten both distances (the entities
//! aim at the edge of the tolerance circles). Straight fixture road, hand computations.

use crate::common::*;

fn lane(s: f64, lane: i32) -> String {
    format!(r#"<LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/>"#)
}

/// Ego at s = 10 drives 10 m/s towards s = 110; Target at s = 50 (lane −2, 5 m/s) must reach
/// s = 150 at the same time, without a final speed.
fn scenario(tolerances: &str) -> String {
    let init = format!(
        "{}{}{}{}",
        teleport("Ego", 10.0, -1),
        init_speed("Ego", "step", "time", 0.0, 10.0),
        teleport("Target", 50.0, -2),
        init_speed("Target", "step", "time", 0.0, 5.0)
    );
    let sync = format!(
        r#"<PrivateAction><SynchronizeAction masterEntityRef="Ego" {tolerances}><TargetPositionMaster>{}</TargetPositionMaster><TargetPosition>{}</TargetPosition></SynchronizeAction></PrivateAction>"#,
        lane(110.0, -1),
        lane(150.0, -2)
    );
    let stories = story("Target", &event("Sync", "overwrite", &sync, &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &format!("<ConditionGroup>{}</ConditionGroup>", sim_time(15.0, "greaterThan", "none", 0.0)))
}

#[test]
fn without_tolerances_the_entity_aims_at_the_target_position() {
    // 100 m in the master's 10 s from 5 m/s: a = 2·(100 − 5·10)/10² = 1 m/s², from the first step.
    let run = run(&scenario(""));
    let dv = at(&run, "Target", 1.0).speed - at(&run, "Target", 0.5).speed;
    assert!(close(dv / 0.5, 1.0, 1e-3), "{dv}");
}

#[test]
fn given_tolerances_shorten_both_distances() {
    // 1 m tolerances: 99 m in 9.9 s: a = 2·(99 − 5·9.9)/9.9² = 1.0101 m/s².
    let run = run(&scenario(r#"targetTolerance="1" targetToleranceMaster="1""#));
    let dv = at(&run, "Target", 1.0).speed - at(&run, "Target", 0.5).speed;
    assert!(close(dv / 0.5, 2.0 * (99.0 - 5.0 * 9.9) / (9.9 * 9.9), 1e-3), "{dv}");
    let end = event_time(&run, "SyncAction", "end").expect("sync ends");
    assert!(close(end, 9.9, 0.05), "{end}");
}
