//! Catalogs: directories from CatalogLocations, lookup of a catalog by its `name` or (as esmini
//! does) by file name `<catalogName>.xosc`, and a per-load cache of parsed catalog files.

use crate::error::{Diagnostic, Error, ErrorKind, Location};
use crate::xml::{read_file, Doc, Elem};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

crate::xml_enum! {
    /// The catalog kinds of CatalogLocations.
    CatalogKind {
        Vehicle = "VehicleCatalog", Controller = "ControllerCatalog", Pedestrian = "PedestrianCatalog",
        MiscObject = "MiscObjectCatalog", Environment = "EnvironmentCatalog", Maneuver = "ManeuverCatalog",
        Trajectory = "TrajectoryCatalog", Route = "RouteCatalog",
    }
}

impl CatalogKind {
    pub const ALL: &'static [CatalogKind] = &[
        CatalogKind::Vehicle,
        CatalogKind::Controller,
        CatalogKind::Pedestrian,
        CatalogKind::MiscObject,
        CatalogKind::Environment,
        CatalogKind::Maneuver,
        CatalogKind::Trajectory,
        CatalogKind::Route,
    ];

    /// Element names of the entries this kind holds.
    pub fn entry_elements(self) -> &'static [&'static str] {
        match self {
            CatalogKind::Vehicle => &["Vehicle"],
            CatalogKind::Controller => &["Controller"],
            CatalogKind::Pedestrian => &["Pedestrian"],
            CatalogKind::MiscObject => &["MiscObject"],
            CatalogKind::Environment => &["Environment"],
            CatalogKind::Maneuver => &["Maneuver"],
            CatalogKind::Trajectory => &["Trajectory"],
            CatalogKind::Route => &["Route"],
        }
    }
}

/// Most catalog files one load may open (hostile input guard).
const MAX_FILES: usize = 500;

#[derive(Debug)]
struct Dir {
    kind: CatalogKind,
    path: PathBuf,
}

/// A found entry: the parsed file (shared) and the index of the entry in its Catalog element.
pub(crate) struct Found {
    pub doc: Rc<Doc>,
    pub entry: usize,
}

impl Found {
    pub(crate) fn elem(&self) -> Option<&Elem> {
        self.doc.root.child("Catalog").and_then(|c| c.children().get(self.entry))
    }
}

#[derive(Default)]
pub(crate) struct CatalogStore {
    dirs: Vec<Dir>,
    /// Parsed files by path; `None` for files that failed to parse (reported once).
    files: BTreeMap<PathBuf, Option<Rc<Doc>>>,
    /// Sorted `.xosc` files of each directory.
    listings: BTreeMap<PathBuf, Vec<PathBuf>>,
}

impl CatalogStore {
    /// Registers a CatalogLocations directory. A directory that does not exist falls back to
    /// `<scenario dir>/Catalogs/<last component>` when that exists (esmini finds its bundled
    /// catalogs in such cases); otherwise it is kept and reported.
    pub(crate) fn add_dir(&mut self, kind: CatalogKind, path: PathBuf, scenario_dir: &Path, loc: Location, warnings: &mut Vec<Diagnostic>) {
        let mut path = path;
        if !path.is_dir() {
            let fallback = path.file_name().map(|n| scenario_dir.join("Catalogs").join(n));
            match fallback.filter(|f| f.is_dir()) {
                Some(f) => {
                    warnings.push(Diagnostic {
                        location: loc,
                        message: format!("catalog directory {} does not exist; using {} instead", path.display(), f.display()),
                    });
                    path = f;
                }
                None => warnings.push(Diagnostic { location: loc, message: format!("catalog directory {} does not exist", path.display()) }),
            }
        }
        self.dirs.push(Dir { kind, path });
    }

    /// Whether every registered catalog directory exists (so a catalog not found in them is
    /// named wrongly rather than not shipped).
    pub(crate) fn all_directories_exist(&self) -> bool {
        !self.dirs.is_empty() && self.dirs.iter().all(|d| d.path.is_dir())
    }

