//! LateralDistanceAction (road coordinates, with a maximum acceleration) where a road ends:
//! the actor that reaches a dead end turns round and drives back along the road, a reference
//! that passes a direct junction stays joined to the actor behind it, and an actor with a
//! route keeps to it through a junction. The expected poses are esmini 3.6.0's on these
//! scenarios (written here, run with esmini).

use crate::common::*;

/// Ego keeps 5 m left of the Target in road coordinates (maxAcceleration 2, maxSpeed 3), from
/// 0.5 s on; `ego` and `target` are (s, lane, speed) on road 1.
fn scenario(ego: (f64, i32, f64), target: (f64, i32, f64)) -> String {
    let init = format!("{}{}", placed_in_one_private("Ego", ego.0, ego.1, ego.2), placed_in_one_private("Target", target.0, target.1, target.2));
    let action = r#"<PrivateAction><LateralAction><LateralDistanceAction entityRef="Target" coordinateSystem="road" distance="5" freespace="false" continuous="true" displacement="leftToReferencedEntity"><DynamicConstraints maxAcceleration="2" maxDeceleration="5" maxSpeed="3"/></LateralDistanceAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Keep", "overwrite", action, &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))));
    xosc(&init, &stories, &stop_at(6.0))
}

#[test]
fn at_a_dead_end_the_actor_turns_round() {
    // Ego drives lane 1 towards s = 0, where the road has no predecessor. Stuck there, only the
    // offset moves it: its heading (the step's displacement) turns across the road, and
    // Object::MoveAlongS, which goes the way the heading points, takes it back along +s.
    let run = run(&scenario((20.0, 1, 10.0), (20.0, -1, 0.0)));
    let rows = [
        ("Ego", 1.0, 10.001469, 1.856951, 3.103885),
        ("Ego", 2.0, 0.012542, 2.326467, 3.094323),
        ("Ego", 2.5, 4.795382, 2.546187, 0.040353),
        ("Ego", 4.0, 19.788904, 2.976389, 0.018495),
        ("Ego", 6.0, 39.787679, 3.183664, 0.004894),
    ];
    assert_esmini_poses(&run, &rows, 0.01, 0.001);
}

#[test]
fn a_reference_past_a_direct_junction_is_still_joined_to_the_actor() {
    // The Target leaves road 1 for road 2 at 4 s through a direct junction whose connection
    // names road 1 as incoming; esmini adds the counter connection, so the road path from
    // road 2 back to road 1 exists and the action goes on (it used to end there).
    let text = scenario((20.0, -1, 10.0), (60.0, -1, 10.0)).replace("straight.xodr", "direct_junction.xodr");
    let run = run_on(&text, "direct_junction.xodr", &engine::Settings { step: 0.01, max_time: 20.0 });
    let w: Vec<_> = run.warnings.iter().filter(|w| w.message.contains("LateralDistanceAction")).collect();
    assert!(w.is_empty(), "{w:?}");
    let rows = [
        ("Ego", 2.0, 39.881574, -0.04205, 0.160917),
        ("Ego", 4.0, 59.741712, 2.247782, 0.067044),
        ("Ego", 5.0, 69.719744, 1.923752, 6.151401),
        ("Ego", 6.0, 79.454841, -0.311515, 5.998546),
    ];
    assert_esmini_poses(&run, &rows, 0.01, 0.001);
}

#[test]
fn through_a_junction_the_actor_keeps_to_its_route() {
    // On the crossing (`crossing.xodr`), Ego drives road 3's lane 1 east towards the junction
    // with a route that turns left onto road 2 (north); the action's move along the road is
    // Object::MoveAlongS, which follows the assigned route (it used to go straight on).
    let route = r#"<PrivateAction><RoutingAction><AssignRouteAction><Route name="Left" closed="false"><Waypoint routeStrategy="shortest"><Position><LanePosition roadId="3" laneId="1" offset="0" s="40"/></Position></Waypoint><Waypoint routeStrategy="shortest"><Position><LanePosition roadId="2" laneId="-1" offset="0" s="50"/></Position></Waypoint></Route></AssignRouteAction></RoutingAction></PrivateAction></Private>"#;
    let text =
        scenario((40.0, 1, 10.0), (30.0, -1, 0.0)).replacen("</Private>", route, 1).replace(r#"<LanePosition roadId="1""#, r#"<LanePosition roadId="3""#);
    let run = run_on(&text.replace("straight.xodr", "crossing.xodr"), "crossing.xodr", &engine::Settings { step: 0.01, max_time: 20.0 });
    let rows = [
        ("Ego", 3.0, -30.020677, -2.727306, 6.250914),
        ("Ego", 4.0, -20.023859, -2.976389, 6.26469),
        ("Ego", 5.0, -10.318974, -0.822074, 0.424862),
        ("Ego", 6.0, -2.377101, 5.125691, 0.857844),
    ];
    assert_esmini_poses(&run, &rows, 0.01, 0.001);
}
