//! Headings of positions given in road terms on the left side of the road (right-hand
//! traffic, where lanes 1, 2, … drive against s). esmini turns a RoadPosition's relative
//! orientation from the road's reference direction on either side, but a LanePosition's from
//! the lane's driving direction (half a turn on the left). Straight fixture road along +x
//! (heading 0); lane 1's centre is y = 1.75.

use crate::common::*;
use std::f64::consts::PI;

fn place(entity: &str, position: &str) -> String {
    format!(r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction></Private>"#)
}

fn dh(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    if d > PI {
        d - 2.0 * PI
    } else {
        d
    }
}

fn stop() -> String {
    stop_at(1.0)
}

#[test]
fn a_road_position_turns_its_relative_heading_from_the_reference_line_on_the_left_too() {
    let road = r#"<RoadPosition roadId="1" s="50" t="1.75"><Orientation type="relative" h="0.3"/></RoadPosition>"#;
    let lane = r#"<LanePosition roadId="1" laneId="1" s="80" offset="0"><Orientation type="relative" h="0.3"/></LanePosition>"#;
    let init = format!("{}{}", place("Ego", road), place("Target", lane));
    let run = run(&xosc(&init, "", &stop()));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.x, 50.0, 1e-9) && close(e.y, 1.75, 1e-9), "{e:?}");
    // Road heading 0 + 0.3, no half turn.
    assert!(dh(e.h, 0.3).abs() < 1e-9, "{e:?}");
    // The lane position on lane 1: the lane's direction π, then + 0.3.
    let t = at(&run, "Target", 0.0);
    assert!(close(t.x, 80.0, 1e-9) && dh(t.h, PI + 0.3).abs() < 1e-9, "{t:?}");
}

#[test]
fn a_road_position_with_a_relative_half_turn_faces_against_s() {
    let road = r#"<RoadPosition roadId="1" s="50" t="-1.75"><Orientation type="relative" h="3.141592653589793"/></RoadPosition>"#;
    let run = run(&xosc(&place("Ego", road), "", &stop()));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.y, -1.75, 1e-9) && dh(e.h, PI).abs() < 1e-9, "{e:?}");
}
