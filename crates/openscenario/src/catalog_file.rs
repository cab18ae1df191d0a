//! A catalog file read on its own (every entry resolved with its default parameter values).

use crate::attr::Cx;
use crate::catalog::CatalogKind;
use crate::error::Error;
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

pub(crate) fn read_catalog_file(r: &mut Reader, file: &Arc<Path>, cat: &Elem) -> Result<CatalogFile, Error> {
    // A catalog read on its own may refer to other entries of its own directory (esmini's
    // vehicle catalog does, for trailers).
    if let Some(dir) = file.parent() {
        for kind in CatalogKind::ALL {
            r.catalogs.add_dir(*kind, dir.to_path_buf(), dir, crate::error::Location::file_only(file), &mut r.warnings);
        }
    }
    let scope = Scope::default();
    let cx = Cx::new(file.clone(), &scope);
    let mut entries = Vec::new();
    for e in cat.children() {
        if let Some(entry) = crate::read::read_catalog_entry(r, &cx, e)? {
            entries.push(entry);
        }
    }
    Ok(CatalogFile { name: cx.opt_text(cat, "name")?.unwrap_or_default(), entries })
}
