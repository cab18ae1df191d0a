//! RelativeClearanceCondition across a road link: the entity's lane is carried along the lane
//! links onto the other entity's road before the lanes are compared, and across the reference
//! line the centre lane is not counted (esmini's Position::Delta). Fixture: two roads meeting
//! end to end with opposite reference directions (`fixtures/opposite_roads.xodr`).

use crate::common::*;

fn run_on_opposite_roads(opposite_lanes: bool) -> engine::Run {
    // Ego on road 0, lane -1, s = 150 (x = 150), facing +x; Target on road 1, lane -1,
    // s = 190 (x = 210): on the lane that continues road 0's lane 1, 60 m ahead of Ego and
    // driving the other way. Both stand still.
    let init = r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="0" laneId="-1" offset="0" s="150"/></Position></TeleportAction></PrivateAction></Private><Private entityRef="Target"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" offset="0" s="190"/></Position></TeleportAction></PrivateAction></Private>"#;
    let cond = format!(
        r#"<Condition name="clear" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><RelativeClearanceCondition distanceForward="100" distanceBackward="30" freeSpace="false" oppositeLanes="{opposite_lanes}"><RelativeLaneRange from="-1" to="3"/><EntityRef entityRef="Target"/></RelativeClearanceCondition></EntityCondition></ByEntityCondition></Condition>"#
    );
    let stories = story("Ego", &event("E", "overwrite", &speed_action("step", "time", 0.0, 1.0), &trigger(&cond)));
    let stop = stop_at(1.0);
    let text = xosc(init, &stories, &stop).replace("straight.xodr", "opposite_roads.xodr");
    run_on(&text, "opposite_roads.xodr", &engine::Settings { step: 0.01, max_time: 5.0 })
}

#[test]
fn a_car_on_the_opposite_lane_beyond_a_link_is_not_in_the_way_unless_opposite_lanes_count() {
    // Carried across the link, Ego's lane -1 becomes road 1's lane 1; Target's lane -1 is on
    // the other side of the reference line: opposite, lane difference (−1 − 1) → −2 → −1
    // without the centre lane, inside [−1, 3]. Without opposite lanes the window is clear and
    // the event starts at once (the act starts at 0, its event in the same frame); with them
    // Target blocks it for good. esmini 3.6.0 on both scenarios (run by hand) agrees: E starts
    // at 0.000 without opposite lanes and never with them.
    let clear = run_on_opposite_roads(false);
    assert_eq!(event_time(&clear, "E", "start"), Some(0.0));
    let blocked = run_on_opposite_roads(true);
    assert_eq!(event_time(&blocked, "E", "start"), None);
}
