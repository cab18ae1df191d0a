//! What the OpenSCENARIO document says, feature by feature, on a scenario built in code
//! (`synthetic.rs`): entities of their kind and shape with the reference point at the box
//! centre, a vertex per state with absolute timing, obstacles added and deleted at the right
//! times, the light's controller rotated by its offset, the goal as discs, the 1.0 form, the
//! external ego, the carried planning problem, and the same bytes for the same input.

use std::f64::consts::SQRT_2;

use commonroad::{GoalPosition, LaneletId, PlacedRectangle, Point, Polygon, Rectangle};
use roxmltree::{Document, Node};

use crate::synthetic::{circle, scenario, source};

fn export_text(goal: GoalPosition, options: &export::ExportOptions) -> (String, Vec<String>) {
    let e = export::export(&source(scenario(goal)), "", options).expect("exports");
    (e.xosc, e.warnings)
}

fn default_text() -> String {
    export_text(circle(60.0, 1.75, 3.0), &export::ExportOptions::default()).0
}

fn named<'a, 'i>(doc: &'a Document<'i>, tag: &str, name: &str) -> Node<'a, 'i> {
    doc.descendants().find(|n| n.has_tag_name(tag) && n.attribute("name") == Some(name)).unwrap_or_else(|| panic!("<{tag} name={name:?}>"))
}

fn child<'a, 'i>(n: Node<'a, 'i>, tag: &str) -> Node<'a, 'i> {
    n.descendants().find(|c| c.has_tag_name(tag)).unwrap_or_else(|| panic!("<{tag}> below <{}>", n.tag_name().name()))
}

fn f(n: Node, attr: &str) -> f64 {
    n.attribute(attr).and_then(|v| v.parse().ok()).unwrap_or_else(|| panic!("{attr} of <{}>", n.tag_name().name()))
}

/// (kind element, category, length, width, centre x, centre y) of a scenario object.
fn kind(doc: &Document, name: &str) -> (String, String, f64, f64, f64, f64) {
    let so = named(doc, "ScenarioObject", name);
    let object = so.children().find(|c| c.is_element() && c.tag_name().name() != "ObjectController").expect("entity object");
    let category = ["vehicleCategory", "pedestrianCategory", "miscObjectCategory"].iter().find_map(|a| object.attribute(*a)).unwrap_or("").to_string();
    let (dim, centre) = (child(object, "Dimensions"), child(object, "Center"));
    (object.tag_name().name().to_string(), category, f(dim, "length"), f(dim, "width"), f(centre, "x"), f(centre, "y"))
}

fn condition_value(doc: &Document, condition: &str) -> f64 {
    f(child(named(doc, "Condition", condition), "SimulationTimeCondition"), "value")
}

