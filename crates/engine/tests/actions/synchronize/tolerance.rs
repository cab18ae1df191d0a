//! SynchronizeAction tolerances: without `targetTolerance`/`targetToleranceMaster` esmini 3.6
//! aims at the target positions themselves; given ones shorten both distances (the entities
//! aim at the edge of the tolerance circles). Straight fixture road, hand computations checked
//! against esmini 3.6.0's log. Started with the run, the action first stops the Target: the
//! master's velocity, derived from the motion of the step before, is still 0 (esmini's
//! "Waiting for master to move"); from standstill it then accelerates constantly.

use crate::common::*;

fn lane(s: f64, lane: i32) -> String {
    format!(r#"<LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/>"#)
}

/// Ego at s = 10 drives 10 m/s towards s = 110; Target at s = 50 (lane −2, 5 m/s) must reach
/// s = 150 at the same time, without a final speed.
fn scenario(tolerances: &str) -> String {
    let init = format!("{}{}", placed("Ego", 10.0, -1, 10.0), placed("Target", 50.0, -2, 5.0));
    let sync = format!(
        r#"<PrivateAction><SynchronizeAction masterEntityRef="Ego" {tolerances}><TargetPositionMaster>{}</TargetPositionMaster><TargetPosition>{}</TargetPosition></SynchronizeAction></PrivateAction>"#,
        lane(110.0, -1),
        lane(150.0, -2)
    );
    let stories = story("Target", &event("Sync", "overwrite", &sync, &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &stop_at(15.0))
}

#[test]
fn without_tolerances_the_entity_aims_at_the_target_position() {
    // 100 m in the master's 10 s from 0 m/s: a = 2·100/10² = 2 m/s² (esmini: 0.999975 m/s at 0.5 s).
    let run = run(&scenario(""));
    assert!(close(at(&run, "Target", 0.5).speed, 0.999975, 2e-6), "{}", at(&run, "Target", 0.5).speed);
    let dv = at(&run, "Target", 1.0).speed - at(&run, "Target", 0.5).speed;
    assert!(close(dv / 0.5, 2.0, 1e-3), "{dv}");
}

#[test]
fn given_tolerances_shorten_both_distances() {
    // 1 m tolerances: 99 m in 9.9 s from 0 m/s: a = 2·99/9.9² = 2.0202 m/s² (esmini: 1.010075 m/s
    // at 0.5 s; the action ends at 9.9 s).
    let run = run(&scenario(r#"targetTolerance="1" targetToleranceMaster="1""#));
    assert!(close(at(&run, "Target", 0.5).speed, 1.010075, 2e-6), "{}", at(&run, "Target", 0.5).speed);
    let dv = at(&run, "Target", 1.0).speed - at(&run, "Target", 0.5).speed;
    assert!(close(dv / 0.5, 2.0 * 99.0 / (9.9 * 9.9), 1e-3), "{dv}");
    let end = event_time(&run, "SyncAction", "end").expect("sync ends");
    assert!(close(end, 9.9, 0.05), "{end}");
}
