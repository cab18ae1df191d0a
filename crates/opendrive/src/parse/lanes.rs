//! `<lanes>`: lane offsets, lane sections, lanes.

use super::xml::{children_named, elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::lanes::{Lane, LaneChange, LaneHeight, LaneSection, LaneSpeed, LaneType, RoadMark, RoadMarkType};
use crate::model::poly::CubicRecord;
use roxmltree::Node;

/// Hostile-input caps.
const MAX_SECTIONS: usize = 1_000_000;
const MAX_LANES_PER_SIDE: usize = 1_000;

/// Parse a cubic record whose start attribute is `s_attr` (`s` or `sOffset`).
pub(super) fn cubic(ctx: &Ctx, node: Node, s_attr: &str) -> Result<CubicRecord, Error> {
    Ok(CubicRecord {
        s: ctx.req_f64(node, s_attr)?,
        a: ctx.req_f64(node, "a")?,
        b: ctx.req_f64(node, "b")?,
        c: ctx.req_f64(node, "c")?,
        d: ctx.req_f64(node, "d")?,
    })
}

pub(super) fn sort_records(v: &mut [CubicRecord]) {
    v.sort_by(|a, b| a.s.total_cmp(&b.s));
}

/// Parse `<lanes>` into (lane offsets, lane sections).
pub(super) fn parse_lanes(ctx: &mut Ctx, node: Node) -> Result<(Vec<CubicRecord>, Vec<LaneSection>), Error> {
    let mut offsets = Vec::new();
    let mut sections = Vec::new();
    for child in elements(node) {
        match child.tag_name().name() {
            "laneOffset" => offsets.push(cubic(ctx, child, "s")?),
            "laneSection" => {
                ctx.cap(child, "lane sections in one road", sections.len() + 1, MAX_SECTIONS)?;
                sections.push(parse_section(ctx, child)?);
            }
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<lanes><{n}> is not modelled; ignored")),
        }
    }
    sort_records(&mut offsets);
    sections.sort_by(|a: &LaneSection, b| a.s.total_cmp(&b.s));
    Ok((offsets, sections))
}

fn parse_section(ctx: &mut Ctx, node: Node) -> Result<LaneSection, Error> {
    let mut sec = LaneSection {
        s: ctx.req_f64(node, "s")?,
        single_side: ctx.opt_bool(node, "singleSide"),
        left: Vec::new(),
        center: None,
        right: Vec::new(),
        pos: ctx.pos(node),
    };
    for side in elements(node) {
        let name = side.tag_name().name();
        if !matches!(name, "left" | "center" | "right") {
            if !irrelevant(name) {
                ctx.warn(side, format!("<laneSection><{name}> is not modelled; ignored"));
            }
            continue;
        }
        for ln in children_named(side, "lane") {
            let lane = parse_lane(ctx, ln)?;
            let ok_side = match name {
                "left" => lane.id > 0,
                "right" => lane.id < 0,
                _ => lane.id == 0,
            };
            if !ok_side {
                return Err(ctx.error(ln, format!("lane id {} does not belong in <{name}>", lane.id)));
            }
            match name {
                "left" => sec.left.push(lane),
                "right" => sec.right.push(lane),
                _ => sec.center = Some(lane),
            }
            ctx.cap(ln, "lanes on one side", sec.left.len().max(sec.right.len()), MAX_LANES_PER_SIDE)?;
        }
    }
    sec.left.sort_by_key(|l| l.id);
    sec.right.sort_by_key(|l| -l.id);
    for side in [&sec.left, &sec.right] {
        if side.windows(2).any(|w| w[0].id == w[1].id) {
            return Err(ctx.error(node, "duplicate lane id in lane section"));
        }
    }
    Ok(sec)
}

fn speed_mps(max_raw: &str, unit: Option<&str>) -> Option<f64> {
    let v: f64 = max_raw.trim().parse().ok().filter(|v: &f64| v.is_finite())?;
    let factor = match unit.map(str::trim) {
        Some("km/h") => 1.0 / 3.6,
        Some("mph") => 0.44704,
        _ => 1.0,
    };
    Some(v * factor)
}

/// Speed limit in m/s from `max` and `unit` (m/s when no unit); None for "no limit".
pub(super) fn parse_speed_value(max_raw: &str, unit: Option<&str>) -> Option<f64> {
    speed_mps(max_raw, unit)
}

fn parse_lane(ctx: &mut Ctx, node: Node) -> Result<Lane, Error> {
    let type_raw = node.attribute("type").unwrap_or("none").to_string();
    let mut lane = Lane {
        id: ctx.req_i32(node, "id")?,
        kind: LaneType::parse(&type_raw),
        type_raw,
        level: ctx.opt_bool(node, "level").unwrap_or(false),
        predecessors: Vec::new(),
        successors: Vec::new(),
        widths: Vec::new(),
        borders: Vec::new(),
        road_marks: Vec::new(),
        speeds: Vec::new(),
        heights: Vec::new(),
        pos: ctx.pos(node),
    };
    if lane.kind == LaneType::Other {
        ctx.warn(node, format!("unknown lane type `{}`", lane.type_raw));
    }
    for child in elements(node) {
        match child.tag_name().name() {
            "link" => {
                for l in elements(child) {
                    match l.tag_name().name() {
                        "predecessor" => lane.predecessors.push(ctx.req_i32(l, "id")?),
                        "successor" => lane.successors.push(ctx.req_i32(l, "id")?),
                        n if irrelevant(n) => {}
                        n => ctx.warn(l, format!("<lane><link><{n}> is not modelled; ignored")),
                    }
                }
            }
            "width" => lane.widths.push(cubic(ctx, child, "sOffset")?),
            "border" => lane.borders.push(cubic(ctx, child, "sOffset")?),
            "roadMark" => lane.road_marks.push(parse_road_mark(ctx, child)?),
            "speed" => {
                let max_raw = ctx.req_str(child, "max")?.to_string();
                let unit = ctx.opt_string(child, "unit");
                lane.speeds.push(LaneSpeed { s_offset: ctx.f64_or(child, "sOffset", 0.0)?, max_mps: speed_mps(&max_raw, unit.as_deref()), max_raw, unit });
            }
            "height" => {
                let h = LaneHeight {
                    s_offset: ctx.f64_or(child, "sOffset", 0.0)?,
                    inner: ctx.f64_or(child, "inner", 0.0)?,
                    outer: ctx.f64_or(child, "outer", 0.0)?,
                };
                // kept sorted as esmini inserts them (Lane::AddLaneHeight): after equal ones
                let at = lane.heights.partition_point(|e| e.s_offset <= h.s_offset);
                lane.heights.insert(at, h);
            }
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<lane><{n}> is not modelled; ignored")),
        }
    }
    if !lane.widths.is_empty() && !lane.borders.is_empty() {
        ctx.warn(node, "lane has both <width> and <border>; <width> is used as the standard says");
    }
    if lane.id != 0 && lane.widths.is_empty() && lane.borders.is_empty() {
        ctx.warn(node, format!("lane {} has neither <width> nor <border>; width 0", lane.id));
    }
    sort_records(&mut lane.widths);
    sort_records(&mut lane.borders);
    lane.road_marks.sort_by(|a, b| a.s_offset.total_cmp(&b.s_offset));
    Ok(lane)
}

fn parse_road_mark(ctx: &mut Ctx, node: Node) -> Result<RoadMark, Error> {
    let type_raw = node.attribute("type").unwrap_or("none").to_string();
    let kind = RoadMarkType::parse(&type_raw);
    if kind == RoadMarkType::Other {
        ctx.warn(node, format!("unknown road mark type `{type_raw}`"));
    }
    let lane_change = node.attribute("laneChange").and_then(|v| match v.trim().to_ascii_lowercase().as_str() {
        "increase" => Some(LaneChange::Increase),
        "decrease" => Some(LaneChange::Decrease),
        "both" => Some(LaneChange::Both),
        "none" => Some(LaneChange::None),
        _ => None,
    });
    Ok(RoadMark {
        s_offset: ctx.f64_or(node, "sOffset", 0.0)?,
        kind,
        type_raw,
        weight: ctx.opt_string(node, "weight"),
        color: ctx.opt_string(node, "color"),
        material: ctx.opt_string(node, "material"),
        width: ctx.opt_f64(node, "width")?,
        height: ctx.opt_f64(node, "height")?,
        lane_change,
        lines: node
            .children()
            .filter(|c| c.has_tag_name("type") || c.has_tag_name("explicit"))
            .map(|c| c.children().filter(|l| l.has_tag_name("line")).count())
            .sum(),
    })
}
