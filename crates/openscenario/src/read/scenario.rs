//! The scenario definition at the top of an OpenSCENARIO file.

use super::entity::read_entities;
use super::storyboard::read_storyboard;
use super::Reader;
use crate::attr::{Cx, Record};
use crate::catalog::CatalogKind;
use crate::error::{Diagnostic, Error};
use crate::model::*;
use crate::params::{read_declarations, ParameterDeclaration, Scope};
use crate::xml::Elem;
use std::path::{Path, PathBuf};

/// Reads a scenario root (`OpenSCENARIO` with a Storyboard). `overrides` replace the values
/// of global parameters.
pub(crate) fn read_scenario(
    r: &mut Reader,
    record: &Record,
    path: &Path,
    file: &std::sync::Arc<Path>,
    root: &Elem,
    overrides: &[(String, String)],
) -> Result<Scenario, Error> {
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let empty = Scope::default();
    let decls = root.child("ParameterDeclarations");
    let parameters = read_declarations(decls, &empty, overrides, file, &mut r.warnings)?;
    for (name, _) in overrides {
        if !parameters.iter().any(|p| &p.name == name) {
            r.problems.push(Diagnostic {
                location: crate::error::Location::file_only(path),
                message: format!("parameter '{name}' given as an override (a distribution's run or --param) is not declared by the scenario"),
            });
        }
    }
    let scope = Scope { params: parameters.clone(), parent: None };
    let cx = Cx::new(file.clone(), &scope, record);
    let variables: Vec<ParameterDeclaration> = read_declarations(root.child("VariableDeclarations"), &scope, &[], file, &mut r.warnings)?;

    if let Some(cl) = root.child("CatalogLocations") {
        for k in cl.children() {
            let Some(kind) = crate::attr::parse_enum::<CatalogKind>(&k.name) else {
                r.unsupported(&cx, k, "CatalogLocations");
                continue;
            };
            let _ = kind.entry_elements();
            for d in k.children_named("Directory") {
                let p = crate::error::absolute(&dir.join(cx.text(d, "path")?));
                r.catalogs.add_dir(kind, p, &dir, cx.loc(d.pos), &mut r.warnings);
            }
        }
    }

    let header = match root.child("FileHeader") {
        Some(h) => FileHeader {
            rev_major: cx.u32_or(h, "revMajor", 1)?,
            rev_minor: cx.u32_or(h, "revMinor", 0)?,
            date: cx.opt_text(h, "date")?.unwrap_or_default(),
            description: cx.opt_text(h, "description")?.unwrap_or_default(),
            author: cx.opt_text(h, "author")?.unwrap_or_default(),
        },
        None => {
            r.warn(cx.loc(root.pos), "no FileHeader; assuming OpenSCENARIO 1.0");
            FileHeader { rev_major: 1, rev_minor: 0, date: String::new(), description: String::new(), author: String::new() }
        }
    };

    record.rev_minor.set(Some(header.rev_minor));

    let road_network = read_road_network(r, &cx, root.child("RoadNetwork"), &dir)?;
    let (entities, entity_selections) = match root.child("Entities") {
        Some(e) => read_entities(r, &cx, e)?,
        None => (Vec::new(), Vec::new()),
    };
    let storyboard = read_storyboard(r, &cx, cx.child(root, "Storyboard")?)?;
    for c in root.children() {
        if !matches!(
            c.name.as_str(),
            "FileHeader" | "ParameterDeclarations" | "VariableDeclarations" | "CatalogLocations" | "RoadNetwork" | "Entities" | "Storyboard"
        ) {
            r.unsupported(&cx, c, "OpenSCENARIO");
        }
    }
    Ok(Scenario { path: path.to_path_buf(), header, parameters, variables, road_network, entities, entity_selections, storyboard, reference_sites: Vec::new() })
}

fn read_road_network(r: &mut Reader, cx: &Cx, e: Option<&Elem>, dir: &Path) -> Result<RoadNetwork, Error> {
    let mut rn = RoadNetwork { logic_file: None, logic_file_at: None, scene_graph_file: None, traffic_signal_controllers: Vec::new(), used_area: Vec::new() };
    let Some(e) = e else { return Ok(rn) };
    if let Some(f) = e.child("LogicFile") {
        let raw = cx.text(f, "filepath")?;
        rn.logic_file_at = Some(cx.loc(f.pos));
        let p = crate::error::absolute(&dir.join(&raw));
        rn.logic_file = Some(if p.is_file() {
            p
        } else {
            match find_by_file_name(&p, dir) {
                Some(found) => {
                    r.warn(cx.loc(f.pos), format!("road network {} not found; using {} (same file name)", p.display(), found.display()));
                    found
                }
                None => {
                    r.warn(cx.loc(f.pos), format!("road network {} not found", p.display()));
                    p
                }
            }
        });
    }
    if let Some(f) = e.child("SceneGraphFile") {
        rn.scene_graph_file = Some(crate::error::absolute(&dir.join(cx.text(f, "filepath")?)));
    }
    if let Some(ts) = e.child("TrafficSignals") {
        for c in ts.children_named("TrafficSignalController") {
            let mut phases = Vec::new();
            for p in c.children_named("Phase") {
                phases.push(Phase {
                    name: cx.opt_text(p, "name")?.unwrap_or_default(),
                    duration: cx.f64(p, "duration")?,
                    states: p
                        .children_named("TrafficSignalState")
                        .map(|s| Ok((cx.reference(s, "trafficSignalId")?, cx.text(s, "state")?)))
                        .collect::<Result<_, Error>>()?,
                    group_state: p.child("TrafficSignalGroupState").map(|g| cx.text(g, "state")).transpose()?,
                });
            }
            rn.traffic_signal_controllers.push(TrafficSignalController {
                name: cx.text(c, "name")?,
                delay: cx.opt_f64(c, "delay")?,
                reference: cx.opt_reference(c, "reference")?,
                phases,
                origin: cx.loc(c.pos),
            });
        }
    }
    if let Some(ua) = e.child("UsedArea") {
        for p in ua.children_named("Position") {
            if let Some(w) = p.child("WorldPosition") {
                rn.used_area.push((cx.f64(w, "x")?, cx.f64(w, "y")?));
            }
        }
    }
    Ok(rn)
}

/// esmini finds a road network whose path does not exist by its file name in the scenario's
/// directory or a sibling `xodr` directory.
fn find_by_file_name(p: &Path, dir: &Path) -> Option<PathBuf> {
    // Windows paths ("c:/a/b.xodr" or "c:\\a\\b.xodr") have no file_name on Unix when they use '\\'.
    let text = p.to_string_lossy();
    let name = text.rsplit(['/', '\\']).next()?;
    [dir.join(name), crate::error::absolute(&dir.join("../xodr").join(name))].into_iter().find(|c| c.is_file())
}
