//! `<signals>`.

use super::xml::{children_named, elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::signals::{LaneValidity, Signal, SignalOrientation, SignalReference};
use roxmltree::Node;

/// Hostile-input cap on signals per road.
const MAX_SIGNALS: usize = 1_000_000;

fn validities(ctx: &Ctx, node: Node) -> Result<Vec<LaneValidity>, Error> {
    children_named(node, "validity").map(|v| Ok(LaneValidity { from_lane: ctx.req_i32(v, "fromLane")?, to_lane: ctx.req_i32(v, "toLane")? })).collect()
}

pub(super) fn parse_signals(ctx: &mut Ctx, node: Node, signals: &mut Vec<Signal>, refs: &mut Vec<SignalReference>) -> Result<(), Error> {
    for child in elements(node) {
        match child.tag_name().name() {
            "signal" => {
                ctx.cap(child, "signals in one road", signals.len() + 1, MAX_SIGNALS)?;
                let dynamic = matches!(child.attribute("dynamic").map(str::trim), Some("yes" | "true"));
                signals.push(Signal {
                    id: ctx.req_str(child, "id")?.to_string(),
                    name: ctx.opt_string(child, "name"),
                    s: ctx.req_f64(child, "s")?,
                    t: ctx.req_f64(child, "t")?,
                    z_offset: ctx.f64_or(child, "zOffset", 0.0)?,
                    h_offset: ctx.f64_or(child, "hOffset", 0.0)?,
                    pitch: ctx.f64_or(child, "pitch", 0.0)?,
                    roll: ctx.f64_or(child, "roll", 0.0)?,
                    country: ctx.opt_string(child, "country"),
                    country_revision: ctx.opt_string(child, "countryRevision"),
                    type_raw: child.attribute("type").unwrap_or("-1").to_string(),
                    subtype: ctx.opt_string(child, "subtype"),
                    value: ctx.opt_f64(child, "value")?,
                    unit: ctx.opt_string(child, "unit"),
                    text: ctx.opt_string(child, "text"),
                    dynamic,
                    orientation: SignalOrientation::parse(child.attribute("orientation").unwrap_or("none")),
                    height: ctx.opt_f64(child, "height")?,
                    width: ctx.opt_f64(child, "width")?,
                    validity: validities(ctx, child)?,
                });
                for sub in elements(child) {
                    match sub.tag_name().name() {
                        "validity" | "dependency" | "reference" | "semantics" => {}
                        "positionRoad" | "positionInertial" => {
                            ctx.warn(sub, "signal <positionRoad>/<positionInertial> is not modelled; s/t of the signal used")
                        }
                        n if irrelevant(n) => {}
                        n => ctx.warn(sub, format!("<signal><{n}> is not modelled; ignored")),
                    }
                }
            }
            "signalReference" => refs.push(SignalReference {
                id: ctx.req_str(child, "id")?.to_string(),
                s: ctx.req_f64(child, "s")?,
                t: ctx.req_f64(child, "t")?,
                orientation: SignalOrientation::parse(child.attribute("orientation").unwrap_or("none")),
                validity: validities(ctx, child)?,
            }),
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<signals><{n}> is not modelled; ignored")),
        }
    }
    Ok(())
}
