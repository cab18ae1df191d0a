//! `<objects>`.

use super::xml::{elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::objects::{Object, ObjectRepeat, RepeatEnds};
use roxmltree::Node;

/// Hostile-input cap on objects per road.
const MAX_OBJECTS: usize = 1_000_000;

pub(super) fn parse_objects(ctx: &mut Ctx, node: Node, out: &mut Vec<Object>) -> Result<(), Error> {
    for child in elements(node) {
        match child.tag_name().name() {
            "object" => {
                ctx.cap(child, "objects in one road", out.len() + 1, MAX_OBJECTS)?;
                out.push(parse_object(ctx, child)?);
            }
            n @ ("objectReference" | "tunnel" | "bridge") => ctx.warn(child, format!("<objects><{n}> is not modelled; ignored")),
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<objects><{n}> is not modelled; ignored")),
        }
    }
    Ok(())
}

fn parse_object(ctx: &mut Ctx, node: Node) -> Result<Object, Error> {
    let mut o = Object {
        id: ctx.req_str(node, "id")?.to_string(),
        name: ctx.opt_string(node, "name"),
        type_raw: ctx.opt_string(node, "type"),
        subtype: ctx.opt_string(node, "subtype"),
        dynamic: ctx.opt_bool(node, "dynamic"),
        s: ctx.req_f64(node, "s")?,
        t: ctx.req_f64(node, "t")?,
        z_offset: ctx.f64_or(node, "zOffset", 0.0)?,
        hdg: ctx.opt_f64(node, "hdg")?,
        pitch: ctx.opt_f64(node, "pitch")?,
        roll: ctx.opt_f64(node, "roll")?,
        length: ctx.opt_f64(node, "length")?,
        width: ctx.opt_f64(node, "width")?,
        radius: ctx.opt_f64(node, "radius")?,
        height: ctx.opt_f64(node, "height")?,
        valid_length: ctx.opt_f64(node, "validLength")?,
        orientation: ctx.opt_string(node, "orientation"),
        repeats: Vec::new(),
        has_outline: false,
    };
    for child in elements(node) {
        match child.tag_name().name() {
            "repeat" => o.repeats.push(ObjectRepeat {
                s: ctx.req_f64(child, "s")?,
                length: ctx.req_f64(child, "length")?,
                distance: ctx.f64_or(child, "distance", 0.0)?,
                t: repeat_ends(ctx, child, "t")?,
                width: repeat_ends(ctx, child, "width")?,
                height: repeat_ends(ctx, child, "height")?,
                z_offset: repeat_ends(ctx, child, "zOffset")?,
                object_length: repeat_ends(ctx, child, "length")?,
                radius: repeat_ends(ctx, child, "radius")?,
            }),
            "outline" | "outlines" => {
                if !o.has_outline {
                    ctx.warn(child, format!("outline of object `{}` is not modelled; ignored", o.id));
                }
                o.has_outline = true;
            }
            "validity" | "parkingSpace" | "markings" | "borders" | "skeleton" => {}
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<object><{n}> is not modelled; ignored")),
        }
    }
    Ok(o)
}

/// The attributes `<name>Start` and `<name>End` of a `<repeat>`.
fn repeat_ends(ctx: &Ctx, node: Node, name: &str) -> Result<RepeatEnds, Error> {
    Ok(RepeatEnds { start: ctx.opt_f64(node, &format!("{name}Start"))?, end: ctx.opt_f64(node, &format!("{name}End"))? })
}
