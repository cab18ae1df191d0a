//! The written XML against the XSD itself: element order of every `xs:sequence` we write,
//! enumeration spellings, lexical form of numbers, determinism, writer errors.

use crate::common;

use std::collections::BTreeMap;

use commonroad::xml::{write_map, write_scenario};
use commonroad::Error;
use commonroad::*;
use roxmltree::{Document, Node};

const XS: &str = "http://www.w3.org/2001/XMLSchema";

fn xsd_texts() -> Option<Vec<String>> {
    let shared = testkit::shared_dir()?;
    let mut v = Vec::new();
    for f in ["XML_commonRoad_XSD_2020a.commonroad-io-2024.3.xsd", "XML_commonRoad_XSD_2020a.commonroad-io-2026.1.xsd"] {
        v.push(std::fs::read_to_string(shared.join("tools/xsd").join(f)).unwrap());
    }
    Some(v)
}

fn is_xs(n: &Node, name: &str) -> bool {
    n.is_element() && n.tag_name().namespace() == Some(XS) && n.tag_name().name() == name
}

/// Names of the `xs:element`s of a complex type's content model, in declaration order,
/// without descending into nested anonymous complex types.
fn sequence_names(ct: Node) -> Vec<String> {
    fn walk(n: Node, out: &mut Vec<String>) {
        for c in n.children().filter(Node::is_element) {
            if is_xs(&c, "element") {
                out.push(c.attribute("name").unwrap().to_string());
            } else if !is_xs(&c, "complexType") {
                walk(c, out);
            }
        }
    }
    let mut out = Vec::new();
    walk(ct, &mut out);
    out
}

fn named<'a>(doc: &'a Document, kind: &str, name: &str) -> Node<'a, 'a> {
    doc.root_element().children().find(|n| is_xs(n, kind) && n.attribute("name") == Some(name)).unwrap_or_else(|| panic!("{kind} {name} not in XSD"))
}

fn enumeration(doc: &Document, simple_type: &str) -> Vec<String> {
    named(doc, "simpleType", simple_type).descendants().filter(|n| is_xs(n, "enumeration")).map(|n| n.attribute("value").unwrap().to_string()).collect()
}

fn written() -> String {
    let m = common::minimal();
    String::from_utf8(write_scenario(&m.scenario, &m.problems).unwrap()).unwrap()
}

/// Checks that the children of every element named `tag` appear in the order of `order`.
fn assert_children_in_order(doc: &Document, tag: &str, order: &[String]) -> usize {
    let mut seen = 0;
    for n in doc.descendants().filter(|n| n.has_tag_name(tag)) {
        seen += 1;
        let mut last = 0;
        for c in n.children().filter(Node::is_element) {
            let name = c.tag_name().name();
            let i = order.iter().position(|o| o == name).unwrap_or_else(|| panic!("<{name}> not allowed in <{tag}>"));
            assert!(i >= last, "<{name}> after <{}> in <{tag}>", order[last]);
            last = i;
        }
    }
    seen
}

#[test]
fn every_sequence_is_written_in_xsd_order() {
    let Some(xsds) = xsd_texts() else { return };
    let out = written();
    let ours = Document::parse(&out).unwrap();
    for xsd in &xsds {
        let x = Document::parse(xsd).unwrap();
        let root = x.root_element().children().find(|n| is_xs(n, "element") && n.attribute("name") == Some("commonRoad")).unwrap();
        let root_order = sequence_names(root.children().find(|n| is_xs(n, "complexType")).unwrap());
        assert_eq!(assert_children_in_order(&ours, "commonRoad", &root_order), 1);
        let pairs: &[(&str, &str)] = &[
            ("location", "location"),
            ("lanelet", "lanelet"),
            ("leftBound", "bound"),
            ("rightBound", "bound"),
            ("stopLine", "stopLine"),
            ("point", "point"),
            ("trafficSign", "trafficSign"),
            ("trafficLight", "trafficLight"),
            ("cycle", "trafficLightCycle"),
            ("cycleElement", "trafficCycleElement"),
            ("staticObstacle", "staticObstacle"),
            ("dynamicObstacle", "dynamicObstacle"),
            ("planningProblem", "planningProblem"),
            ("rectangle", "rectangle"),
        ];
        for (tag, ty) in pairs {
            let order = sequence_names(named(&x, "complexType", ty));
            assert!(assert_children_in_order(&ours, tag, &order) > 0, "no <{tag}> written");
        }
    }
}

