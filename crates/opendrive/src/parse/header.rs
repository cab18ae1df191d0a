//! `<header>`.

use super::xml::{elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::header::{Header, HeaderOffset};
use roxmltree::Node;

pub(super) fn parse_header(ctx: &mut Ctx, node: Node) -> Result<Header, Error> {
    let mut h = Header {
        rev_major: ctx.opt_i32(node, "revMajor")?.unwrap_or(1).max(0) as u32,
        rev_minor: ctx.opt_i32(node, "revMinor")?.unwrap_or(4).max(0) as u32,
        name: ctx.opt_string(node, "name"),
        version: ctx.opt_string(node, "version"),
        date: ctx.opt_string(node, "date"),
        vendor: ctx.opt_string(node, "vendor"),
        north: ctx.opt_f64(node, "north")?,
        south: ctx.opt_f64(node, "south")?,
        east: ctx.opt_f64(node, "east")?,
        west: ctx.opt_f64(node, "west")?,
        geo_reference: None,
        offset: None,
    };
    for child in elements(node) {
        match child.tag_name().name() {
            "geoReference" => {
                let text: String = child.descendants().filter(|n| n.is_text()).filter_map(|n| n.text()).collect();
                h.geo_reference = Some(text.trim().to_string());
            }
            "offset" => {
                h.offset = Some(HeaderOffset {
                    x: ctx.f64_or(child, "x", 0.0)?,
                    y: ctx.f64_or(child, "y", 0.0)?,
                    z: ctx.f64_or(child, "z", 0.0)?,
                    hdg: ctx.f64_or(child, "hdg", 0.0)?,
                });
            }
            "license" => {}
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<header><{n}> is not modelled; ignored")),
        }
    }
    Ok(h)
}
