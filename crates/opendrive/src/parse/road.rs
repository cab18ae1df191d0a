//! `<road>`: attributes, links, types, plan view, profiles, lanes, objects, signals.

use super::lanes::{cubic, parse_lanes, parse_speed_value, sort_records};
use super::objects::parse_objects;
use super::plan_view::parse_plan_view;
use super::signals::parse_signals;
use super::xml::{elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::road::{ContactPoint, ElementDir, ElementType, Road, RoadKind, RoadLink, RoadTypeRecord, SpeedLimit, TrafficRule};
use roxmltree::Node;

pub(super) fn contact_point(ctx: &Ctx, node: Node, raw: &str) -> Result<ContactPoint, Error> {
    match raw.trim() {
        "start" => Ok(ContactPoint::Start),
        "end" => Ok(ContactPoint::End),
        other => Err(ctx.error(node, format!("contactPoint: expected `start` or `end`, found `{other}`"))),
    }
}

fn parse_link(ctx: &mut Ctx, node: Node) -> Result<RoadLink, Error> {
    let element_type = match ctx.req_str(node, "elementType")?.trim() {
        "road" => ElementType::Road,
        "junction" => ElementType::Junction,
        other => return Err(ctx.error(node, format!("elementType: expected `road` or `junction`, found `{other}`"))),
    };
    let contact = match node.attribute("contactPoint") {
        Some(raw) => Some(contact_point(ctx, node, raw)?),
        None => None,
    };
    if element_type == ElementType::Road && contact.is_none() {
        ctx.warn(node, "road link without contactPoint; the link is assumed to meet the other road's start");
    }
    let element_dir = match node.attribute("elementDir").map(str::trim) {
        Some("+") => Some(ElementDir::Plus),
        Some("-") => Some(ElementDir::Minus),
        _ => None,
    };
    Ok(RoadLink {
        element_type,
        element_id: ctx.req_str(node, "elementId")?.to_string(),
        contact_point: contact,
        element_s: ctx.opt_f64(node, "elementS")?,
        element_dir,
    })
}

pub(super) fn parse_road(ctx: &mut Ctx, node: Node) -> Result<Road, Error> {
    let rule = match node.attribute("rule").map(|r| r.trim().to_ascii_uppercase()) {
        None => TrafficRule::RightHand,
        Some(r) if r == "RHT" => TrafficRule::RightHand,
        Some(r) if r == "LHT" => TrafficRule::LeftHand,
        Some(r) => {
            ctx.warn(node, format!("road rule `{r}` is neither RHT nor LHT; RHT assumed"));
            TrafficRule::RightHand
        }
    };
    let junction = node.attribute("junction").map(str::trim).filter(|j| !j.is_empty() && *j != "-1").map(str::to_string);
    let length = ctx.req_f64(node, "length")?;
    if length < 0.0 {
        return Err(ctx.error(node, format!("road length must not be negative, found {length}")));
    }
    let mut road = Road {
        id: ctx.req_str(node, "id")?.to_string(),
        name: node.attribute("name").unwrap_or("").to_string(),
        length,
        junction,
        rule,
        types: Vec::new(),
        predecessor: None,
        successor: None,
        geometries: Vec::new(),
        elevation: Vec::new(),
        superelevation: Vec::new(),
        lane_offsets: Vec::new(),
        lane_sections: Vec::new(),
        objects: Vec::new(),
        signals: Vec::new(),
        signal_references: Vec::new(),
        pos: ctx.pos(node),
        lane0_osi: std::sync::OnceLock::new(),
        raised_lanes: std::sync::OnceLock::new(),
    };
    let mut saw_plan_view = false;
    let mut saw_lanes = false;
    for child in elements(node) {
        match child.tag_name().name() {
            "link" => {
                for l in elements(child) {
                    match l.tag_name().name() {
                        "predecessor" => road.predecessor = Some(parse_link(ctx, l)?),
                        "successor" => road.successor = Some(parse_link(ctx, l)?),
                        "neighbor" => ctx.warn(l, "<road><link><neighbor> is not modelled; ignored"),
                        n if irrelevant(n) => {}
                        n => ctx.warn(l, format!("<road><link><{n}> is not modelled; ignored")),
                    }
                }
            }
            "type" => {
                let raw = ctx.req_str(child, "type")?.to_string();
                let kind = RoadKind::parse(&raw);
                if kind == RoadKind::Other {
                    ctx.warn(child, format!("unknown road type `{raw}`"));
                }
                let speed = match elements(child).find(|n| n.tag_name().name() == "speed") {
                    Some(sp) => {
                        let max_raw = ctx.req_str(sp, "max")?.to_string();
                        let unit = ctx.opt_string(sp, "unit");
                        Some(SpeedLimit { max_mps: parse_speed_value(&max_raw, unit.as_deref()), max_raw, unit })
                    }
                    None => None,
                };
                road.types.push(RoadTypeRecord { s: ctx.req_f64(child, "s")?, kind, raw, country: ctx.opt_string(child, "country"), speed });
            }
            "planView" => {
                saw_plan_view = true;
                road.geometries = parse_plan_view(ctx, child)?;
            }
            "elevationProfile" => {
                for e in elements(child) {
                    match e.tag_name().name() {
                        "elevation" => road.elevation.push(cubic(ctx, e, "s")?),
                        n if irrelevant(n) => {}
                        n => ctx.warn(e, format!("<elevationProfile><{n}> is not modelled; ignored")),
                    }
                }
            }
            "lateralProfile" => {
                for e in elements(child) {
                    match e.tag_name().name() {
                        "superelevation" => {
                            let rec = cubic(ctx, e, "s")?;
                            if rec.a != 0.0 || rec.b != 0.0 || rec.c != 0.0 || rec.d != 0.0 {
                                // The engine banks the road with it (esmini's Track2XYZ); only the
                                // flat 2D geometry built here leaves lateral offsets unturned.
                                ctx.warn(
                                    e,
                                    "non-zero superelevation: the simulation banks the road, but lanelet borders \
                                     and OSI lane points lay lane offsets flat (not shortened by the roll)",
                                );
                            }
                            road.superelevation.push(rec);
                        }
                        n @ ("crossfall" | "shape") => ctx.warn(e, format!("<lateralProfile><{n}> is not modelled; ignored")),
                        n if irrelevant(n) => {}
                        n => ctx.warn(e, format!("<lateralProfile><{n}> is not modelled; ignored")),
                    }
                }
            }
            "lanes" => {
                saw_lanes = true;
                let (offsets, sections) = parse_lanes(ctx, child)?;
                road.lane_offsets = offsets;
                road.lane_sections = sections;
            }
            "objects" => parse_objects(ctx, child, &mut road.objects)?,
            "signals" => parse_signals(ctx, child, &mut road.signals, &mut road.signal_references)?,
            "railroad" => ctx.warn(child, "<railroad> is not modelled; ignored"),
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<road><{n}> is not modelled; ignored")),
        }
    }
    if !saw_plan_view || road.geometries.is_empty() {
        return Err(ctx.error(node, format!("road `{}` needs a <planView> with at least one <geometry>", road.id)));
    }
    if !saw_lanes || road.lane_sections.is_empty() {
        return Err(ctx.error(node, format!("road `{}` needs <lanes> with at least one <laneSection>", road.id)));
    }
    road.types.sort_by(|a, b| a.s.total_cmp(&b.s));
    sort_records(&mut road.elevation);
    sort_records(&mut road.superelevation);
    Ok(road)
}