    /// The catalog files parsed so far, in path order.
    pub(crate) fn documents(&self) -> impl Iterator<Item = &Doc> + '_ {
        self.files.values().filter_map(|d| d.as_deref())
    }

    fn listing(&mut self, dir: &Path) -> Vec<PathBuf> {
        if let Some(l) = self.listings.get(dir) {
            return l.clone();
        }
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
            .map(|rd| rd.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xosc"))).collect())
            .unwrap_or_default();
        files.sort();
        files.truncate(MAX_FILES);
        self.listings.insert(dir.to_path_buf(), files.clone());
        files
    }

    fn file(&mut self, path: &Path, warnings: &mut Vec<Diagnostic>) -> Result<Option<Rc<Doc>>, Error> {
        if let Some(d) = self.files.get(path) {
            return Ok(d.clone());
        }
        if self.files.len() >= MAX_FILES {
            return Err(Error::new(ErrorKind::Limit, Location::file_only(path), "too many catalog files"));
        }
        let doc = match read_file(path) {
            Ok(d) if d.root.child("Catalog").is_some() => Some(Rc::new(d)),
            Ok(_) => None,
            Err(e) => {
                warnings.push(Diagnostic { location: e.location.clone(), message: format!("catalog file skipped: {}", e.message) });
                None
            }
        };
        self.files.insert(path.to_path_buf(), doc.clone());
        Ok(doc)
    }

    /// Finds `entry` of catalog `catalog` for one of `kinds`. Order: directories of the expected
    /// kinds before the others; in each group, files whose Catalog@name matches, then files
    /// named `<catalog>.xosc`.
    /// `at`: where the reference names the catalog and the entry (for the errors).
    pub(crate) fn find(
        &mut self,
        kinds: &[CatalogKind],
        catalog: &str,
        entry: &str,
        at: (&Location, &Location),
        warnings: &mut Vec<Diagnostic>,
    ) -> Result<Found, Error> {
        let mut groups: Vec<Vec<PathBuf>> = vec![Vec::new(), Vec::new()];
        for d in &self.dirs {
            let g = usize::from(!kinds.contains(&d.kind));
            if !groups[g].contains(&d.path) {
                groups[g].push(d.path.clone());
            }
        }
        let mut catalog_found: Option<PathBuf> = None;
        for dirs in &groups {
            let mut candidates: Vec<PathBuf> = Vec::new();
            for dir in dirs {
                for f in self.listing(dir) {
                    if let Some(doc) = self.file(&f, warnings)? {
                        let name = doc.root.child("Catalog").and_then(|c| c.attr("name")).map(|a| a.value.as_str());
                        if name == Some(catalog) {
                            candidates.push(f);
                        }
                    }
                }
            }
            for dir in dirs {
                let f = dir.join(format!("{catalog}.xosc"));
                if f.is_file() && !candidates.contains(&f) {
                    candidates.push(f);
                }
            }
            for f in candidates {
                let Some(doc) = self.file(&f, warnings)? else { continue };
                catalog_found.get_or_insert_with(|| f.clone());
                let cat = doc.root.child("Catalog");
                let idx = cat.and_then(|c| {
                    // looking for the entry is not reading the others
                    c.children_unmarked().iter().position(|e| e.attrs.iter().any(|a| a.name == "name" && a.value == entry))
                });
                if let Some(i) = idx {
                    return Ok(Found { doc, entry: i });
                }
            }
        }
        match catalog_found {
            Some(f) => {
                Err(Error::new(ErrorKind::MissingCatalogEntry, at.1.clone(), format!("catalog '{catalog}' ({}) has no entry named '{entry}'", f.display())))
            }
            None => {
                let tried: Vec<String> = self
                    .dirs
                    .iter()
                    .map(|d| if d.path.is_dir() { d.path.display().to_string() } else { format!("{} (does not exist)", d.path.display()) })
                    .collect();
                Err(Error::new(
                    ErrorKind::MissingCatalog,
                    at.0.clone(),
                    format!(
                        "catalog '{catalog}' (for entry '{entry}') not found; looked in {}",
                        if tried.is_empty() { "no catalog directories (CatalogLocations is empty)".to_string() } else { tried.join(", ") }
                    ),
                ))
            }
        }
    }
}
