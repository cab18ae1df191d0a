//! Traffic signs, traffic lights and stop lines → `<signal>`s. A sign or light is written on
//! the road of the first lanelet that refers to it, at its position projected onto that
//! road (kept inside that lanelet's lane section), valid for the referring lanes there;
//! referring lanelets elsewhere get a `<signalReference>`. The signal's id is the CommonRoad
//! id in decimal (the OpenSCENARIO side names traffic lights by it). German sign numbers
//! are written as they are (`274`, `1002` with subtype `10` for `1002-10`); speed values go
//! from m/s to km/h. Stop lines are signals of type 294 (the German stop line) on their lane.

use crate::model::{Road, Signal, SignalReference, Validity};
use crate::reference::RefLine;
use crate::roads::Placed;
use crate::vec2::V2;
use crate::warning::{Subject, Warning};
use commonroad::{LaneletNetwork, Point, TrafficLightDirection};
use std::collections::BTreeMap;

/// Signals are kept this far inside their lane section (m), so a reader finds the section.
const INSET: f64 = 1e-3;

/// ISO 3166 alpha-2 of an alpha-3 code CommonRoad uses (`ZAM` reads the German table).
pub(crate) fn alpha2(country: &str) -> Option<&'static str> {
    Some(match country.trim().to_ascii_uppercase().as_str() {
        "DEU" | "DE" | "ZAM" => "DE",
        "USA" | "US" => "US",
        "CHN" | "CN" => "CN",
        "ESP" | "ES" => "ES",
        "RUS" | "RU" => "RU",
        "ARG" | "AR" => "AR",
        "BEL" | "BE" => "BE",
        "FRA" | "FR" => "FR",
        "GRC" | "GR" => "GR",
        "HRV" | "HR" => "HR",
        "ITA" | "IT" => "IT",
        "PRI" | "PR" => "PR",
        "AUS" | "AU" => "AU",
        _ => return None,
    })
}

/// What the signals of a network need to know about where lanelets went.
pub(crate) struct Places<'a> {
    pub net: &'a LaneletNetwork,
    pub placed: &'a [Option<Placed>],
    pub lines: &'a [RefLine],
    pub roads: &'a [Road],
    pub country: Option<String>,
}

/// A signal's spot: road, (s, t), orientation.
struct Spot {
    road: usize,
    s: f64,
    t: f64,
    orientation: &'static str,
}

impl Spot {
    /// A signal named `name` standing here, valid on `validity`: static, of no country, kind or
    /// value yet, subtype `-1` — the caller says what it is.
    fn signal(&self, id: u64, name: String, validity: Vec<Validity>) -> Signal {
        Signal {
            id,
            s: self.s,
            t: self.t,
            name,
            dynamic: false,
            orientation: self.orientation,
            country: None,
            kind: String::new(),
            subtype: "-1".into(),
            value: None,
            validity,
        }
    }
}

impl Places<'_> {
    fn section_range(&self, p: Placed) -> (f64, f64) {
        let Some(road) = self.roads.get(p.road) else { return (0.0, 0.0) };
        let s0 = road.sections.get(p.section).map_or(0.0, |s| s.s);
        let s1 = road.sections.get(p.section + 1).map_or(road.length, |s| s.s);
        (s0, s1)
    }

    /// `at` projected onto the lanelet's road, s kept inside its section; the distance moved.
    fn spot(&self, i: usize, at: V2) -> Option<(Spot, f64)> {
        let p = self.placed.get(i).copied().flatten()?;
        let line = self.lines.get(p.road)?;
        let (s, t) = line.project(at, None);
        let (s0, s1) = self.section_range(p);
        let inset = INSET.min(0.25 * (s1 - s0));
        let kept = s.clamp(s0 + inset, s1 - inset);
        let moved = line.pose(kept).at_t(t).dist(at);
        Some((Spot { road: p.road, s: kept, t, orientation: if p.along { "+" } else { "-" } }, moved))
    }

    /// Where an element with no position of its own stands: `end` of the lanelet's right bound.
    fn default_at(&self, i: usize, end: bool) -> Option<V2> {
        let l = self.net.lanelets.get(i)?;
        let r = l.bounds.right();
        (if end { r.last() } else { r.first() }).map(V2::of)
    }
}