#[test]
fn entities_are_of_their_kind_and_shape_with_the_reference_point_at_the_box_centre() {
    let text = default_text();
    let doc = Document::parse(&text).expect("xml");
    let k = |n: &str| kind(&doc, n);
    assert_eq!(k("Ego").0, "Vehicle");
    assert_eq!(k("car_4"), ("Vehicle".into(), "car".into(), 4.5, 1.8, 0.0, 0.0));
    assert_eq!(k("truck_5"), ("Vehicle".into(), "truck".into(), 9.0, 2.5, 0.0, 0.0));
    let p = k("pedestrian_6");
    assert_eq!((p.0.as_str(), p.1.as_str()), ("Pedestrian", "pedestrian"));
    assert!((p.2 - 0.4 * SQRT_2).abs() < 1e-12 && (p.3 - 0.4 * SQRT_2).abs() < 1e-12, "the square whose half diagonal is the radius");
    assert_eq!(k("parkedVehicle_7"), ("Vehicle".into(), "car".into(), 4.0, 1.8, 0.0, 0.0));
    assert_eq!(k("constructionZone_8"), ("MiscObject".into(), "patch".into(), 6.0, 2.0, 0.0, 0.0));
    assert_eq!(k("building_9"), ("MiscObject".into(), "building".into(), 20.0, 10.0, 0.0, 0.0));
    // the polygon's box centre (3, 1) in its frame is where it is placed
    let private = doc.descendants().find(|n| n.has_tag_name("Private") && n.attribute("entityRef") == Some("constructionZone_8")).expect("placed");
    let w = child(private, "WorldPosition");
    assert_eq!((f(w, "x"), f(w, "y")), (243.0, -3.0));
    let building = doc.descendants().find(|n| n.has_tag_name("Private") && n.attribute("entityRef") == Some("building_9")).expect("placed");
    let w = child(building, "WorldPosition");
    assert_eq!((f(w, "x"), f(w, "y"), f(w, "h")), (150.0, 30.0, 0.3));
    // the CommonRoad type and id travel as properties
    assert!(text.contains(r#"<Property name="osc2cr:commonRoadType" value="staticObstacle/parkedVehicle"/>"#), "type property");
    assert!(text.contains(r#"<Property name="osc2cr:commonRoadId" value="7"/>"#), "id property");
}

#[test]
fn a_trajectory_has_a_vertex_per_state_with_absolute_timing() {
    let text = default_text();
    let doc = Document::parse(&text).expect("xml");
    let t = named(&doc, "Trajectory", "car_4_trajectory");
    let vertices: Vec<Node> = t.descendants().filter(|n| n.has_tag_name("Vertex")).collect();
    assert_eq!(vertices.len(), 101, "states 0..=100");
    assert_eq!(vertices[0].attribute("time"), Some("0.0"));
    assert_eq!(vertices[3].attribute("time"), Some("0.3"), "k·dt as CommonRoad writes decimals");
    assert_eq!(vertices[100].attribute("time"), Some("10.0"));
    let w = child(vertices[10], "WorldPosition");
    assert!((f(w, "x") - 32.0).abs() < 1e-9 && f(w, "y") == 1.75 && f(w, "h") == 0.0);
    let action = t.ancestors().find(|n| n.has_tag_name("FollowTrajectoryAction")).expect("action");
    let timing = child(action, "Timing");
    assert_eq!((timing.attribute("domainAbsoluteRelative"), f(timing, "scale"), f(timing, "offset")), (Some("absolute"), 1.0, 0.0));
    assert_eq!(child(action, "TrajectoryFollowingMode").attribute("followingMode"), Some("position"));
    assert!(t.parent().is_some_and(|p| p.has_tag_name("TrajectoryRef")), "1.3 wraps the trajectory in TrajectoryRef");
}

#[test]
fn obstacles_are_added_and_deleted_when_they_appear_and_leave() {
    let text = default_text();
    let doc = Document::parse(&text).expect("xml");
    let has_init = |name: &str| doc.descendants().any(|n| n.has_tag_name("Private") && n.attribute("entityRef") == Some(name));
    assert!(has_init("car_4") && has_init("Ego") && has_init("parkedVehicle_7"));
    assert!(!has_init("truck_5") && !has_init("pedestrian_6"), "added by events, not by the Init");
    // first state at step k: added when the time passes (k − 1)·dt, with a margin of dt/1000,
    // never at time 0 itself (esmini's Init frame fires events too)
    assert_eq!(condition_value(&doc, "truck_5_appears_time"), 0.0001);
    assert_eq!(condition_value(&doc, "pedestrian_6_appears_time"), 0.3999);
    // last state at step k (before the end): deleted when the time passes k·dt
    assert_eq!(condition_value(&doc, "truck_5_leaves_time"), 5.9999);
    assert_eq!(condition_value(&doc, "pedestrian_6_leaves_time"), 3.9999);
    assert!(!text.contains("car_4_leaves"), "the car is there to the end");
    // added at its first state
    let add = child(named(&doc, "Action", "pedestrian_6_add"), "WorldPosition");
    assert_eq!((f(add, "x"), f(add, "y")), (100.0, 8.0));
    // the run ends at the last state or goal time: step 100
    assert_eq!(condition_value(&doc, "time_is_up"), 9.9999);
}

#[test]
fn a_light_cycle_becomes_a_controller_rotated_by_its_offset() {
    let text = default_text();
    let doc = Document::parse(&text).expect("xml");
    let c = named(&doc, "TrafficSignalController", "light_3");
    let phases: Vec<(f64, String, String)> = c
        .children()
        .filter(|n| n.has_tag_name("Phase"))
        .map(|p| {
            let s = child(p, "TrafficSignalState");
            (f(p, "duration"), s.attribute("state").unwrap_or("").to_string(), s.attribute("trafficSignalId").unwrap_or("").to_string())
        })
        .collect();
    // offset 12 of 80: at time 0 the cycle is at 68, 7 steps into green
    let want = [(0.7, "off;off;on"), (0.5, "off;on;off"), (3.0, "on;off;off"), (0.5, "on;on;off"), (3.3, "off;off;on")];
    assert_eq!(phases.len(), want.len(), "{phases:?}");
    for ((d, state, id), (wd, ws)) in phases.iter().zip(want) {
        assert!((d - wd).abs() < 1e-9 && state == ws && id == "3", "{phases:?}");
    }
}

#[test]
fn the_goal_is_said_with_discs_inside_its_region() {
    let o = export::ExportOptions::default();
    // a circle is itself: one group, the exact radius
    let (text, w) = export_text(circle(60.0, 1.75, 3.0), &o);
    let doc = Document::parse(&text).expect("xml");
    let event = named(&doc, "Event", "Ego_GoalReached");
    let groups: Vec<Node> = event.descendants().filter(|n| n.has_tag_name("ConditionGroup")).collect();
    assert_eq!(groups.len(), 1);
    let d = child(groups[0], "DistanceCondition");
    assert_eq!((f(d, "value"), d.attribute("relativeDistanceType"), d.attribute("freespace")), (3.0, Some("euclidianDistance"), Some("false")));
    assert!(child(groups[0], "AngleCondition").attribute("angleTolerance") == Some("0.5"));
    assert!(!w.iter().any(|w| w.contains("disc")), "{w:?}");
    assert!(text.contains("Ego_goal_reached") && text.contains("<VariableDeclaration name=\"Ego_goal_reached\""));
    // a 50 × 10 rectangle: 9 discs of radius 5, a warning
    let r = GoalPosition::Rectangles(vec![PlacedRectangle {
        rectangle: Rectangle::new(50.0, 10.0).expect("box"),
        center: Point::new(100.0, 1.75),
        orientation: 0.0,
    }]);
    let (text, w) = export_text(r, &o);
    let doc = Document::parse(&text).expect("xml");
    let groups = named(&doc, "Event", "Ego_GoalReached").descendants().filter(|n| n.has_tag_name("ConditionGroup")).count();
    assert_eq!(groups, 9);
    assert!(w.iter().any(|w| w.contains("9 disc(s) inside it")), "{w:?}");
    // a lanelet: discs along its centre line, as wide as it is
    let (text, _) = export_text(GoalPosition::Lanelets(vec![LaneletId::new(1).expect("id")]), &o);
    let doc = Document::parse(&text).expect("xml");
    let discs: Vec<f64> =
        named(&doc, "Event", "Ego_GoalReached").descendants().filter(|n| n.has_tag_name("DistanceCondition")).map(|d| f(d, "value")).collect();
    assert!(discs.len() > 10 && discs.iter().all(|r| (r - 1.75).abs() < 1e-9), "{discs:?}");
    // a polygon: no condition, a warning; the run ends by time
    let p = GoalPosition::Polygons(vec![Polygon::new(vec![Point::new(0.0, 0.0), Point::new(5.0, 0.0), Point::new(5.0, 5.0)]).expect("polygon")]);
    let (text, w) = export_text(p, &o);
    assert!(!text.contains("Ego_GoalReached"));
    assert!(w.iter().any(|w| w.contains("polygon goal region")), "{w:?}");
    // reaching the goal ends the run, unless --play-to-end
    let stop = |text: &str| text[text.find("<StopTrigger>").expect("stop trigger")..].contains("StoryboardElementStateCondition");
    assert!(stop(&default_text()));
    let (text, _) = export_text(circle(60.0, 1.75, 3.0), &export::ExportOptions { play_to_end: true, ..Default::default() });
    assert!(!stop(&text) && text.contains("Ego_GoalReached"), "the goal is still an event");
}

#[test]
fn osc_1_0_writes_only_1_0_constructs() {
    let o = export::ExportOptions { osc: export::OscVersion::V1_0, ego_controller: export::EgoController::External, play_to_end: false };
    let (text, w) = export_text(circle(60.0, 1.75, 3.0), &o);
    let doc = Document::parse(&text).expect("xml");
    assert_eq!(child(doc.root_element(), "FileHeader").attribute("revMinor"), Some("0"));
    for absent in [
        "TrajectoryRef",
        "VariableDeclarations",
        "VariableAction",
        "DistanceCondition",
        "AngleCondition",
        "<ControllerAction",
        "greaterOrEqual",
        "mass=\"1500\"",
    ] {
        assert!(!text.contains(absent), "1.0 has no {absent}");
    }
    for present in
        ["ReachPositionCondition", "<ParameterDeclaration name=\"Ego_goal_reached\" parameterType=\"boolean\"", "ParameterAction", "model=\"pedestrian\""]
    {
        assert!(text.contains(present), "1.0 writes {present}");
    }
    let activate = doc.descendants().find(|n| n.has_tag_name("ActivateControllerAction")).expect("activation");
    assert!(activate.parent().is_some_and(|p| p.has_tag_name("PrivateAction")), "directly under PrivateAction in 1.0");
    assert!(w.iter().any(|w| w.contains("1.0 has no heading condition")), "{w:?}");
}

#[test]
fn an_external_ego_gets_esminis_external_controller() {
    let o = export::ExportOptions { ego_controller: export::EgoController::External, ..Default::default() };
    let (text, _) = export_text(circle(60.0, 1.75, 3.0), &o);
    let doc = Document::parse(&text).expect("xml");
    let ego = named(&doc, "ScenarioObject", "Ego");
    assert_eq!(child(ego, "Controller").attribute("name"), Some("ExternalController"));
    let activate = doc.descendants().find(|n| n.has_tag_name("ActivateControllerAction")).expect("activation");
    assert!(activate.ancestors().any(|a| a.has_tag_name("Init")) && activate.parent().is_some_and(|p| p.has_tag_name("ControllerAction")));
    assert!(!default_text().contains("ExternalController"));
}

#[test]
fn the_planning_problem_travels_unchanged_in_the_egos_property() {
    assert_eq!(export::PLANNING_PROBLEM_PROPERTY, convert::PLANNING_PROBLEM_PROPERTY, "the writer and the forward reader agree");
    let b = scenario(GoalPosition::Lanelets(vec![LaneletId::new(1).expect("id")]));
    let problem = b.problems.problems[0].clone();
    let lanelet = b.scenario.network.lanelets[0].clone();
    let text = export::export(&source(b), "", &export::ExportOptions::default()).expect("exports").xosc;
    let doc = Document::parse(&text).expect("xml");
    let carried = doc.descendants().find(|n| n.has_tag_name("Property") && n.attribute("name") == Some(export::PLANNING_PROBLEM_PROPERTY)).expect("carried");
    let back = commonroad::xml::read_planning_problem_str(carried.attribute("value").expect("value"), std::path::Path::new("property")).expect("reads");
    assert_eq!(back.problem, problem);
    assert_eq!(back.lanelets, vec![lanelet], "the goal's lanelet travels with it");
    assert!(named(&doc, "ScenarioObject", "Ego").ancestors().any(|a| a.has_tag_name("Entities")));
}

#[test]
fn the_same_scenario_gives_the_same_bytes() {
    let a = export::export(&source(scenario(circle(60.0, 1.75, 3.0))), "maps/", &export::ExportOptions::default()).expect("exports");
    let b = export::export(&source(scenario(circle(60.0, 1.75, 3.0))), "maps/", &export::ExportOptions::default()).expect("exports");
    assert_eq!(a.xosc, b.xosc);
    let (ma, mb) = (a.map.expect("map"), b.map.expect("map"));
    assert_eq!((ma.file_name.as_str(), ma.xodr.as_str()), (mb.file_name.as_str(), mb.xodr.as_str()));
    assert!(ma.file_name.starts_with("DEU_") && ma.file_name.ends_with(".xodr") && ma.file_name.len() == "DEU_".len() + 16 + ".xodr".len());
    assert!(a.xosc.contains(&format!("<LogicFile filepath=\"maps/{}\"/>", ma.file_name)));
    // another network, another name
    let mut other = scenario(circle(60.0, 1.75, 3.0));
    other.scenario.network.lanelets.pop();
    other.scenario.network.lanelets[0].adjacent_left = None;
    let c = export::export(&source(other), "", &export::ExportOptions::default()).expect("exports");
    assert_ne!(c.map.expect("map").file_name, ma.file_name);
}

#[test]
fn the_2024_files_export_as_the_xml_does() {
    let Some(shared) = testkit::shared_dir() else { return };
    let dir = crate::common::fresh_dir("protobuf-input");
    let mut compared = 0;
    for f in testkit::files_with_ext(&shared.join("commonroad-scenarios"), "xml") {
        let Ok(xml_source) = export::read_source(&f) else { continue };
        let Ok(files) = commonroad::protobuf::write(&xml_source.scenario, &xml_source.problems) else { continue };
        let stem = export::scenario_name(&f);
        let sc = dir.join(commonroad::protobuf::scenario_file_name(&stem));
        std::fs::write(dir.join(files.map.file_name()), &files.map.bytes).expect("map");
        std::fs::write(&sc, &files.scenario).expect("scenario");
        std::fs::write(dir.join(commonroad::protobuf::dynamic_file_name(&stem)), &files.dynamic).expect("dynamic");
        let pb_source = export::read_source(&sc).expect("the 2024 files read");
        let o = export::ExportOptions::default();
        // what 2024 cannot say: the map's name differs if its network does; a missing initial
        // acceleration is written as 0
        let zero = "&lt;acceleration&gt;&lt;exact&gt;0.0&lt;/exact&gt;&lt;/acceleration&gt;";
        let strip = |t: String| t.replace(zero, "").lines().filter(|l| !l.contains("<LogicFile")).collect::<Vec<_>>().join("\n");
        let a = strip(export::export(&xml_source, "", &o).expect("exports").xosc);
        let b = strip(export::export(&pb_source, "", &o).expect("exports").xosc);
        assert_eq!(a, b, "{}: the 2024 files export as the XML", f.display());
        compared += 1;
    }
    assert!(compared >= 15, "{compared}");
}
