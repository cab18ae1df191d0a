//! Distance actions whose event runs them again (maximumExecutionCount > 1): esmini builds
//! each action object once per actor and only starts it again, so what its Start and Step
//! leave in the object is there at the next execution.
//!
//! Fixture `distance_actions_repeated.xosc` (straight road, all at 10 m/s):
//! - Act synchronises with Master (master target s = 120, its own target 60 m ahead of itself,
//!   re-evaluated at each start). The first execution arrives at t = 10.00 s; the second starts
//!   at 10.01 s 60 m from its new target, more than the last distance SynchronizeAction::Step
//!   kept (0), and is done at once ("missed destination"): it ends in its first step.
//! - Follower keeps 10 m to Lead with displacement "any" and no limits: the first execution
//!   (t = 1.01 s, Follower behind) resolves "any" to trailing and jumps 10 m behind Lead; at
//!   3 s Follower is put 30 m ahead of Lead; the second execution (5.01 s) keeps the trailing
//!   side LongDistanceAction::Start resolved the first time and jumps back 10 m behind Lead,
//!   not 10 m ahead.
//!
//! The numbers are esmini 3.6.0's.

use crate::common::event_time;
use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn distance_actions_executed_again_keep_their_objects_state() {
    let run = assert_fixture_matches_esmini(
        "distance_actions_repeated.xosc",
        14.0,
        &[
            ("Follower", 5.01, 420.0, -1.75, 0.0),
            // Behind Lead (at 390.2), as the first execution resolved "any".
            ("Follower", 5.02, 380.2, -1.75, 0.0),
            ("Follower", 7.02, 400.2, -1.75, 0.0),
            ("Act", 10.0, 120.1, -1.75, 0.0),
            ("Act", 10.01, 120.133954, -1.75, 0.0),
        ],
    );
    let sync_ends: Vec<f64> = run.trace.events.iter().filter(|e| e.element == "ESync" && e.transition == "end").map(|e| e.time).collect();
    assert_eq!(sync_ends.len(), 2, "{sync_ends:?}");
    assert!((sync_ends[0] - 10.0).abs() < 1e-9 && (sync_ends[1] - 10.01).abs() < 1e-9, "{sync_ends:?}");
    assert!(event_time(&run, "EGap", "start").is_some_and(|t| (t - 1.01).abs() < 1e-9));
}