/// Validity of the referring lanelets on the host's road and section; references elsewhere.
fn attach(pl: &Places, host: usize, refs: &[usize], id: u64) -> (Vec<Validity>, Vec<(usize, SignalReference)>) {
    let Some(h) = pl.placed.get(host).copied().flatten() else { return (Vec::new(), Vec::new()) };
    let mut validity = Vec::new();
    let mut others = Vec::new();
    for &i in refs {
        let Some(p) = pl.placed.get(i).copied().flatten() else { continue };
        let v = Validity { from: p.lane, to: p.lane };
        if p.road == h.road && p.section == h.section {
            if !validity.contains(&v) {
                validity.push(v);
            }
        } else {
            let (s0, s1) = pl.section_range(p);
            others.push((p.road, SignalReference { id, s: 0.5 * (s0 + s1), t: 0.0, orientation: if p.along { "+" } else { "-" }, validity: vec![v] }));
        }
    }
    (validity, others)
}

fn type_and_subtype(sign_id: &str) -> (String, String) {
    if sign_id.starts_with(|c: char| c.is_ascii_digit()) {
        if let Some((a, b)) = sign_id.split_once('-') {
            return (a.to_string(), b.to_string());
        }
    }
    (sign_id.to_string(), "-1".to_string())
}

/// Adds every sign, light and stop line to the roads; `next_id` numbers the signals that
/// have no CommonRoad id (extra sign elements, stop lines).
pub(crate) fn add_signals(pl: &Places, roads: &mut [Road], next_id: &mut u64, warnings: &mut Vec<Warning>) {
    let net = pl.net;
    // referring lanelets of each sign / light, in network order
    let mut sign_refs: BTreeMap<u64, Vec<usize>> = BTreeMap::new();
    let mut light_refs: BTreeMap<u64, Vec<usize>> = BTreeMap::new();
    for (i, l) in net.lanelets.iter().enumerate() {
        let stop = l.stop_line.as_ref();
        for s in l.traffic_sign_refs.iter().chain(stop.iter().flat_map(|s| s.traffic_sign_refs.iter())) {
            sign_refs.entry(s.get()).or_default().push(i);
        }
        for s in l.traffic_light_refs.iter().chain(stop.iter().flat_map(|s| s.traffic_light_refs.iter())) {
            light_refs.entry(s.get()).or_default().push(i);
        }
    }
    let put = |roads: &mut [Road], spot: &Spot, sig: Signal, refs: Vec<(usize, SignalReference)>, warnings: &mut Vec<Warning>, subject: Subject| {
        if let Some(r) = roads.get_mut(spot.road) {
            r.signals.push(sig);
        }
        // OpenDRIVE says "this signal also applies here" with a <signalReference>, which
        // esmini 3.6 refuses with an error: they are left out, each a warning
        let mut roads_named: Vec<u64> = refs.iter().filter_map(|(road, _)| roads.get(*road).map(|r| r.id)).collect();
        roads_named.dedup();
        if !roads_named.is_empty() {
            let list: Vec<String> = roads_named.iter().map(u64::to_string).collect();
            warnings.push(Warning::new(
                subject,
                format!(
                    "it also applies to lanes of road(s) {}; the signalReference that would say so is not written (esmini 3.6 reports it as an error)",
                    list.join(", ")
                ),
            ));
        }
    };
    for sign in &net.traffic_signs {
        let subject = Subject::TrafficSign(sign.id.get());
        let mut refs = sign_refs.get(&sign.id.get()).cloned().unwrap_or_default();
        refs.retain(|&i| pl.placed.get(i).copied().flatten().is_some());
        refs.dedup();
        let Some(&host) = refs.first() else {
            warnings.push(Warning::new(subject, "no exported lanelet refers to it; not written"));
            continue;
        };
        let at = sign.position.as_ref().map(V2::of).or_else(|| pl.default_at(host, false));
        let Some((spot, moved)) = at.and_then(|a| pl.spot(host, a)) else { continue };
        if moved > 0.05 {
            warnings.push(Warning::new(subject, format!("moved {moved:.2} m along the road into the lane section of lanelet it refers to")));
        }
        if sign.is_virtual {
            warnings.push(Warning::new(subject, "a virtual sign: OpenDRIVE has no virtual signals; written as a real one"));
        }
        let (validity, others) = attach(pl, host, &refs, sign.id.get());
        for (k, el) in sign.elements.iter().enumerate() {
            let (kind, subtype) = type_and_subtype(&el.sign_id);
            let country = if el.sign_id.starts_with(|c: char| c.is_ascii_digit()) {
                Some("DE".to_string())
            } else {
                pl.country.as_deref().and_then(alpha2).map(str::to_string)
            };
            let speed = matches!(kind.as_str(), "274" | "274.1" | "274.2" | "275" | "278");
            let value = el.additional_values.first().and_then(|v| v.trim().parse::<f64>().ok()).filter(|v| v.is_finite());
            let value = match value {
                Some(v) if speed => Some((v * 3.6, "km/h")),
                Some(v) => Some((v, "")),
                None => None,
            };
            if el.additional_values.len() > 1 {
                warnings.push(Warning::new(
                    subject,
                    format!(
                        "sign {} has {} additional values; OpenDRIVE has one value per signal, the first is written",
                        el.sign_id,
                        el.additional_values.len()
                    ),
                ));
            }
            let id = if k == 0 {
                sign.id.get()
            } else {
                let id = *next_id;
                *next_id += 1;
                warnings.push(Warning::new(
                    subject,
                    format!("its element {} ({}) is written as a signal of its own, id {id} (one sign per OpenDRIVE signal)", k + 1, el.sign_id),
                ));
                id
            };
            let sig = Signal { country, kind, subtype, value, ..spot.signal(id, format!("traffic sign {}", sign.id.get()), validity.clone()) };
            put(roads, &spot, sig, if k == 0 { others.clone() } else { Vec::new() }, warnings, subject);
        }
    }
    for light in &net.traffic_lights {
        let subject = Subject::TrafficLight(light.id.get());
        let mut refs = light_refs.get(&light.id.get()).cloned().unwrap_or_default();
        refs.retain(|&i| pl.placed.get(i).copied().flatten().is_some());
        refs.dedup();
        let host = refs.first().copied().or_else(|| {
            // no lanelet refers to it: the lanelet nearest to its position
            let p = light.position.as_ref().map(V2::of)?;
            nearest_lanelet(pl, p)
        });
        let Some(host) = host else {
            warnings.push(Warning::new(subject, "neither a lanelet refers to it nor has it a position; not written"));
            continue;
        };
        let at = light.position.as_ref().map(V2::of).or_else(|| pl.default_at(host, true));
        let Some((spot, moved)) = at.and_then(|a| pl.spot(host, a)) else { continue };
        if moved > 0.05 {
            warnings.push(Warning::new(subject, format!("moved {moved:.2} m along the road into the lane section of the lanelet it controls")));
        }
        if light.direction.is_some_and(|d| d != TrafficLightDirection::All) {
            warnings.push(Warning::new(subject, "its direction (which turns it controls) has no OpenDRIVE attribute; written as a light for all directions"));
        }
        if light.active == Some(false) {
            warnings.push(Warning::new(subject, "it is inactive; OpenDRIVE has no inactive signal, it is written as a light"));
        }
        let (validity, others) = attach(pl, host, &refs, light.id.get());
        let sig = Signal {
            dynamic: true,
            country: Some("OpenDRIVE".into()),
            kind: "1000001".into(),
            ..spot.signal(light.id.get(), format!("traffic light {}", light.id.get()), validity)
        };
        put(roads, &spot, sig, others, warnings, subject);
    }
    for (i, l) in net.lanelets.iter().enumerate() {
        let Some(stop) = &l.stop_line else { continue };
        let Some(p) = pl.placed.get(i).copied().flatten() else { continue };
        let at = match &stop.points {
            Some([a, b]) => mid(a, b),
            None => match (l.bounds.left().last(), l.bounds.right().last()) {
                (Some(a), Some(b)) => mid(a, b),
                _ => continue,
            },
        };
        let Some((spot, _)) = pl.spot(i, at) else { continue };
        let id = *next_id;
        *next_id += 1;
        let validity = vec![Validity { from: p.lane, to: p.lane }];
        let sig = Signal { country: Some("DE".into()), kind: "294".into(), ..spot.signal(id, format!("stop line of lanelet {}", l.id.get()), validity) };
        put(roads, &spot, sig, Vec::new(), warnings, Subject::Lanelet(l.id.get()));
    }
}

fn mid(a: &Point, b: &Point) -> V2 {
    V2::of(a).lerp(V2::of(b), 0.5)
}

fn nearest_lanelet(pl: &Places, p: V2) -> Option<usize> {
    let mut best: Option<(f64, usize)> = None;
    for (i, l) in pl.net.lanelets.iter().enumerate() {
        if pl.placed.get(i).copied().flatten().is_none() {
            continue;
        }
        let c: Vec<V2> = l.bounds.left().iter().zip(l.bounds.right()).map(|(a, b)| mid(a, b)).collect();
        let d = crate::vec2::to_polyline(p, &c);
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, i));
        }
    }
    best.map(|(_, i)| i)
}
