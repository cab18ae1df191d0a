//! A lane change under an ACC in override mode when the ACC's move takes the entity onto a road
//! that runs the other way (fixture `acc_override_lane_change_onto_opposite_road.xosc` on
//! `opposite_roads.xodr`: road 0 along +x meets road 1, along −x, end to end at x = 200; Ego at
//! 20 m/s in lane −1 of road 0 from s = 170, a 3 s sinusoidal shift of 0.5 m within its lane from
//! t > 1). esmini's LatLaneChangeAction::Step puts the entity back on its own position on road 0
//! with Position::SetLanePos, which keeps the heading relative to the road the ACC's MoveAlongS
//! left it on (road 1, facing against its s): on road 0 that faces back towards x = 0, and from
//! then on the entity drives back along road 0. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn the_acc_move_onto_an_opposite_road_turns_the_lane_changing_entity_round() {
    let run = run_fixture("acc_override_lane_change_onto_opposite_road.xosc", "opposite_roads.xodr");
    // (time, x, y, heading): on road 1 at 1.50 s, turned round on road 0 from 1.51 s
    // (was: on along road 1, x 200.4 at 1.51 s)
    let expected = [
        (1.49, 199.999936, -1.469077, 0.006186),
        (1.5, 200.199932, -1.467803, 0.006306),
        (1.51, 199.599936, -1.466506, 3.135167),
        (1.52, 199.399941, -1.465186, 3.135048),
        (2.5, 179.801124, -1.252618, 3.128505),
        (4.0, 149.802435, -1.000014, 3.141319),
    ];
    for (t, x, y, h) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.h, h, 1e-3), "t {t}: {e:?}, esmini ({x}, {y}) h {h}");
    }
}
