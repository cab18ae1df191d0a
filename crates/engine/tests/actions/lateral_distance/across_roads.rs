//! LateralDistanceAction (road coordinates, rigid) between a reference and an actor, on the
//! same road or on roads that meet end to end, as esmini 3.6.0 measures it through its
//! road-path delta (LatDistanceAction::GetDistanceError, Position::Delta, RoadPath::Calculate)
//! — every expected position was checked by running esmini on these scenarios.
//! Fixture `fixtures/opposite_roads.xodr`: road 0 from (0, 0) along +x, road 1 from (400, 0)
//! along −x, their ends meeting at x = 200; lanes 1 and −1, 3 m wide (centres at t = ±1.5).
//! The actor (Target) drives road 0's lane −1 (y = −1.5) along +x at 5 m/s.

use crate::common::*;

fn run_lateral(reference_road: u32, lane: i32, reference_s: f64, displacement: &str) -> engine::Run {
    let init = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="{reference_road}" laneId="{lane}" offset="0" s="{reference_s}"/></Position></TeleportAction></PrivateAction></Private><Private entityRef="Target"><PrivateAction><TeleportAction><Position><LanePosition roadId="0" laneId="-1" offset="0" s="50"/></Position></TeleportAction></PrivateAction>{}</Private>"#,
        speed_action("step", "time", 0.0, 5.0)
    );
    let action = format!(
        r#"<PrivateAction><LateralAction><LateralDistanceAction entityRef="Ego" distance="1" freespace="false" continuous="false" coordinateSystem="road" displacement="{displacement}"/></LateralAction></PrivateAction>"#
    );
    let stories = story("Target", &event("L", "overwrite", &action, &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))));
    let stop = stop_at(2.0);
    let text = xosc(&init, &stories, &stop).replace("straight.xodr", "opposite_roads.xodr");
    run_on(&text, "opposite_roads.xodr", &engine::Settings { step: 0.01, max_time: 5.0 })
}

/// The actor's y once the action has placed it, and that nothing was approximated.
fn settled_y(run: &engine::Run) -> f64 {
    let w: Vec<_> = run.warnings.iter().filter(|w| w.message.contains("LateralDistanceAction")).collect();
    assert!(w.is_empty(), "{w:?}");
    let e = at(run, "Target", 1.5);
    assert!(close(e.x, 57.5, 1e-9), "{e:?}");
    e.y
}

#[test]
fn reference_ahead_on_the_opposite_road_facing_the_actor() {
    // Ego on road 1's lane −1 at x = 300, y = 1.5, facing −x: 1 m to its left is y = 0.5.
    assert!(close(settled_y(&run_lateral(1, -1, 100.0, "leftToReferencedEntity")), 0.5, 1e-9));
}

#[test]
fn reference_on_the_opposite_road_facing_away_from_the_path() {
    // Ego on road 1's lane 1 at x = 300, y = −1.5, facing +x (against road 1's s): the path to
    // the actor starts behind it; 1 m to its left is y = −0.5, to its right y = −2.5.
    assert!(close(settled_y(&run_lateral(1, 1, 100.0, "leftToReferencedEntity")), -0.5, 1e-9));
    assert!(close(settled_y(&run_lateral(1, 1, 100.0, "rightToReferencedEntity")), -2.5, 1e-9));
}

#[test]
fn reference_on_the_same_road_facing_against_its_s() {
    // Ego on road 0's lane 1 at x = 150, y = 1.5, facing −x: its left is −y, so y = 0.5.
    assert!(close(settled_y(&run_lateral(0, 1, 150.0, "leftToReferencedEntity")), 0.5, 1e-9));
}

#[test]
fn reference_on_the_same_road_facing_along_its_s() {
    // Ego on road 0's lane −1 at x = 150, y = −1.5, facing +x: 1 m to its right is y = −2.5.
    assert!(close(settled_y(&run_lateral(0, -1, 150.0, "rightToReferencedEntity")), -2.5, 1e-9));
}
