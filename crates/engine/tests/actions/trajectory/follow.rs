//! FollowTrajectoryAction and TrajectoryPosition on the straight fixture road (lane -1's centre
//! is y = -1.75), checked against hand computations.

use crate::common::*;

fn world(x: f64, y: f64) -> String {
    format!(r#"<Position><WorldPosition x="{x}" y="{y}" z="0" h="0"/></Position>"#)
}

fn vertex(time: Option<f64>, x: f64, y: f64) -> String {
    match time {
        Some(t) => format!(r#"<Vertex time="{t}">{}</Vertex>"#, world(x, y)),
        None => format!("<Vertex>{}</Vertex>", world(x, y)),
    }
}

fn follow(shape: &str, timing: &str, mode: &str) -> String {
    format!(
        r#"<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="T" closed="false"><ParameterDeclarations/><Shape>{shape}</Shape></Trajectory></TrajectoryRef><TimeReference>{timing}</TimeReference><TrajectoryFollowingMode followingMode="{mode}"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#
    )
}

const RELATIVE: &str = r#"<Timing domainAbsoluteRelative="relative" scale="1" offset="0"/>"#;

fn init_with(entity: &str, actions: &str) -> String {
    format!(r#"{}<Private entityRef="{entity}">{actions}</Private>"#, teleport(entity, 10.0, -1))
}

#[test]
fn timed_polyline_in_position_mode_moves_at_each_segment_mean_speed() {
    // 20 m in 2 s, then 40 m in 2 s: 10 m/s, then 20 m/s; after the last stamp the default
    // controller drives on at 20 m/s.
    let shape = format!("<Polyline>{}{}{}</Polyline>", vertex(Some(0.0), 10.0, -1.75), vertex(Some(2.0), 30.0, -1.75), vertex(Some(4.0), 70.0, -1.75));
    let run = run(&xosc(&init_with("Ego", &follow(&shape, RELATIVE, "position")), "", &stop_at(6.0)));
    let e1 = at(&run, "Ego", 1.0);
    assert!(close(e1.x, 20.0, 1e-6) && close(e1.y, -1.75, 1e-6) && close(e1.speed, 10.0, 1e-6), "{e1:?}");
    let e3 = at(&run, "Ego", 3.0);
    assert!(close(e3.x, 50.0, 1e-6) && close(e3.speed, 20.0, 1e-6), "{e3:?}");
    assert!(close(at(&run, "Ego", 5.0).x, 90.0, 1e-6));
}

#[test]
fn timed_polyline_in_follow_mode_accelerates_uniformly_per_segment() {
    // esmini 3.6.0 (PolyLineShape::CalculatePolyLine, follow mode): the speed starts at the
    // entity's, 0 here. First segment: 20 m in 2 s from rest, a = 10 m/s², 20 m/s at the
    // stamp. Second: 5 m in 1 s from 20 m/s would end at −10 m/s, so esmini brakes to a stop
    // over the 5 m instead (a = −20²/(2·5) = −40 m/s²), arriving at 2.5 s, and waits there.
    let shape = format!("<Polyline>{}{}{}</Polyline>", vertex(Some(0.0), 10.0, -1.75), vertex(Some(2.0), 30.0, -1.75), vertex(Some(3.0), 35.0, -1.75));
    let run = run(&xosc(&init_with("Ego", &follow(&shape, RELATIVE, "follow")), "", &stop_at(5.0)));
    // s(1) = 10·1²/2 = 5; esmini's speed is the last step's mean, 9.95 m/s.
    let e1 = at(&run, "Ego", 1.0);
    assert!(close(e1.x, 15.0, 1e-6) && close(e1.speed, 9.95, 1e-6), "{e1:?}");
    assert!(close(at(&run, "Ego", 2.0).x, 30.0, 1e-6));
    let e = at(&run, "Ego", 2.5);
    assert!(close(e.x, 35.0, 1e-6) && close(e.speed, 0.2, 1e-6), "{e:?}");
    assert!(close(at(&run, "Ego", 2.75).speed, 0.0, 1e-9));
}

#[test]
fn untimed_clothoid_arc_from_the_current_pose_at_the_entity_speed() {
    // Constant curvature 0.02 from (10, −1.75) heading 0 at 10 m/s: after 20 m the heading is
    // 0.4 and the point is (10 + sin 0.4 / 0.02, −1.75 + (1 − cos 0.4) / 0.02).
    let shape = r#"<Clothoid curvature="0.02" curvaturePrime="0" length="50"/>"#;
    let actions = format!("{}{}", speed_action("step", "time", 0.0, 10.0), follow(shape, "<None/>", "position"));
    let run = run(&xosc(&init_with("Ego", &actions), "", &stop_at(3.0)));
    let e = at(&run, "Ego", 2.0);
    let (x, y) = (10.0 + 0.4f64.sin() / 0.02, -1.75 + (1.0 - 0.4f64.cos()) / 0.02);
    assert!(close(e.x, x, 1e-4) && close(e.y, y, 1e-4) && close(e.h, 0.4, 1e-4), "{e:?} vs ({x}, {y})");
    assert!(close(e.speed, 10.0, 1e-9));
}

#[test]
fn untimed_polyline_ends_at_its_last_vertex_and_the_entity_drives_on() {
    let shape = format!("<Polyline>{}{}</Polyline>", vertex(None, 10.0, -1.75), vertex(None, 30.0, -1.75));
    let actions = format!("{}{}", speed_action("step", "time", 0.0, 10.0), follow(&shape, "<None/>", "position"));
    let text = xosc(&init_with("Ego", &actions), "", &stop_at(4.0));
    let run = run(&text);
    assert!(close(at(&run, "Ego", 1.0).x, 20.0, 1e-6));
    // The path ends after 20 m (t = 2 s); the remaining steps follow the lane at 10 m/s.
    assert!(close(at(&run, "Ego", 3.0).x, 40.0, 1e-6));
    assert!(run.trace.events.iter().any(|e| e.element.contains("FollowTrajectoryAction") && e.to == "complete"));
}

#[test]
fn trajectory_position_is_s_along_and_t_left_of_the_path() {
    let traj = format!(
        r#"<Trajectory name="P" closed="false"><ParameterDeclarations/><Shape><Polyline>{}{}</Polyline></Shape></Trajectory>"#,
        vertex(None, 0.0, 0.0),
        vertex(None, 100.0, 0.0)
    );
    let init = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><TrajectoryPosition s="30" t="-1.75"><TrajectoryRef>{traj}</TrajectoryRef></TrajectoryPosition></Position></TeleportAction></PrivateAction></Private>"#
    );
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.x, 30.0, 1e-9) && close(e.y, -1.75, 1e-9) && close(e.h, 0.0, 1e-9), "{e:?}");
    assert_eq!(e.road.map(|r| r.lane_id), Some(-1));
}
