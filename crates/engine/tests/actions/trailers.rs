//! Trailers: a trailer named by its tow vehicle's model (TrailerRef) or connected by
//! ConnectTrailerAction is pulled so that its coupler sits on the tow vehicle's hitch; checked on
//! a straight road and against the closed-form steady state of a constant-radius turn; a towed
//! trailer ignores TeleportActions and a disconnected one drives on (checked against esmini on
//! fixtures).

use crate::common::*;

/// Hitch 1.2 m behind the tow vehicle's reference point; coupler 4 m ahead of the trailer's axle.
const HITCH: f64 = -1.2;
const COUPLER: f64 = 4.0;

fn vehicle(name: &str, category: &str, extra: &str) -> String {
    format!(
        r#"<ScenarioObject name="{name}"><Vehicle name="{name}" vehicleCategory="{category}">
  <Performance maxSpeed="70" maxAcceleration="200" maxDeceleration="200"/>
  <BoundingBox><Center x="1.5" y="0" z="0.9"/><Dimensions width="2.0" length="4.5" height="1.8"/></BoundingBox>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="3.1" positionZ="0.3"/>
  <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/></Axles>
  {extra}<Properties/></Vehicle></ScenarioObject>"#
    )
}

/// Entities: Car (with a hitch; towing `Trailer` from the start when `linked`) and Trailer.
fn scenario(linked: bool, road: bool, init: &str, stories: &str, stop: f64) -> String {
    let tow_extra = format!(r#"<TrailerHitch dx="{HITCH}"/>{}"#, if linked { r#"<Trailer><TrailerRef entityRef="Trailer"/></Trailer>"# } else { "" });
    let trailer_extra = format!(r#"<TrailerCoupler dx="{COUPLER}"/>"#);
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="test" author="osc2cr"/>
<CatalogLocations/>
<RoadNetwork>{}</RoadNetwork>
<Entities>{}{}</Entities>
<Storyboard>
<Init><Actions>{init}</Actions></Init>
{stories}
<StopTrigger><ConditionGroup>{}</ConditionGroup></StopTrigger>
</Storyboard>
</OpenSCENARIO>"#,
        if road { r#"<LogicFile filepath="straight.xodr"/>"# } else { "" },
        vehicle("Car", "car", &tow_extra),
        vehicle("Trailer", "trailer", &trailer_extra),
        sim_time(stop, "greaterThan", "none", 0.0)
    )
}

fn run_no_road(text: &str) -> engine::Run {
    engine::simulate(&scenario_of(text), None, &engine::Settings { step: 0.01, max_time: 60.0 }).expect("simulate")
}

fn world(entity: &str, x: f64, y: f64, h: f64) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><WorldPosition x="{x}" y="{y}" h="{h}"/></Position></TeleportAction></PrivateAction></Private>"#
    )
}

#[test]
fn trailer_behind_a_truck_driving_straight_stays_aligned_at_hitch_coupler_distance() {
    let init = format!("{}{}", teleport("Car", 50.0, -1), init_speed("Car", "step", "time", 0.0, 10.0));
    let run = run(&scenario(true, true, &init, "", 5.0));
    for t in [0.0, 1.0, 4.0] {
        let car = at(&run, "Car", t);
        let tr = at(&run, "Trailer", t);
        assert!(close(car.x, 50.0 + 10.0 * t, 1e-9), "car x {}", car.x);
        assert!(close(tr.x, car.x + HITCH - COUPLER, 1e-9), "t = {t}: trailer x {} car x {}", tr.x, car.x);
        assert!(close(tr.y, -1.75, 1e-9) && close(tr.h, 0.0, 1e-9), "trailer y {} h {}", tr.y, tr.h);
        assert!(close(tr.speed, 10.0, 1e-9));
    }
}