#[test]
fn enumerations_match_the_xsd() {
    let Some(xsds) = xsd_texts() else { return };
    for xsd in &xsds {
        let x = Document::parse(xsd).unwrap();
        let s = |v: Vec<&'static str>| v.into_iter().map(String::from).collect::<Vec<_>>();
        assert_eq!(enumeration(&x, "lineMarking"), s(LineMarking::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "laneletType"), s(LaneletType::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "vehicleType"), s(RoadUser::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "drivingDir"), s(DrivingDir::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "trafficLightColor"), s(TrafficLightColor::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "obstacleTypeStatic"), s(StaticObstacleType::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "obstacleTypeDynamic"), s(DynamicObstacleType::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(enumeration(&x, "obstacleTypeEnvironment"), s(EnvironmentObstacleType::ALL.iter().map(|v| v.as_str()).collect()));
        let direction: Vec<String> = named(&x, "complexType", "trafficLight")
            .descendants()
            .filter(|n| is_xs(n, "enumeration"))
            .map(|n| n.attribute("value").unwrap().to_string())
            .collect();
        assert_eq!(direction, s(TrafficLightDirection::ALL.iter().map(|v| v.as_str()).collect()));
        assert_eq!(sequence_names(named(&x, "complexType", "tag")), s(Tag::ALL.iter().map(|t| t.as_str()).collect()));
        let mut signs = enumeration(&x, "trafficSignID");
        signs.sort();
        assert_eq!(signs, s(XSD_TRAFFIC_SIGN_IDS.to_vec()));
    }
}

#[test]
fn header_and_declaration_are_exact() {
    let out = written();
    assert!(out.starts_with(
        "<?xml version='1.0' encoding='utf-8'?>\n<commonRoad commonRoadVersion=\"2020a\" benchmarkID=\"DEU_Example-1_1_T-1\" date=\"2026-01-15\""
    ));
    assert!(out.ends_with("</commonRoad>\n"));
    let doc = Document::parse(&out).unwrap();
    assert_eq!(doc.root_element().attribute("timeStepSize"), Some("0.1"));
}

#[test]
fn numbers_are_fixed_notation_and_values_survive() {
    let mut m = common::minimal();
    // a lane bound far from the origin (UTM-sized) with sub-millimetre detail
    let (x0, y0) = (692_345.123_456_789, 5_334_210.987_654_321);
    let l = &mut m.scenario.network.lanelets[1];
    l.bounds =
        LaneletBounds::new(vec![Point::new(x0, y0 + 7.0), Point::new(x0 + 100.0, y0 + 7.0)], vec![Point::new(x0, y0 + 3.5), Point::new(x0 + 100.0, y0 + 3.5)])
            .unwrap();
    m.scenario.dynamic_obstacles[0].trajectory[0].orientation = -1e-12;
    m.scenario.dynamic_obstacles[0].trajectory[1].velocity = 1e-5;
    let out = String::from_utf8(write_scenario(&m.scenario, &m.problems).unwrap()).unwrap();
    let doc = Document::parse(&out).unwrap();
    let numeric = ["x", "y", "z", "exact", "intervalStart", "intervalEnd", "length", "width", "radius", "orientation"];
    let mut n = 0;
    for node in doc.descendants().filter(|n| numeric.contains(&n.tag_name().name())) {
        let Some(t) = node.text().filter(|t| !t.trim().is_empty()) else {
            continue;
        };
        n += 1;
        assert!(!t.contains(['e', 'E', 'N', 'I', ',']), "{t}");
        assert!(t.parse::<f64>().is_ok(), "{t}");
    }
    assert!(n > 50);
    let xs: Vec<f64> = doc.descendants().filter(|n| n.has_tag_name("x")).filter_map(|n| n.text()?.parse().ok()).filter(|v: &f64| *v > 600_000.0).collect();
    assert_eq!(xs.len(), 4);
    for v in xs {
        let err = ((v - x0) - (v - x0).round()).abs();
        assert!(err <= 1e-4, "{v}: {err} m off"); // 0.1 mm budget
        assert!(err <= 0.6e-6, "{v}: {err} m off"); // what 6 decimals promise
    }
    assert!(out.contains("<velocity><exact>0.00001</exact></velocity>"));
    assert!(!out.contains("-0.0<"));
}

#[test]
fn same_model_same_bytes() {
    let a = common::minimal();
    let b = common::minimal();
    assert_eq!(write_scenario(&a.scenario, &a.problems).unwrap(), write_scenario(&b.scenario, &b.problems).unwrap());
    assert_eq!(write_map(&a.scenario).unwrap(), write_map(&a.scenario).unwrap());
}

#[test]
fn tags_are_written_in_xsd_order_whatever_the_insertion_order() {
    let mut m = common::minimal();
    m.scenario.tags.clear();
    for t in [Tag::EmergencyBraking, Tag::Simulated, Tag::Interstate] {
        m.scenario.tags.insert(t);
    }
    let out = String::from_utf8(write_map(&m.scenario).unwrap()).unwrap();
    let doc = Document::parse(&out).unwrap();
    let tags: Vec<&str> =
        doc.descendants().find(|n| n.has_tag_name("scenarioTags")).unwrap().children().filter(Node::is_element).map(|n| n.tag_name().name()).collect();
    assert_eq!(tags, vec!["interstate", "simulated", "emergency_braking"]);
    m.scenario.tags.clear();
    assert!(String::from_utf8(write_map(&m.scenario).unwrap()).unwrap().contains("<scenarioTags/>"));
}

#[test]
fn scenario_without_planning_problem_is_refused() {
    let m = common::minimal();
    assert!(matches!(write_scenario(&m.scenario, &PlanningProblemSet::default()), Err(Error::NoPlanningProblem { .. })));
}

#[test]
fn non_finite_number_is_an_error_naming_the_element() {
    let mut m = common::minimal();
    m.scenario.dynamic_obstacles[0].trajectory[1].velocity = f64::NAN;
    match write_scenario(&m.scenario, &m.problems) {
        Err(Error::WriteNonFinite { context, .. }) => {
            assert!(context.contains(&format!("dynamicObstacle {}", m.car)), "{context}");
            assert!(context.contains("time step 2"), "{context}");
            assert!(context.ends_with("velocity"), "{context}");
        }
        other => panic!("expected NonFinite, got {other:?}"),
    }
    let mut m = common::minimal();
    m.scenario.header.time_step_size = f64::INFINITY;
    assert!(matches!(write_map(&m.scenario), Err(Error::WriteNonFinite { .. })));
}

#[test]
fn size_that_rounds_to_zero_is_an_error() {
    let mut m = common::minimal();
    m.scenario.static_obstacles[0].shape = Shape::circle(1e-8).unwrap();
    assert!(matches!(write_map(&m.scenario), Err(Error::WriteNotPositive { .. })));
}

#[test]
fn late_obstacle_and_trajectory_time_steps_are_written_as_given() {
    let mut m = common::minimal();
    let o = &mut m.scenario.dynamic_obstacles[0];
    o.initial_state.time_step = 5;
    o.trajectory = (6..=8).map(|t| common::state(t, 0.0, 0.0, 1.0)).collect();
    let out = String::from_utf8(write_map(&m.scenario).unwrap()).unwrap();
    let doc = Document::parse(&out).unwrap();
    let mut times: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for t in doc.descendants().filter(|n| n.has_tag_name("time")) {
        let parent = t.parent_element().unwrap().tag_name().name();
        let exact = t.children().find(|c| c.has_tag_name("exact")).and_then(|c| c.text()).unwrap();
        times.entry(parent).or_default().push(exact);
    }
    assert_eq!(times["initialState"], vec!["0", "5"]); // static obstacle, then the late car
    assert_eq!(times["state"], vec!["6", "7", "8"]);
}
