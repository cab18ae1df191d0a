//! The OpenDRIVE text of the maps the tool writes itself, so that it runs without the corpus:
//! a 2 km straight road, a road curving left then right, a four-way crossing (right-hand
//! traffic, a dynamic signal on every arm) and a T junction (left-hand traffic). Geometry is
//! computed here, never typed in, so the arcs meet their roads exactly.

use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt::Write as _;

/// Lane width of the built-in maps, m.
pub const LANE_WIDTH: f64 = 3.5;
/// Width of the sidewalks of the junction maps, m.
const SIDEWALK_WIDTH: f64 = 2.0;
/// Distance from a junction's centre to where its arms begin, m (the radius of its turns).
const JUNCTION_RADIUS: f64 = 20.0;
/// Length of each arm of the junction maps, m.
const ARM_LENGTH: f64 = 300.0;
/// OpenDRIVE id of the junction of the junction maps.
const JUNCTION_ID: &str = "1000";

/// One lane of a lane section.
struct LaneSpec {
    id: i32,
    kind: &'static str,
    width: f64,
    predecessor: Option<i32>,
    successor: Option<i32>,
}

impl LaneSpec {
    fn driving(id: i32) -> Self {
        LaneSpec { id, kind: "driving", width: LANE_WIDTH, predecessor: None, successor: None }
    }
    fn xml(&self) -> String {
        let mut link = String::new();
        if let Some(p) = self.predecessor {
            let _ = write!(link, r#"<predecessor id="{p}"/>"#);
        }
        if let Some(s) = self.successor {
            let _ = write!(link, r#"<successor id="{s}"/>"#);
        }
        format!(
            r#"<lane id="{}" type="{}" level="false"><link>{link}</link><width sOffset="0" a="{}" b="0" c="0" d="0"/><roadMark sOffset="0" type="solid" weight="standard" color="standard" width="0.12"/></lane>"#,
            self.id, self.kind, self.width
        )
    }
}

/// The lanes of one road: left lanes listed from the outside in, right lanes from the inside out.
fn lanes_xml(left: &[LaneSpec], right: &[LaneSpec]) -> String {
    let side = |lanes: &[LaneSpec]| lanes.iter().map(LaneSpec::xml).collect::<Vec<_>>().join("\n");
    format!(
        r#"<lanes><laneSection s="0">
<left>{}</left>
<center><lane id="0" type="none" level="false"><roadMark sOffset="0" type="solid" weight="standard" color="standard" width="0.12"/></lane></center>
<right>{}</right>
</laneSection></lanes>"#,
        side(left),
        side(right)
    )
}

struct RoadSpec<'a> {
    id: &'a str,
    length: f64,
    junction: &'a str,
    rule: &'a str,
    links: String,
    plan_view: String,
    lanes: String,
    signals: String,
}

fn road_xml(r: &RoadSpec) -> String {
    format!(
        r#"<road name="r{id}" length="{length:.10}" id="{id}" junction="{junction}" rule="{rule}"><link>{links}</link>
<type s="0" type="town"><speed max="50" unit="km/h"/></type>
<planView>{plan}</planView>
<elevationProfile/><lateralProfile/>
{lanes}
<signals>{signals}</signals></road>"#,
        id = r.id,
        length = r.length,
        junction = r.junction,
        rule = r.rule,
        links = r.links,
        plan = r.plan_view,
        lanes = r.lanes,
        signals = r.signals
    )
}

fn document(name: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
<header revMajor="1" revMinor="6" name="{name}" version="1.00" north="0" south="0" east="0" west="0"/>
{body}
</OpenDRIVE>
"#
    )
}

