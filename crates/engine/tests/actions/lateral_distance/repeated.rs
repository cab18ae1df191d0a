//! A LateralDistanceAction in road coordinates whose event runs it again
//! (maximumExecutionCount > 1). esmini builds the action object once per actor and only starts
//! it again: LatDistanceAction::Start changes the object's own distance (made negative for the
//! left side, the freespace half-widths added on that side), so every execution adds the
//! half-widths once more; and neither Start nor the first step resets the spring's lateral
//! speed and acceleration, so a second execution starts with what the first ended with.
//!
//! Fixture `lat_distance_repeated.xosc` (straight road, all at 10 m/s, the events start at
//! t > 1 s and, non-continuous, start again the step after they end):
//! - ActA, 0.5 m freespace left of RefA (both 2 m wide), maxAcceleration 3, three executions:
//!   0.5 + 2 m, then 2 m further left each time (y 0.74, 2.74, 4.74);
//! - ActB, 2 m right of RefB, maxAcceleration 2 with a jerk limit: the second execution
//!   starts with the first one's lateral speed and overshoots before settling (8.33 s);
//! - ActC, 1 m freespace right of RefC, maxSpeed only: 2 m further right each execution.
//!
//! Main started every execution afresh: the restarts ended at once (ActA, ActC) or 1.3 s early
//! (ActB). The numbers are esmini 3.6.0's.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_event_executed_again_carries_the_distance_and_lateral_motion_over() {
    let run = assert_fixture_matches_esmini(
        "lat_distance_repeated.xosc",
        25.0,
        &[
            ("ActA", 8.09, 100.814267, 0.74002, 0.000951),
            ("ActA", 14.95, 169.358885, 2.74006, 0.000944),
            ("ActA", 21.81, 237.903507, 4.74006, 0.000944),
            ("ActB", 4.79, 347.319929, -7.250549, 6.045854),
            ("ActB", 6.0, 359.224127, -9.348289, 6.191346),
            ("ActB", 8.33, 382.342184, -7.241812, 0.191916),
            ("ActC", 2.52, 624.896939, -8.249999, 6.081827),
            ("ActC", 3.54, 634.894898, -10.249999, 6.081827),
            ("ActC", 4.56, 644.892857, -12.249999, 6.081827),
        ],
    );
    // The executions end when esmini's do.
    let ends: Vec<f64> = run.trace.events.iter().filter(|e| e.element == "EActA" && e.transition == "end").map(|e| e.time).collect();
    assert_eq!(ends.len(), 3, "{ends:?}");
    for (got, want) in ends.iter().zip([8.09, 14.95, 21.81]) {
        assert!((got - want).abs() < 1e-9, "{ends:?}");
    }
}
