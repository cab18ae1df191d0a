//! The stand-in's OpenDRIVE text: the header, a road per lanelet (its pieces as `line`
//! geometries, one lane `-1` of the lanelet's width centred on the line by a `laneOffset`), and
//! the signals of the traffic lights and signs on the road of the first lanelet that refers to
//! them. OpenDRIVE 1.7: its signals have `s` and `t` attributes, which esmini 3.6.0 and
//! osc2cr's reader read (1.8 moved them into `positionRoad`, which neither reads).

use std::fmt::Write;

use commonroad::{LaneletNetwork, Point};

use crate::geometry::Road;
use crate::{Error, Options, Warning};

/// A number as written: shortest round-trip form (never an exponent; `-0` as `0`).
fn num(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else {
        format!("{v}")
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// A signal to place: its id, whether it is a light, its position and the lanelets that refer
/// to it.
struct SignalPlace {
    id: u64,
    light: bool,
    kind: String,
    position: Option<Point>,
    road: Option<u64>,
}

fn signals(network: &LaneletNetwork) -> Vec<SignalPlace> {
    let first = |refers: &dyn Fn(&commonroad::Lanelet) -> bool| network.lanelets.iter().find(|l| refers(l)).map(|l| l.id.get());
    let lights = network.traffic_lights.iter().map(|t| SignalPlace {
        id: t.id.get(),
        light: true,
        kind: "1000001".to_string(),
        position: t.position,
        road: first(&|l| l.traffic_light_refs.contains(&t.id)),
    });
    let signs = network.traffic_signs.iter().map(|s| SignalPlace {
        id: s.id.get(),
        light: false,
        kind: s.elements.first().map_or_else(|| "-1".to_string(), |e| e.sign_id.clone()),
        position: s.position,
        road: first(&|l| l.traffic_sign_refs.contains(&s.id)),
    });
    lights.chain(signs).collect()
}

fn signal_xml(out: &mut String, sig: &SignalPlace, road: &Road, at: (f64, f64)) {
    let (s, t) = road.project(at.0, at.1);
    let (dynamic, name) = if sig.light { ("yes", "traffic light") } else { ("no", "traffic sign") };
    let _ = writeln!(
        out,
        "      <signal s=\"{}\" t=\"{}\" id=\"{}\" name=\"{name} {}\" dynamic=\"{dynamic}\" orientation=\"+\" zOffset=\"2\" type=\"{}\" subtype=\"-1\" height=\"0.8\" width=\"0.3\"/>",
        num(s),
        num(t),
        sig.id,
        sig.id,
        escape(&sig.kind)
    );
}

pub(crate) fn document(network: &LaneletNetwork, roads: &[Road], options: &Options, warnings: &mut Vec<Warning>) -> Result<String, Error> {
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<OpenDRIVE>\n");
    let _ = write!(out, "  <header revMajor=\"1\" revMinor=\"7\" name=\"{}\"", escape(&options.name));
    match &options.geo_reference {
        Some(g) => {
            let _ = writeln!(out, ">\n    <geoReference>{}</geoReference>\n  </header>", escape(g));
        }
        None => out.push_str("/>\n"),
    }
    // signals go to the road of the first lanelet that refers to them, else the nearest road
    let places = signals(network);
    let mut on_road: Vec<Vec<(&SignalPlace, (f64, f64))>> = vec![Vec::new(); roads.len()];
    for sig in &places {
        let index = sig.road.and_then(|id| roads.iter().position(|r| r.lanelet == id));
        let at = sig.position.map(|p| (p.x, p.y)).or_else(|| {
            let r = &roads[index?];
            let last = r.pieces.last()?;
            let (sin, cos) = last.hdg.sin_cos();
            Some((last.x + last.length * cos, last.y + last.length * sin))
        });
        let Some(at) = at else {
            warnings.push(Warning { message: format!("signal {}: no position and no lanelet refers to it; not written", sig.id) });
            continue;
        };
        let index = index.unwrap_or_else(|| {
            let d = |r: &Road| r.nearest(at.0, at.1).0;
            (0..roads.len()).min_by(|&a, &b| d(&roads[a]).total_cmp(&d(&roads[b]))).unwrap_or(0)
        });
        on_road[index].push((sig, at));
    }
    for (road, sigs) in roads.iter().zip(&on_road) {
        let length = road.length();
        if !length.is_finite() || length <= 0.0 {
            return Err(Error::NotFinite(format!("lanelet {} length", road.lanelet)));
        }
        let _ = writeln!(out, "  <road name=\"lanelet {}\" length=\"{}\" id=\"{}\" junction=\"-1\">", road.lanelet, num(length), road.lanelet);
        out.push_str("    <planView>\n");
        for p in &road.pieces {
            let _ = writeln!(
                out,
                "      <geometry s=\"{}\" x=\"{}\" y=\"{}\" hdg=\"{}\" length=\"{}\"><line/></geometry>",
                num(p.s),
                num(p.x),
                num(p.y),
                num(p.hdg),
                num(p.length)
            );
        }
        out.push_str("    </planView>\n    <lanes>\n");
        for p in &road.pieces {
            let slope = (p.w1 - p.w0) / p.length;
            let _ = writeln!(out, "      <laneOffset s=\"{}\" a=\"{}\" b=\"{}\" c=\"0\" d=\"0\"/>", num(p.s), num(0.5 * p.w0), num(0.5 * slope));
        }
        out.push_str("      <laneSection s=\"0\">\n        <center>\n          <lane id=\"0\" type=\"none\" level=\"false\"/>\n        </center>\n");
        out.push_str("        <right>\n          <lane id=\"-1\" type=\"driving\" level=\"false\">\n");
        for p in &road.pieces {
            let slope = (p.w1 - p.w0) / p.length;
            let _ = writeln!(out, "            <width sOffset=\"{}\" a=\"{}\" b=\"{}\" c=\"0\" d=\"0\"/>", num(p.s), num(p.w0), num(slope));
        }
        out.push_str("          </lane>\n        </right>\n      </laneSection>\n    </lanes>\n");
        if !sigs.is_empty() {
            out.push_str("    <signals>\n");
            for (sig, at) in sigs {
                signal_xml(&mut out, sig, road, *at);
            }
            out.push_str("    </signals>\n");
        }
        out.push_str("  </road>\n");
    }
    out.push_str("</OpenDRIVE>\n");
    Ok(out)
}