/// A motorway-like road of three lanes each way along `plan_view`.
fn three_lane_road(id: &str, length: f64, plan_view: String) -> String {
    let left: Vec<LaneSpec> = [3, 2, 1].into_iter().map(LaneSpec::driving).collect();
    let right: Vec<LaneSpec> = [-1, -2, -3].into_iter().map(LaneSpec::driving).collect();
    road_xml(&RoadSpec { id, length, junction: "-1", rule: "RHT", links: String::new(), plan_view, lanes: lanes_xml(&left, &right), signals: String::new() })
        .replace(r#"type="town"><speed max="50""#, r#"type="motorway"><speed max="130""#)
}

/// The 2 km straight road along +x from the origin.
pub fn straight() -> String {
    document("straight", &three_lane_road("1", 2000.0, r#"<geometry s="0" x="0" y="0" hdg="0" length="2000"><line/></geometry>"#.into()))
}

/// Plan view of the curved road: 300 m straight, 400 m of a left arc (radius 250 m), 400 m of
/// a right arc back to heading 0, 400 m straight.
pub fn curve() -> String {
    let k = 0.004;
    let (mut x, mut y, mut h) = (0.0f64, 0.0f64, 0.0f64);
    let mut out = String::new();
    let mut s = 0.0;
    for (len, curvature) in [(300.0, 0.0), (400.0, k), (400.0, -k), (400.0, 0.0)] {
        let shape = if curvature == 0.0 { "<line/>".to_string() } else { format!(r#"<arc curvature="{curvature}"/>"#) };
        let _ = write!(out, r#"<geometry s="{s}" x="{x:.10}" y="{y:.10}" hdg="{h:.10}" length="{len}">{shape}</geometry>"#);
        if curvature == 0.0 {
            x += len * h.cos();
            y += len * h.sin();
        } else {
            let h1 = h + curvature * len;
            x += (h1.sin() - h.sin()) / curvature;
            y += (h.cos() - h1.cos()) / curvature;
            h = h1;
        }
        s += len;
    }
    document("curve", &three_lane_road("1", 1500.0, out))
}

/// Road id of arm `k` of a junction map.
fn arm_id(k: usize) -> String {
    format!("{}", k + 1)
}

/// A junction map: arms leaving the centre in the directions `arms` (radians), each with two
/// lanes each way and a sidewalk on each side, joined by a junction in which every arm reaches
/// every other (straight on, left and right turns). `lht`: left-hand traffic. `signals`: a
/// dynamic signal facing the traffic that enters the junction on each arm (signal id = arm id).
fn junction_map(name: &str, arms: &[f64], lht: bool, signals: bool) -> String {
    let rule = if lht { "LHT" } else { "RHT" };
    // Traffic towards the junction drives against s on an arm (its s runs outwards): left lanes
    // under right-hand traffic, right lanes under left-hand traffic.
    let inward = if lht { -1 } else { 1 };
    let mut body = String::new();
    let mut connections = String::new();
    let mut next_connecting = 100;
    for (a, &phi) in arms.iter().enumerate() {
        let (x0, y0) = (JUNCTION_RADIUS * phi.cos(), JUNCTION_RADIUS * phi.sin());
        let lane = |id: i32| LaneSpec { id, ..LaneSpec::driving(id) };
        let sidewalk = |id: i32| LaneSpec { id, kind: "sidewalk", width: SIDEWALK_WIDTH, predecessor: None, successor: None };
        let left = vec![sidewalk(3), lane(2), lane(1)];
        let right = vec![lane(-1), lane(-2), sidewalk(-3)];
        let signal = if signals {
            // beside the lanes that enter the junction, facing the traffic in them
            let (t, orientation) = if inward > 0 { (2.0 * LANE_WIDTH + SIDEWALK_WIDTH + 0.5, "-") } else { (-(2.0 * LANE_WIDTH + SIDEWALK_WIDTH + 0.5), "+") };
            format!(
                r#"<signal s="3" t="{t}" id="{id}" name="light{id}" dynamic="yes" orientation="{orientation}" zOffset="3.0" type="1000001" country="OpenDRIVE" subtype="-1" hOffset="0" pitch="0" roll="0" height="0.8" width="0.4"/>"#,
                id = arm_id(a)
            )
        } else {
            String::new()
        };
        body.push_str(&road_xml(&RoadSpec {
            id: &arm_id(a),
            length: ARM_LENGTH,
            junction: "-1",
            rule,
            links: format!(r#"<predecessor elementType="junction" elementId="{JUNCTION_ID}"/>"#),
            plan_view: format!(r#"<geometry s="0" x="{x0:.10}" y="{y0:.10}" hdg="{phi:.10}" length="{ARM_LENGTH}"><line/></geometry>"#),
            lanes: lanes_xml(&left, &right),
            signals: signal,
        }));
        body.push('\n');
    }
    for (a, &phi_a) in arms.iter().enumerate() {
        for (b, &phi_b) in arms.iter().enumerate() {
            if a == b {
                continue;
            }
            let id = format!("{next_connecting}");
            next_connecting += 1;
            let heading_in = phi_a + PI;
            let (x0, y0) = (JUNCTION_RADIUS * phi_a.cos(), JUNCTION_RADIUS * phi_a.sin());
            // the turn from the inward heading to the outward one, in (-π, π]
            let mut turn = phi_b - heading_in;
            while turn > PI + 1e-9 {
                turn -= 2.0 * PI;
            }
            while turn <= -PI + 1e-9 {
                turn += 2.0 * PI;
            }
            let (length, shape) = if turn.abs() < 1e-6 {
                (2.0 * JUNCTION_RADIUS, "<line/>".to_string())
            } else {
                let curvature = turn.signum() / JUNCTION_RADIUS;
                (JUNCTION_RADIUS * FRAC_PI_2, format!(r#"<arc curvature="{curvature:.10}"/>"#))
            };
            // the connecting road's lanes drive along its s: right lanes (RHT) or left (LHT)
            let along = -inward;
            let lanes: Vec<LaneSpec> = (1..=2)
                .map(|k| LaneSpec { id: along * k, kind: "driving", width: LANE_WIDTH, predecessor: Some(inward * k), successor: Some(along * k) })
                .collect();
            let (left, right): (Vec<LaneSpec>, Vec<LaneSpec>) = if along > 0 { (lanes.into_iter().rev().collect(), Vec::new()) } else { (Vec::new(), lanes) };
            body.push_str(&road_xml(&RoadSpec {
                id: &id,
                length,
                junction: JUNCTION_ID,
                rule,
                links: format!(
                    r#"<predecessor elementType="road" elementId="{}" contactPoint="start"/><successor elementType="road" elementId="{}" contactPoint="start"/>"#,
                    arm_id(a),
                    arm_id(b)
                ),
                plan_view: format!(r#"<geometry s="0" x="{x0:.10}" y="{y0:.10}" hdg="{heading_in:.10}" length="{length:.10}">{shape}</geometry>"#),
                lanes: lanes_xml(&left, &right),
                signals: String::new(),
            }));
            body.push('\n');
            let _ = write!(
                connections,
                r#"<connection id="{id}" incomingRoad="{}" connectingRoad="{id}" contactPoint="start"><laneLink from="{}" to="{}"/><laneLink from="{}" to="{}"/></connection>"#,
                arm_id(a),
                inward,
                along,
                2 * inward,
                2 * along
            );
        }
    }
    let _ = write!(body, r#"<junction id="{JUNCTION_ID}" name="junction">{connections}</junction>"#);
    document(name, &body)
}

/// A four-way crossing under right-hand traffic, with a signal on every arm.
pub fn crossing() -> String {
    junction_map("crossing", &[0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2], false, true)
}

/// A T junction (arms east, west and south) under left-hand traffic.
pub fn tee() -> String {
    junction_map("tee", &[0.0, PI, 3.0 * FRAC_PI_2], true, false)
}
