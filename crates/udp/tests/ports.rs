//! Ports as esmini numbers them: a controller's `port` property, else the base port plus the
//! entity's esmini object id, the base port being the `basePort` of the last UDP driver read
//! (else 49950), or `ServeOptions::base_port`; each port serves its own entity only; a port
//! opens when its controller is activated; a port in use, or a property esmini refuses, stops
//! the run before it starts, saying which.

use crate::common::*;
use std::net::UdpSocket;
use udp::{serve, Error, Reason};

/// `two_cars.xosc` with these parameters; each car is put at x by XYH states (Car0 at x0 on
/// lane -1, Car1 at x1 on lane -2); the client sends Car1's object id to both ports at frame 5.
fn two_cars(params: &[(&str, String)], base_port: Option<u16>, x0: f64, x1: f64) -> (udp::Outcome, Lockstep) {
    let mut o = options(params, 0.2);
    o.base_port = base_port;
    let script = |id: u32, x: f64, y: f64| {
        (0..=20u32).map(|k| if k == 5 { xyh(1 - id, k, 0.0, 0.0, 0.0, 0.0, 0) } else { xyh(id, k, x, y, 0.0, 0.0, 0) }).collect::<Vec<_>>()
    };
    let mut client = Lockstep::one_each("Car0", script(0, x0, -1.75));
    let car1 = Lockstep::one_each("Car1", script(1, x1, -5.25));
    // one client for both cars
    client = Lockstep::new(vec![("Car0", client_frames(&client, "Car0")), ("Car1", client_frames(&car1, "Car1"))]);
    let outcome = serve(&fixture("two_cars.xosc"), &o, &mut client).expect("serves");
    (outcome, client)
}

fn client_frames(l: &Lockstep, name: &str) -> Vec<Vec<Vec<u8>>> {
    l.script(name)
}

fn port_of(client: &Lockstep, entity: &str) -> u16 {
    client.listening.iter().find(|l| l.entity == entity).map(|l| l.address.port()).unwrap_or_else(|| panic!("{entity} got no port"))
}

fn last_x(outcome: &udp::Outcome, entity: &str) -> f64 {
    outcome.entity(entity).and_then(|e| e.states.last()).map(|(_, s)| s.x).expect("states")
}

#[test]
fn the_base_port_plus_the_object_id_and_the_last_base_port_read_counts_for_all() {
    let base = free_port_pair();
    let (outcome, client) = two_cars(&[("BasePort", base.to_string()), ("ExecMode", "synchronous".into())], None, 70.0, 80.0);
    // Car1's controller sets the base port; Car0's (read before it) gets it too
    assert_eq!((port_of(&client, "Car0"), port_of(&client, "Car1")), (base, base + 1));
    assert!(client.listening.iter().all(|l| l.at_init && l.address.ip().is_loopback()));
    assert!(close(last_x(&outcome, "Car0"), 70.0, 1e-9) && close(last_x(&outcome, "Car1"), 80.0, 1e-9));
    assert_eq!(outcome.entity("Car1").map(|e| e.object_id), Some(1));
    // each port serves its own car: the other car's id is turned away, saying whose port it is
    assert_eq!(client.rejections.len(), 2);
    let to_car1 = client.rejections.iter().find(|r| r.entity == "Car1").expect("a rejection on Car1's port");
    assert_eq!(to_car1.reason, Reason::ObjectId { got: 0, expected: 1 });
    assert!(to_car1.to_string().contains(&format!("objectId 0, expected 1: port {} serves `Car1`, esmini object id 1", base + 1)), "{to_car1}");
}

#[test]
fn a_chosen_base_port_and_a_port_property_take_precedence() {
    let base = free_port_pair();
    let own = free_port();
    let (_, client) = two_cars(&[("BasePort", "1".into()), ("Port1", own.to_string()), ("ExecMode", "asynchronous".into())], Some(base), 70.0, 80.0);
    assert_eq!((port_of(&client, "Car0"), port_of(&client, "Car1")), (base, own));
}

#[test]
fn a_port_opens_when_its_controller_is_activated() {
    let port = free_port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into()), ("ActivateAt", "0.5".into())], 1.0);
    let mut client = Lockstep::one_each("Ego", (0..=60u32).map(|k| xyh(0, k, 100.0 + k as f64, -1.75, 0.0, 0.0, 0)).collect());
    let outcome = serve(&fixture("late_activation.xosc"), &o, &mut client).expect("serves");
    // the storyboard's frame at 0.5 s activates it: the port opens after that step
    assert_eq!(client.listening.len(), 1);
    assert!(!client.listening[0].at_init);
    assert_eq!(client.opened_after, [51]);
    let ego = outcome.entity("Ego").expect("served");
    let (t0, s0) = ego.states.first().cloned().expect("states");
    // until then the scenario drove it at 10 m/s; in the activation step it stays, speed 0
    assert!(close(t0, 0.51, 1e-9) && close(s0.x, 55.0, 1e-9) && s0.speed == 0.0, "{t0}: {s0:?}");
    // then frame k drives the k-th step after
    assert!(close(at(&outcome, "Ego", 0.52).x, 100.0, 1e-9) && close(at(&outcome, "Ego", 1.0).x, 148.0, 1e-9));
}

