//! XML → typed model. Every error names file, line and column; unmodelled relevant
//! elements become warnings.

mod header;
mod junction;
mod lanes;
mod line_index;
mod objects;
mod plan_view;
mod road;
mod signals;
mod xml;

use crate::error::Error;
use crate::model::header::Header;
use crate::model::junction::{Controller, Junction};
use crate::model::road::Road;
use diagnostic::Diagnostic;
use std::path::Path;
use xml::{elements, irrelevant, Ctx};

/// Hostile-input caps: XML nodes in a document, roads, junctions.
pub(crate) const MAX_XML_NODES: u32 = 20_000_000;
pub(crate) const MAX_ROADS: usize = 1_000_000;
pub(crate) const MAX_JUNCTIONS: usize = 1_000_000;

/// Everything read from the file, before indexing.
pub(crate) struct Parsed {
    pub header: Header,
    pub roads: Vec<Road>,
    pub junctions: Vec<Junction>,
    pub controllers: Vec<Controller>,
    pub warnings: Vec<Diagnostic>,
}

/// Parse OpenDRIVE text; `file` is used in messages only.
pub(crate) fn parse_document(text: &str, file: &Path) -> Result<Parsed, Error> {
    let opts = roxmltree::ParsingOptions { allow_dtd: false, nodes_limit: MAX_XML_NODES, ..Default::default() };
    let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| {
        let diagnostic::LineCol { line, col } = diagnostic::LineCol::of_xml_error(&e, text);
        Error::Xml { file: file.to_path_buf(), line, col, message: e.to_string() }
    })?;
    let mut ctx = Ctx::new(file, &doc);
    let root = doc.root_element();
    if root.tag_name().name() != "OpenDRIVE" {
        return Err(ctx.error(root, format!("expected the root element <OpenDRIVE>, found <{}>", root.tag_name().name())));
    }
    let mut parsed = Parsed { header: Header::default(), roads: Vec::new(), junctions: Vec::new(), controllers: Vec::new(), warnings: Vec::new() };
    let mut saw_header = false;
    for child in elements(root) {
        match child.tag_name().name() {
            "header" => {
                saw_header = true;
                parsed.header = header::parse_header(&mut ctx, child)?;
            }
            "road" => {
                ctx.cap(child, "roads", parsed.roads.len() + 1, MAX_ROADS)?;
                parsed.roads.push(road::parse_road(&mut ctx, child)?);
            }
            "junction" => {
                ctx.cap(child, "junctions", parsed.junctions.len() + 1, MAX_JUNCTIONS)?;
                parsed.junctions.push(junction::parse_junction(&mut ctx, child)?);
            }
            "controller" => parsed.controllers.push(junction::parse_controller(&mut ctx, child)?),
            n if irrelevant(n) => {}
            n => ctx.warn(child, format!("<OpenDRIVE><{n}> is not modelled; ignored")),
        }
    }
    if !saw_header {
        ctx.warn(root, "no <header>; revision 1.4 assumed");
    }
    if let Some(offset) = parsed.header.offset {
        apply_header_offset(&mut parsed.roads, &offset);
    }
    if !(parsed.header.rev_major == 1 && (4..=8).contains(&parsed.header.rev_minor)) {
        ctx.warn(root, format!("OpenDRIVE {}.{} is outside 1.4–1.8; read as 1.8", parsed.header.rev_major, parsed.header.rev_minor));
    }
    // Road and junction ids must be unique: everything else refers to them.
    let mut ids: Vec<(&str, usize)> = parsed.roads.iter().enumerate().map(|(i, r)| (r.id.as_str(), i)).collect();
    ids.sort();
    if let Some(w) = ids.windows(2).find(|w| w[0].0 == w[1].0) {
        let p = parsed.roads.get(w[1].1).map(|r| r.pos).unwrap_or_default();
        return Err(Error::Invalid { file: file.to_path_buf(), line: p.line, col: p.col, message: format!("duplicate road id `{}`", w[1].0) });
    }
    parsed.warnings = ctx.warnings;
    Ok(parsed)
}

/// The header `<offset>` moves the whole road network, as esmini's `OpenDrive::LoadOpenDriveFile`
/// does: every plan-view geometry's start is shifted by (x, y) and then rotated by `hdg` about
/// the origin, its heading turned by `hdg` (into [0, 2π)), and every elevation raised by `z`.
fn apply_header_offset(roads: &mut [crate::model::road::Road], offset: &crate::model::header::HeaderOffset) {
    for road in roads {
        for g in &mut road.geometries {
            let (x, y, _) = offset.apply(g.x, g.y, 0.0);
            g.x = x;
            g.y = y;
            g.set_hdg((g.hdg + offset.hdg).rem_euclid(std::f64::consts::TAU));
        }
        for e in &mut road.elevation {
            e.a += offset.z;
        }
    }
}
