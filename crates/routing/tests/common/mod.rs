//! Small OpenDRIVE networks written out by hand for the tests. Geometry is a straight line
//! per road (routing only needs topology and lengths).

#![allow(dead_code)]

use opendrive::RoadNetwork;
use std::path::Path;

/// A lane: id, successor lane ids, predecessor lane ids.
pub(crate) struct L(pub i32, pub &'static [i32], pub &'static [i32]);

pub(crate) struct R {
    pub id: &'static str,
    pub length: f64,
    pub junction: &'static str,
    /// (elementType, elementId, contactPoint or "")
    pub pred: Option<(&'static str, &'static str, &'static str)>,
    pub succ: Option<(&'static str, &'static str, &'static str)>,
    pub lanes: Vec<L>,
    /// Road-type speed limit in m/s.
    pub speed: Option<f64>,
}

fn link(tag: &str, l: &Option<(&str, &str, &str)>) -> String {
    match l {
        Some((t, id, "")) => format!("<{tag} elementType=\"{t}\" elementId=\"{id}\"/>"),
        Some((t, id, cp)) => format!("<{tag} elementType=\"{t}\" elementId=\"{id}\" contactPoint=\"{cp}\"/>"),
        None => String::new(),
    }
}

fn lane(l: &L) -> String {
    let mut links = String::new();
    for p in l.2 {
        links += &format!("<predecessor id=\"{p}\"/>");
    }
    for s in l.1 {
        links += &format!("<successor id=\"{s}\"/>");
    }
    format!("<lane id=\"{}\" type=\"driving\" level=\"false\"><link>{links}</link><width sOffset=\"0\" a=\"3.5\" b=\"0\" c=\"0\" d=\"0\"/></lane>", l.0)
}

pub(crate) fn road(r: &R) -> String {
    let left: Vec<String> = r.lanes.iter().filter(|l| l.0 > 0).map(lane).collect();
    let right: Vec<String> = r.lanes.iter().filter(|l| l.0 < 0).map(lane).collect();
    let speed = r.speed.map(|v| format!("<type s=\"0\" type=\"town\"><speed max=\"{v}\" unit=\"m/s\"/></type>")).unwrap_or_default();
    format!(
        "<road id=\"{}\" length=\"{}\" junction=\"{}\"><link>{}{}</link>{speed}<planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"{}\"><line/></geometry></planView>\
         <lanes><laneSection s=\"0\">{}<center><lane id=\"0\" type=\"none\" level=\"false\"/></center>{}</laneSection></lanes></road>\n",
        r.id,
        r.length,
        r.junction,
        link("predecessor", &r.pred),
        link("successor", &r.succ),
        r.length,
        if left.is_empty() { String::new() } else { format!("<left>{}</left>", left.join("")) },
        if right.is_empty() { String::new() } else { format!("<right>{}</right>", right.join("")) },
    )
}

/// (id, incoming, connecting, contactPoint, [(from, to)])
pub(crate) struct C(pub &'static str, pub &'static str, pub &'static str, pub &'static str, pub &'static [(i32, i32)]);

pub(crate) fn junction(id: &str, conns: &[C]) -> String {
    let mut out = format!("<junction id=\"{id}\" name=\"j{id}\">");
    for c in conns {
        out += &format!("<connection id=\"{}\" incomingRoad=\"{}\" connectingRoad=\"{}\" contactPoint=\"{}\">", c.0, c.1, c.2, c.3);
        for (f, t) in c.4 {
            out += &format!("<laneLink from=\"{f}\" to=\"{t}\"/>");
        }
        out += "</connection>";
    }
    out + "</junction>\n"
}

pub(crate) fn network(roads: &[R], junctions: &[String]) -> RoadNetwork {
    let mut xml = String::from("<OpenDRIVE><header revMajor=\"1\" revMinor=\"6\"/>\n");
    for r in roads {
        xml += &road(r);
    }
    for j in junctions {
        xml += j;
    }
    xml += "</OpenDRIVE>\n";
    match opendrive::parse_str(&xml, Path::new("test.xodr")) {
        Ok(l) => l.network,
        Err(e) => panic!("test network does not parse: {e}\n{xml}"),
    }
}

fn road_link(id: &'static str, cp: &'static str) -> Option<(&'static str, &'static str, &'static str)> {
    Some(("road", id, cp))
}
fn junction_link(id: &'static str) -> Option<(&'static str, &'static str, &'static str)> {
    Some(("junction", id, ""))
}

/// A T-junction. Arms: road 1 (100 m, two lanes -1/-2 eastbound toward the junction, one
/// lane 1 westbound), road 2 (100 m, starts at the junction, lanes -1 east / 1 west), road
/// 3 (100 m, ends at the junction, lanes -1 north / 1 south). Connecting roads: 10 (20 m,
/// 1 ↔ 2 straight, both directions), 12 (15 m, 1 lane -2 → 3 southbound, right turn), 13
/// (15 m, 3 → 2 eastbound), 14 (25 m, 3 → 1 westbound), 15 (25 m, 2 westbound → 3 southbound).
pub(crate) fn t_junction() -> RoadNetwork {
    let roads = vec![
        R {
            id: "1",
            length: 100.0,
            junction: "-1",
            pred: None,
            succ: junction_link("100"),
            lanes: vec![L(1, &[], &[]), L(-1, &[], &[]), L(-2, &[], &[])],
            speed: None,
        },
        R { id: "2", length: 100.0, junction: "-1", pred: junction_link("100"), succ: None, lanes: vec![L(1, &[], &[]), L(-1, &[], &[])], speed: None },
        R { id: "3", length: 100.0, junction: "-1", pred: None, succ: junction_link("100"), lanes: vec![L(1, &[], &[]), L(-1, &[], &[])], speed: None },
        R {
            id: "10",
            length: 20.0,
            junction: "100",
            pred: road_link("1", "end"),
            succ: road_link("2", "start"),
            lanes: vec![L(1, &[1], &[1]), L(-1, &[-1], &[-1])],
            speed: None,
        },
        R { id: "12", length: 15.0, junction: "100", pred: road_link("1", "end"), succ: road_link("3", "end"), lanes: vec![L(-1, &[1], &[-2])], speed: None },
        R {
            id: "13",
            length: 15.0,
            junction: "100",
            pred: road_link("3", "end"),
            succ: road_link("2", "start"),
            lanes: vec![L(-1, &[-1], &[-1])],
            speed: None,
        },
        R { id: "14", length: 25.0, junction: "100", pred: road_link("3", "end"), succ: road_link("1", "end"), lanes: vec![L(-1, &[1], &[-1])], speed: None },
        R { id: "15", length: 25.0, junction: "100", pred: road_link("2", "start"), succ: road_link("3", "end"), lanes: vec![L(-1, &[1], &[1])], speed: None },
    ];
    let j = junction(
        "100",
        &[
            C("0", "1", "10", "start", &[(-1, -1)]),
            C("1", "2", "10", "end", &[(1, 1)]),
            C("2", "1", "12", "start", &[(-2, -1)]),
            C("3", "3", "13", "start", &[(-1, -1)]),
            C("4", "3", "14", "start", &[(-1, -1)]),
            C("5", "2", "15", "start", &[(1, -1)]),
        ],
    );
    network(&roads, &[j])
}

/// Two ways from road A to road F, one lane each way (-1 only, one-way roads):
/// A (100) → J1 → c1 (10) → B (50, 5 m/s) → J2 → c3 (10) → F (100): 2 junctions, short, slow;
/// A (100) → J1 → c2 (10) → D (500, 100 m/s) → F directly: 1 junction, long, fast.
pub(crate) fn two_ways() -> RoadNetwork {
    let roads = vec![
        R { id: "A", length: 100.0, junction: "-1", pred: None, succ: junction_link("J1"), lanes: vec![L(-1, &[], &[])], speed: None },
        R {
            id: "c1",
            length: 10.0,
            junction: "J1",
            pred: road_link("A", "end"),
            succ: road_link("B", "start"),
            lanes: vec![L(-1, &[-1], &[-1])],
            speed: Some(5.0),
        },
        R { id: "c2", length: 10.0, junction: "J1", pred: road_link("A", "end"), succ: road_link("D", "start"), lanes: vec![L(-1, &[-1], &[-1])], speed: None },
        R { id: "B", length: 50.0, junction: "-1", pred: junction_link("J1"), succ: junction_link("J2"), lanes: vec![L(-1, &[], &[])], speed: Some(5.0) },
        R {
            id: "c3",
            length: 10.0,
            junction: "J2",
            pred: road_link("B", "end"),
            succ: road_link("F", "start"),
            lanes: vec![L(-1, &[-1], &[-1])],
            speed: Some(5.0),
        },
        R {
            id: "D",
            length: 500.0,
            junction: "-1",
            pred: junction_link("J1"),
            succ: road_link("F", "start"),
            lanes: vec![L(-1, &[-1], &[])],
            speed: Some(100.0),
        },
        R { id: "F", length: 100.0, junction: "-1", pred: junction_link("J2"), succ: None, lanes: vec![L(-1, &[], &[])], speed: None },
    ];
    let j1 = junction("J1", &[C("0", "A", "c1", "start", &[(-1, -1)]), C("1", "A", "c2", "start", &[(-1, -1)])]);
    let j2 = junction("J2", &[C("0", "B", "c3", "start", &[(-1, -1)])]);
    network(&roads, &[j1, j2])
}

/// A ring: R1 (100 m) → R2 (50 m) → R1, one lane -1.
pub(crate) fn ring() -> RoadNetwork {
    let roads = vec![
        R {
            id: "R1",
            length: 100.0,
            junction: "-1",
            pred: road_link("R2", "end"),
            succ: road_link("R2", "start"),
            lanes: vec![L(-1, &[-1], &[-1])],
            speed: None,
        },
        R {
            id: "R2",
            length: 50.0,
            junction: "-1",
            pred: road_link("R1", "end"),
            succ: road_link("R1", "start"),
            lanes: vec![L(-1, &[-1], &[-1])],
            speed: None,
        },
    ];
    network(&roads, &[])
}
