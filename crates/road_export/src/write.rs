//! The OpenDRIVE 1.8 writer: element order of the 1.8 schema, numbers in Rust's shortest
//! round-trip notation (every f64 reads back bit for bit), nothing that depends on the clock
//! or on hash order, so the same network gives the same bytes.

use crate::model::{Document, Junction, Lane, LinkTarget, Mark, Road, Section, Signal, SignalReference, Validity};
use crate::offsets::Cubic;
use opendrive::Shape;
use std::fmt::Write;

/// A number as `xs:double` text (non-finite values, which the export never makes, as 0).
pub(crate) fn num(v: f64) -> String {
    if v.is_finite() {
        if v == 0.0 {
            "0".into()
        } else {
            format!("{v}")
        }
    } else {
        "0".into()
    }
}

/// Attribute text with XML's special characters escaped.
pub(crate) fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => {}
            c => o.push(c),
        }
    }
    o
}

struct Out {
    s: String,
}

impl Out {
    fn line(&mut self, depth: usize, text: &str) {
        for _ in 0..depth {
            self.s.push_str("  ");
        }
        self.s.push_str(text);
        self.s.push('\n');
    }
}

fn link(kind: &str, l: &LinkTarget) -> String {
    match l {
        LinkTarget::Road { id, at_start } => {
            format!("<{kind} elementType=\"road\" elementId=\"{id}\" contactPoint=\"{}\"/>", if *at_start { "start" } else { "end" })
        }
        LinkTarget::Junction { id } => format!("<{kind} elementType=\"junction\" elementId=\"{id}\"/>"),
    }
}

fn cubic_attrs(c: &Cubic) -> String {
    format!("a=\"{}\" b=\"{}\" c=\"{}\" d=\"{}\"", num(c.a), num(c.b), num(c.c), num(c.d))
}

fn mark(o: &mut Out, depth: usize, m: &Option<Mark>) {
    if let Some(m) = m {
        let weight = m.weight.map(|w| format!(" weight=\"{w}\"")).unwrap_or_default();
        o.line(depth, &format!("<roadMark sOffset=\"0\" type=\"{}\"{weight} color=\"standard\"/>", m.kind));
    }
}

fn lane(o: &mut Out, depth: usize, l: &Lane) {
    o.line(depth, &format!("<lane id=\"{}\" type=\"{}\" level=\"false\">", l.id, l.kind));
    if !l.predecessors.is_empty() || !l.successors.is_empty() {
        o.line(depth + 1, "<link>");
        for p in &l.predecessors {
            o.line(depth + 2, &format!("<predecessor id=\"{p}\"/>"));
        }
        for p in &l.successors {
            o.line(depth + 2, &format!("<successor id=\"{p}\"/>"));
        }
        o.line(depth + 1, "</link>");
    }
    for w in &l.widths {
        o.line(depth + 1, &format!("<width sOffset=\"{}\" {}/>", num(w.s), cubic_attrs(w)));
    }
    mark(o, depth + 1, &l.mark);
    if let Some(user) = l.access {
        o.line(depth + 1, &format!("<access sOffset=\"0\" rule=\"allow\" restriction=\"{user}\"/>"));
    }
    o.line(depth, "</lane>");
}

fn section(o: &mut Out, depth: usize, sec: &Section) {
    o.line(depth, &format!("<laneSection s=\"{}\">", num(sec.s)));
    if !sec.left.is_empty() {
        o.line(depth + 1, "<left>");
        for l in sec.left.iter().rev() {
            lane(o, depth + 2, l);
        }
        o.line(depth + 1, "</left>");
    }
    o.line(depth + 1, "<center>");
    if sec.centre_mark.is_some() {
        o.line(depth + 2, "<lane id=\"0\" type=\"none\" level=\"false\">");
        mark(o, depth + 3, &sec.centre_mark);
        o.line(depth + 2, "</lane>");
    } else {
        o.line(depth + 2, "<lane id=\"0\" type=\"none\" level=\"false\"/>");
    }
    o.line(depth + 1, "</center>");
    if !sec.right.is_empty() {
        o.line(depth + 1, "<right>");
        for l in &sec.right {
            lane(o, depth + 2, l);
        }
        o.line(depth + 1, "</right>");
    }
    o.line(depth, "</laneSection>");
}

fn validity(o: &mut Out, depth: usize, v: &[Validity]) {
    for v in v {
        o.line(depth, &format!("<validity fromLane=\"{}\" toLane=\"{}\"/>", v.from, v.to));
    }
}

fn signal(o: &mut Out, depth: usize, s: &Signal) {
    let mut a = format!(
        "<signal s=\"{}\" t=\"{}\" id=\"{}\" name=\"{}\" dynamic=\"{}\" orientation=\"{}\" zOffset=\"0\"",
        num(s.s),
        num(s.t),
        s.id,
        esc(&s.name),
        if s.dynamic { "yes" } else { "no" },
        s.orientation
    );
    if let Some(c) = &s.country {
        let _ = write!(a, " country=\"{}\"", esc(c));
    }
    let _ = write!(a, " type=\"{}\" subtype=\"{}\"", esc(&s.kind), esc(&s.subtype));
    if let Some((v, unit)) = s.value {
        let _ = write!(a, " value=\"{}\"", num(v));
        if !unit.is_empty() {
            let _ = write!(a, " unit=\"{unit}\"");
        }
    }
    with_validity(o, depth, &a, "signal", &s.validity);
}