#[test]
fn articulation_in_a_constant_radius_turn_approaches_the_closed_form_steady_state() {
    // The car follows a circle of radius R (a clothoid with zero curvature rate) at 5 m/s.
    // Steady state: the hitch runs on radius √(R² + HITCH²) and lags the car's axle by
    // atan(|HITCH|/R); the trailer's axle runs on radius √(R_h² − COUPLER²) and lags the hitch by
    // atan(COUPLER/R_t). The articulation angle is the sum of the two lags.
    let r = 15.0;
    let len = 2.0 * std::f64::consts::PI * r * 1.5;
    let follow = format!(
        r#"<PrivateAction><RoutingAction><FollowTrajectoryAction><Trajectory closed="false" name="circle"><Shape><Clothoid curvature="{}" curvatureDot="0" length="{len}"><Position><WorldPosition x="0" y="0" h="0"/></Position></Clothoid></Shape></Trajectory><TimeReference><None/></TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#,
        1.0 / r
    );
    let init = format!(r#"{}<Private entityRef="Car">{}{follow}</Private>"#, world("Car", 0.0, 0.0, 0.0), speed_action("step", "time", 0.0, 5.0));
    let run = run_no_road(&scenario(true, false, &init, "", 40.0));
    let rh = (r * r + HITCH * HITCH).sqrt();
    let rt = (rh * rh - COUPLER * COUPLER).sqrt();
    let expected = (HITCH.abs() / r).atan() + (COUPLER / rt).atan();
    let articulation = |t: f64| {
        let d = at(&run, "Car", t).h - at(&run, "Trailer", t).h;
        d.sin().atan2(d.cos())
    };
    let late = articulation(35.0);
    assert!(close(late, expected, 5e-3), "articulation {late} vs steady state {expected}");
    // It approaches the steady state from straight (zero articulation).
    assert!(articulation(0.5) < late);
    // The coupler stays on the hitch.
    let (car, tr) = (at(&run, "Car", 35.0), at(&run, "Trailer", 35.0));
    let (hx, hy) = (car.x + HITCH * car.h.cos(), car.y + HITCH * car.h.sin());
    let (cx, cy) = (tr.x + COUPLER * tr.h.cos(), tr.y + COUPLER * tr.h.sin());
    assert!(close(hx, cx, 1e-9) && close(hy, cy, 1e-9));
    // The trailer's axle runs on radius R_t about the circle's centre (0, R).
    let rad = (tr.x * tr.x + (tr.y - r).powi(2)).sqrt();
    assert!(close(rad, rt, 5e-2), "trailer radius {rad} vs {rt}");
}

#[test]
fn connect_puts_the_coupler_on_the_hitch_and_disconnect_lets_the_trailer_roll_on() {
    // On lane -1 of the straight road: the trailer's coupler 2 m behind the hitch; Car drives
    // at 2 m/s from 1 s; connected at 0.5 s, disconnected at 3 s.
    let init = format!("{}{}", teleport("Car", 20.0, -1), teleport("Trailer", 20.0 + HITCH - COUPLER - 2.0, -1));
    let events = format!(
        "{}{}{}",
        event(
            "Connect",
            "parallel",
            r#"<PrivateAction><TrailerAction><ConnectTrailerAction trailerRef="Trailer"/></TrailerAction></PrivateAction>"#,
            &trigger(&sim_time(0.5, "greaterThan", "rising", 0.0))
        ),
        event("Go", "parallel", &speed_action("step", "time", 0.0, 2.0), &trigger(&sim_time(1.0, "greaterThan", "rising", 0.0))),
        event(
            "Disconnect",
            "parallel",
            r#"<PrivateAction><TrailerAction><DisconnectTrailerAction/></TrailerAction></PrivateAction>"#,
            &trigger(&sim_time(3.0, "greaterThan", "rising", 0.0))
        ),
    );
    let run = run(&scenario(false, true, &init, &story("Car", &events), 5.0));
    let before = at(&run, "Trailer", 0.4);
    assert!(close(before.x, 20.0 + HITCH - COUPLER - 2.0, 1e-9));
    let connected = at(&run, "Trailer", 0.7);
    assert!(close(connected.x, 20.0 + HITCH - COUPLER, 1e-9), "connected x {}", connected.x);
    let pulled = at(&run, "Trailer", 2.5);
    assert!(close(pulled.x, at(&run, "Car", 2.5).x + HITCH - COUPLER, 1e-9) && close(pulled.speed, 2.0, 1e-9));
    // Disconnected, it keeps its last speed and the default controller moves it on.
    let (a, b) = (at(&run, "Trailer", 3.5), at(&run, "Trailer", 4.5));
    assert!(close(b.x - a.x, 2.0, 1e-9) && close(b.speed, 2.0, 1e-12), "trailer {} -> {} at {}", a.x, b.x, b.speed);
    assert!(at(&run, "Car", 4.5).x > at(&run, "Car", 3.5).x + 1.9);
}

#[test]
fn a_disconnected_trailer_drives_on_at_its_last_speed_and_stops_at_the_road_end() {
    // esmini's Vehicle::DisconnectTrailer only drops the link: the trailer keeps the speed its
    // tow vehicle last set and ScenarioEngine::defaultController moves it along its lane, while
    // the car slows down; it stops at the road's end (s = 1000). Fixture
    // trailer_disconnected_drives_on.xosc (numbers from esmini 3.6.0's run of it).
    let run = crate::common::oracle::run_fixture_scenario("trailer_disconnected_drives_on.xosc", 20.0);
    crate::common::oracle::assert_esmini_pose_at(&run, "Trailer", 5.4, 960.35, -1.75, 0.0);
    let end = at(&run, "Trailer", 9.9);
    assert!(close(end.x, 1000.0, 1e-6) && close(end.speed, 0.0, 1e-12), "trailer at {} speed {}", end.x, end.speed);
    assert!(at(&run, "Car", 9.9).x < 980.0);
    crate::common::oracle::assert_matches_esmini("trailer_disconnected_drives_on.xosc", &run, 1e-3);
}

#[test]
fn a_towed_trailer_ignores_teleport_actions_and_is_pulled_from_where_it_was_made() {
    // esmini's TeleportAction::Start leaves a towed trailer alone ("position controlled by tow
    // vehicle"). TrailerA is connected to CarA in the Init before its own TeleportAction, so it
    // is still at the origin when the first pull puts its coupler on the hitch, on the line
    // from the hitch towards the origin; the story's teleport at 2 s changes nothing. TrailerB,
    // teleported before its connection, is pulled straight (fixture
    // trailer_teleported_while_towed.xosc; the numbers are esmini 3.6.0's run of it).
    let run = crate::common::oracle::run_fixture_scenario("trailer_teleported_while_towed.xosc", 20.0);
    crate::common::oracle::assert_esmini_pose_at(&run, "TrailerA", 0.0, 95.550510, -1.692443, 6.265475);
    crate::common::oracle::assert_esmini_pose_at(&run, "TrailerA", 2.5, 120.55, -1.749971, 6.283176);
    let b = at(&run, "TrailerB", 2.5);
    assert!(close(b.x, 204.45, 1e-9) && close(b.y, 1.75, 1e-9), "TrailerB at ({}, {})", b.x, b.y);
    crate::common::oracle::assert_matches_esmini("trailer_teleported_while_towed.xosc", &run, 1e-3);
}

#[test]
fn a_trailer_connected_to_a_second_vehicle_stays_on_the_first_ones_hitch() {
    // esmini's ConnectTrailerAction sets the trailer's coupler and the new tow vehicle's hitch
    // and clears neither side of the old link (Vehicle::ConnectTrailer). TrailerA, coupled at
    // 0.3 s to CarB, which has no hitch, is towed by nobody (Object::TowVehicle): the default
    // controller moves it along its lane and CarA, whose hitch still holds it, pulls it after.
    // TrailerC, coupled at 1 s to CarD (with a hitch, one lane over), is pulled by CarC and
    // then by CarD in every step. Fixture trailer_connected_to_a_second_vehicle.xosc (numbers
    // from esmini 3.6.0's run of it).
    let name = "trailer_connected_to_a_second_vehicle.xosc";
    let run = crate::common::oracle::run_fixture_scenario(name, 10.0);
    crate::common::oracle::assert_esmini_pose_at(&run, "TrailerA", 1.3, 108.55, -1.728, 6.276);
    crate::common::oracle::assert_esmini_pose_at(&run, "TrailerC", 1.3, 331.188, -4.753, 6.13);
    assert!(close(at(&run, "TrailerC", 1.3).speed, 12.0, 1e-12));
    assert!(run.warnings.iter().any(|w| w.message.contains("needs a TrailerCoupler and the tow vehicle a TrailerHitch")));
    crate::common::oracle::assert_matches_esmini(name, &run, 1e-3);
}
