//! `<junction>` and top-level `<controller>`.

use super::road::contact_point;
use super::xml::{children_named, elements, irrelevant, Ctx};
use crate::error::Error;
use crate::model::junction::{Connection, Control, Controller, Junction, JunctionController, JunctionType, LaneLink};
use roxmltree::Node;

/// Hostile-input cap on connections per junction.
const MAX_CONNECTIONS: usize = 1_000_000;

pub(super) fn parse_junction(ctx: &mut Ctx, node: Node) -> Result<Junction, Error> {
    let kind = match node.attribute("type").map(str::trim) {
        None | Some("default") => JunctionType::Default,
        Some("direct") => JunctionType::Direct,
        Some("virtual") => JunctionType::Virtual,
        Some("crossing") => JunctionType::Crossing,
        Some(other) => {
            ctx.warn(node, format!("unknown junction type `{other}`; treated as default"));
            JunctionType::Default
        }
    };
    let mut j =
        Junction { id: ctx.req_str(node, "id")?.to_string(), name: ctx.opt_string(node, "name"), kind, connections: Vec::new(), controllers: Vec::new() };
    for child in elements(node) {
        match child.tag_name().name() {
            "connection" => {
                ctx.cap(child, "connections in one junction", j.connections.len() + 1, MAX_CONNECTIONS)?;
                let contact = match child.attribute("contactPoint") {
                    Some(raw) => Some(contact_point(ctx, child, raw)?),
                    None => None,
                };
                let mut lane_links = Vec::new();
                for ll in children_named(child, "laneLink") {
                    lane_links.push(LaneLink { from: ctx.req_i32(ll, "from")?, to: ctx.req_i32(ll, "to")? });
                }
                let conn = Connection {
                    id: ctx.opt_string(child, "id").unwrap_or_default(),
                    incoming_road: ctx.opt_string(child, "incomingRoad"),
                    connecting_road: ctx.opt_string(child, "connectingRoad"),
                    linked_road: ctx.opt_string(child, "linkedRoad"),
                    contact_point: contact,
                    lane_links,
                };
                if conn.target_road().is_none() {
                    ctx.warn(child, "connection has neither connectingRoad nor linkedRoad; ignored");
                } else {
                    j.connections.push(conn);
                }
            }
            "controller" => j.controllers.push(JunctionController {
                id: ctx.req_str(child, "id")?.to_string(),
                kind: ctx.opt_string(child, "type"),
                sequence: ctx.opt_i32(child, "sequence")?.map(|v| v.max(0) as u32),
            }),
            "priority" | "surface" => {}
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<junction><{n}> is not modelled; ignored")),
        }
    }
    Ok(j)
}

pub(super) fn parse_controller(ctx: &mut Ctx, node: Node) -> Result<Controller, Error> {
    let mut controls = Vec::new();
    for c in children_named(node, "control") {
        controls.push(Control { signal_id: ctx.req_str(c, "signalId")?.to_string(), kind: ctx.opt_string(c, "type") });
    }
    Ok(Controller {
        id: ctx.req_str(node, "id")?.to_string(),
        name: ctx.opt_string(node, "name"),
        sequence: ctx.opt_i32(node, "sequence")?.map(|v| v.max(0) as u32),
        controls,
    })
}