fn signal_reference(o: &mut Out, depth: usize, r: &SignalReference) {
    let a = format!("<signalReference s=\"{}\" t=\"{}\" id=\"{}\" orientation=\"{}\"", num(r.s), num(r.t), r.id, r.orientation);
    with_validity(o, depth, &a, "signalReference", &r.validity);
}

/// Closes the start tag `open` (`<tag` and its attributes): empty, or holding the lanes the
/// element is valid in.
fn with_validity(o: &mut Out, depth: usize, open: &str, tag: &str, lanes: &[Validity]) {
    if lanes.is_empty() {
        o.line(depth, &format!("{open}/>"));
    } else {
        o.line(depth, &format!("{open}>"));
        validity(o, depth + 1, lanes);
        o.line(depth, &format!("</{tag}>"));
    }
}

fn road(o: &mut Out, r: &Road) {
    o.line(
        1,
        &format!(
            "<road id=\"{}\" name=\"{}\" length=\"{}\" junction=\"{}\" rule=\"{}\">",
            r.id,
            esc(&r.name),
            num(r.length),
            r.junction.map_or_else(|| "-1".to_string(), |j| j.to_string()),
            if r.lht { "LHT" } else { "RHT" }
        ),
    );
    if r.predecessor.is_some() || r.successor.is_some() {
        o.line(2, "<link>");
        if let Some(p) = &r.predecessor {
            o.line(3, &link("predecessor", p));
        }
        if let Some(p) = &r.successor {
            o.line(3, &link("successor", p));
        }
        o.line(2, "</link>");
    }
    o.line(2, &format!("<type s=\"0\" type=\"{}\"/>", r.road_type));
    o.line(2, "<planView>");
    for g in &r.geometries {
        o.line(3, &format!("<geometry s=\"{}\" x=\"{}\" y=\"{}\" hdg=\"{}\" length=\"{}\">", num(g.s), num(g.x), num(g.y), num(g.hdg), num(g.length)));
        match &g.shape {
            Shape::ParamPoly3(p) => o.line(
                4,
                &format!(
                    "<paramPoly3 aU=\"{}\" bU=\"{}\" cU=\"{}\" dU=\"{}\" aV=\"{}\" bV=\"{}\" cV=\"{}\" dV=\"{}\" pRange=\"normalized\"/>",
                    num(p.u[0]),
                    num(p.u[1]),
                    num(p.u[2]),
                    num(p.u[3]),
                    num(p.v[0]),
                    num(p.v[1]),
                    num(p.v[2]),
                    num(p.v[3])
                ),
            ),
            _ => o.line(4, "<line/>"),
        }
        o.line(3, "</geometry>");
    }
    o.line(2, "</planView>");
    o.line(2, "<lanes>");
    for c in &r.lane_offsets {
        o.line(3, &format!("<laneOffset s=\"{}\" {}/>", num(c.s), cubic_attrs(c)));
    }
    for sec in &r.sections {
        section(o, 3, sec);
    }
    o.line(2, "</lanes>");
    if !r.signals.is_empty() || !r.signal_references.is_empty() {
        o.line(2, "<signals>");
        for s in &r.signals {
            signal(o, 3, s);
        }
        for s in &r.signal_references {
            signal_reference(o, 3, s);
        }
        o.line(2, "</signals>");
    }
    o.line(1, "</road>");
}

fn junction(o: &mut Out, j: &Junction) {
    o.line(1, &format!("<junction id=\"{}\" name=\"{}\" type=\"{}\">", j.id, esc(&j.name), if j.direct { "direct" } else { "default" }));
    for (k, c) in j.connections.iter().enumerate() {
        let target = if j.direct { "linkedRoad" } else { "connectingRoad" };
        o.line(
            2,
            &format!(
                "<connection id=\"{k}\" incomingRoad=\"{}\" {target}=\"{}\" contactPoint=\"{}\">",
                c.incoming,
                c.target,
                if c.target_at_start { "start" } else { "end" }
            ),
        );
        for (from, to) in &c.lane_links {
            o.line(3, &format!("<laneLink from=\"{from}\" to=\"{to}\"/>"));
        }
        o.line(2, "</connection>");
    }
    o.line(1, "</junction>");
}

/// The document as OpenDRIVE 1.8 XML.
pub(crate) fn write(doc: &Document) -> String {
    let mut o = Out { s: String::new() };
    o.line(0, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    o.line(0, "<OpenDRIVE>");
    o.line(1, &format!("<header revMajor=\"1\" revMinor=\"8\" name=\"{}\" version=\"1.0\" vendor=\"osc2cr\">", esc(&doc.name)));
    if let Some(g) = &doc.geo_reference {
        o.line(2, &format!("<geoReference><![CDATA[{}]]></geoReference>", g.replace("]]>", "]]]]><![CDATA[>")));
    }
    o.line(1, "</header>");
    for r in &doc.roads {
        road(&mut o, r);
    }
    for j in &doc.junctions {
        junction(&mut o, j);
    }
    o.line(0, "</OpenDRIVE>");
    o.s
}