#[test]
fn a_port_in_use_or_a_property_esmini_refuses_stops_the_run_before_it_starts() {
    let taken = UdpSocket::bind("127.0.0.1:0").expect("a socket");
    let port = taken.local_addr().expect("address").port();
    let o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into())], 1.0);
    match serve(&fixture("one_car.xosc"), &o, &mut udp::Silent) {
        Err(Error::Bind(m)) => assert!(m.contains(&format!("cannot listen on 127.0.0.1:{port} for `Ego`")), "{m}"),
        other => panic!("expected a bind error, got {other:?}"),
    }
    let o = options(&[("ExecMode", "lockstep".into())], 1.0);
    match serve(&fixture("one_car.xosc"), &o, &mut udp::Silent) {
        Err(Error::Setup(m)) => {
            assert!(m.contains("one_car.xosc:") && m.contains(r#"execMode "lockstep" is neither "asynchronous" nor "synchronous""#), "{m}")
        }
        other => panic!("expected a setup error, got {other:?}"),
    }
    let o = options(&[("Port", "70000".into())], 1.0);
    assert!(matches!(serve(&fixture("one_car.xosc"), &o, &mut udp::Silent), Err(Error::Setup(m)) if m.contains(r#"port "70000" is outside 0..=65535"#)));
}

#[test]
fn esminis_controller_catalog_entry_is_served_with_its_port_and_base_port_parameters() {
    let Some(shared) = testkit::shared_dir() else { return };
    let catalogs = shared.join("corpus/esmini/xosc/Catalogs");
    // esmini's two_cars_in_open_space.xosc, on the straight road: Car1's assignment sets the
    // base port (the catalog passes BasePort as the `basePort` property)
    let base = free_port_pair();
    let car = std::fs::read_to_string(fixture("two_cars.xosc")).expect("fixture");
    let vehicle = &car[car.find("<Vehicle ").expect("a vehicle")..car.find("</Vehicle>").expect("its end") + "</Vehicle>".len()];
    let controller = |assignments: &str| {
        format!(
            r#"<ObjectController><CatalogReference catalogName="ControllerCatalog" entryName="UDPDriverController"><ParameterAssignments>{assignments}</ParameterAssignments></CatalogReference></ObjectController>"#
        )
    };
    let init = |name: &str, lane: i32| {
        format!(
            r#"<Private entityRef="{name}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="50"/></Position></TeleportAction></PrivateAction><PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="true"/></ControllerAction></PrivateAction></Private>"#
        )
    };
    let text = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" description="esmini's UDP driver catalog entry" author="osc2cr"/>
<ParameterDeclarations/>
<CatalogLocations><ControllerCatalog><Directory path="{}"/></ControllerCatalog></CatalogLocations>
<RoadNetwork><LogicFile filepath="{}"/></RoadNetwork>
<Entities>
<ScenarioObject name="Car0">{vehicle}{}</ScenarioObject>
<ScenarioObject name="Car1">{vehicle}{}</ScenarioObject>
</Entities>
<Storyboard><Init><Actions>{}{}</Actions></Init><StopTrigger/></Storyboard>
</OpenSCENARIO>"#,
        catalogs.join("Controllers").display(),
        fixture("straight.xodr").display(),
        controller(r#"<ParameterAssignment parameterRef="Port" value="0"/><ParameterAssignment parameterRef="ExecMode" value="synchronous"/>"#),
        controller(&format!(
            r#"<ParameterAssignment parameterRef="Port" value="0"/><ParameterAssignment parameterRef="BasePort" value="{base}"/><ParameterAssignment parameterRef="ExecMode" value="synchronous"/>"#
        )),
        init("Car0", -1),
        init("Car1", -2),
    );
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("udp-catalog");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("two_cars_catalog.xosc");
    std::fs::write(&path, text).expect("written");
    let mut client = Lockstep::new(vec![
        ("Car0", (0..=10u32).map(|k| vec![xyh(0, k, 70.0, -1.75, 0.0, 0.0, 0)]).collect()),
        ("Car1", (0..=10u32).map(|k| vec![xyh(1, k, 80.0, -5.25, 0.0, 0.0, 0)]).collect()),
    ]);
    let mut o = options(&[], 0.1);
    o.convert.parameters.clear();
    let outcome = serve(&path, &o, &mut client).expect("serves");
    assert_eq!((port_of(&client, "Car0"), port_of(&client, "Car1")), (base, base + 1));
    assert!(client.listening.iter().all(|l| l.exec == udp::ExecMode::Synchronous));
    assert!(client.rejections.is_empty(), "{:?}", client.rejections);
    assert!(close(last_x(&outcome, "Car0"), 70.0, 1e-9) && close(last_x(&outcome, "Car1"), 80.0, 1e-9));
}
