//! A catalog file read on its own (every entry resolved with its default parameter values).

use crate::attr::{Cx, Record};
use crate::catalog::CatalogKind;
use crate::error::{Error, ErrorKind};
use crate::model::*;
use crate::params::Scope;
use crate::read::Reader;
use crate::xml::Elem;
use serde::Serialize;
use std::path::Path;
use std::sync::Arc;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CatalogFile {
    pub name: String,
    pub entries: Vec<CatalogEntry>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum CatalogEntry {
    Object(EntityObject),
    Controller(Controller),
    Environment(Environment),
    Maneuver(Maneuver),
    Trajectory(Trajectory),
    Route(Route),
}

pub(crate) fn read_catalog_file(r: &mut Reader, record: &Record, file: &Arc<Path>, cat: &Elem) -> Result<CatalogFile, Error> {
    // A catalog read on its own may refer to other entries of its own directory (esmini's
    // vehicle catalog does, for trailers).
    if let Some(dir) = file.parent() {
        for kind in CatalogKind::ALL {
            r.catalogs.add_dir(*kind, dir.to_path_buf(), dir, crate::error::Location::file_only(file), &mut r.warnings);
        }
    }
    let scope = Scope::default();
    let cx = Cx::new(file.clone(), &scope, record);
    let mut entries = Vec::new();
    for e in cat.children() {
        match crate::read::read_catalog_entry(r, &cx, e) {
            Ok(Some(entry)) => entries.push(entry),
            Ok(None) => {}
            // An entry may use parameters that only the scenario referring to it declares (esmini
            // resolves them in the referring scope): read alone, it cannot be resolved, which is
            // not a fault of the file. The schema pass says where each such parameter is used.
            Err(err) if err.kind == ErrorKind::UndeclaredParameter => {
                e.announce();
                let name = e.attrs.iter().find(|a| a.name == "name").map_or("", |a| a.value.as_str());
                r.warn(
                    err.location.clone(),
                    format!("catalog entry '{name}' is not read alone: {} (a scenario that uses the entry must declare it)", err.message),
                );
            }
            Err(err) => return Err(err),
        }
    }
    Ok(CatalogFile { name: cx.opt_text(cat, "name")?.unwrap_or_default(), entries })
}
