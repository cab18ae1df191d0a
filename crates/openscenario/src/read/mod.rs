//! Reading the positioned XML tree into the model, resolving parameters and catalogs.

mod action;
mod condition;
mod entity;
mod environment;
mod global_action;
mod position;
mod scenario;
mod storyboard;
mod trajectory;

pub(crate) use scenario::read_scenario;

use crate::attr::Cx;
use crate::catalog::{CatalogKind, CatalogStore};
use crate::error::{Diagnostic, Error, ErrorKind, Location};
use crate::params::{read_declarations, ParameterDeclaration, Scope};
use crate::xml::Elem;

/// Deepest chain of catalog references (an entry referring to another catalog, ...).
const MAX_CATALOG_DEPTH: usize = 16;

pub(crate) struct Reader {
    pub warnings: Vec<Diagnostic>,
    /// What a strict reading rejects (see `Loaded::problems`).
    pub problems: Vec<Diagnostic>,
    pub catalogs: CatalogStore,
    catalog_depth: usize,
    /// `LoadOptions::go_on_without_catalogs`.
    pub go_on_without_catalogs: bool,
}

impl Reader {
    pub(crate) fn new() -> Self {
        Reader { warnings: Vec::new(), problems: Vec::new(), catalogs: CatalogStore::default(), catalog_depth: 0, go_on_without_catalogs: false }
    }

    pub(crate) fn warn(&mut self, location: Location, message: impl Into<String>) {
        self.warnings.push(Diagnostic { location, message: message.into() });
    }

    /// Records an element the model does not represent yet.
    pub(crate) fn unsupported(&mut self, cx: &Cx, e: &Elem, parent: &str) {
        e.announce();
        self.warn(cx.loc(e.pos), format!("<{}> in {parent} is not supported yet; it is kept as a placeholder", e.name));
    }

    /// Declarations of an entry (Vehicle, Maneuver, ...) resolved with `assignments`, and the
    /// scope they open inside `cx`'s (the entry is read in `cx.scoped(&scope)`).
    pub(crate) fn declarations<'s>(
        &mut self,
        cx: &Cx<'s>,
        e: &Elem,
        assignments: &[(String, String)],
    ) -> Result<(Vec<ParameterDeclaration>, Scope<'s>), Error> {
        // an assignment that matches no declaration is said where it is written (`catalog_entry`)
        let parameters = read_declarations(e.child("ParameterDeclarations"), cx.scope, assignments, &cx.file, &mut self.warnings)?;
        Ok((parameters.clone(), cx.scope.child(parameters)))
    }

    /// Resolves a CatalogReference element and reads the entry with `read`, which receives the
    /// catalog's context (its file, a scope whose parent is the referring scope), the entry
    /// element and the resolved parameter assignments.
    pub(crate) fn catalog_entry<T>(
        &mut self,
        cx: &Cx,
        reference: &Elem,
        kinds: &[CatalogKind],
        read: impl FnOnce(&mut Reader, &Cx, &Elem, &[(String, String)]) -> Result<T, Error>,
    ) -> Result<T, Error> {
        let catalog = cx.reference(reference, "catalogName")?;
        let entry = cx.reference(reference, "entryName")?;
        let mut assignments = Vec::new();
        let mut assigned_at = Vec::new();
        if let Some(pa) = reference.child("ParameterAssignments") {
            for a in pa.children_named("ParameterAssignment") {
                let name = cx.name_ref(a, "parameterRef")?;
                let value = cx.text(a, "value")?;
                assigned_at.push((name.clone(), a.attr("parameterRef").map_or(a.pos, |r| r.pos)));
                match assignments.iter_mut().find(|(n, _): &&mut (String, String)| n == &name) {
                    Some(slot) => slot.1 = value,
                    None => assignments.push((name, value)),
                }
            }
        }
        let at = cx.loc(reference.pos);
        if self.catalog_depth >= MAX_CATALOG_DEPTH {
            return Err(Error::new(ErrorKind::Limit, at, format!("catalog references nested deeper than {MAX_CATALOG_DEPTH}")));
        }
        // a catalog that cannot be found is said at its name, a missing entry at the entry's
        let attr_at = |name: &str| cx.loc(reference.attr(name).map_or(reference.pos, |a| a.pos));
        let found = self.catalogs.find(kinds, &catalog, &entry, (&attr_at("catalogName"), &attr_at("entryName")), &mut self.warnings)?;
        let Some(elem) = found.elem() else {
            return Err(Error::new(ErrorKind::MissingCatalogEntry, at, format!("catalog entry '{entry}' vanished")));
        };
        let expected: Vec<&str> = kinds.iter().flat_map(|k| k.entry_elements().iter().copied()).collect();
        if !expected.contains(&elem.name.as_str()) {
            return Err(Error::new(
                ErrorKind::Structure,
                at,
                format!("catalog entry '{entry}' of catalog '{catalog}' is a <{}>, expected {}", elem.name, expected.join(" or ")),
            ));
        }
        let declared: Vec<&str> = elem
            .children_unmarked()
            .iter()
            .filter(|d| d.name == "ParameterDeclarations")
            .flat_map(|d| d.children_unmarked())
            .filter_map(|p| p.attrs.iter().find(|a| a.name == "name").map(|a| a.value.trim().trim_start_matches('$')))
            .collect();
        for (name, pos) in &assigned_at {
            if !declared.contains(&name.as_str()) {
                self.warn(
                    cx.loc(*pos),
                    format!("parameter assignment '{name}' does not match any parameter declared by <{}> '{entry}' of catalog '{catalog}'", elem.name),
                );
            }
        }
        let scope = Scope { params: Vec::new(), parent: Some(cx.scope) };
        let entry_cx = cx.in_file(found.doc.file.clone(), &scope);
        self.catalog_depth += 1;
        let result = read(self, &entry_cx, elem, &assignments);
        self.catalog_depth -= 1;
        result
    }
}

impl Reader {
    /// [`Reader::catalog_entry`], or — when the catalog or the entry cannot be found and the load
    /// goes on without catalogs — `placeholder(entry name)`, the gap being reported.
    pub(crate) fn catalog_entry_or<T>(
        &mut self,
        cx: &Cx,
        reference: &Elem,
        kinds: &[CatalogKind],
        read: impl FnOnce(&mut Reader, &Cx, &Elem, &[(String, String)]) -> Result<T, Error>,
        placeholder: impl FnOnce(String) -> T,
    ) -> Result<T, Error> {
        match self.catalog_entry(cx, reference, kinds, read) {
            Err(e) if self.go_on_without_catalogs && matches!(e.kind, ErrorKind::MissingCatalog | ErrorKind::MissingCatalogEntry) => {
                reference.announce();
                let gap = Diagnostic { location: e.location.clone(), message: e.message.clone() };
                // a catalog missing from directories that are all there is a wrong name, not a gap
                if e.kind == ErrorKind::MissingCatalog && !self.catalogs.all_directories_exist() {
                    self.warnings.push(Diagnostic { message: format!("{} {}", gap.message, crate::CATALOG_NOT_CHECKED), ..gap });
                } else {
                    self.problems.push(gap);
                }
                let entry = reference.attr("entryName").map(|a| a.value.clone()).unwrap_or_default();
                Ok(placeholder(entry))
            }
            other => other,
        }
    }

    /// The child of `wrapper`: the element `element` itself (read with `read`) or a
    /// CatalogReference to an entry of catalog `kind`. Environment, Trajectory and Route are
    /// given either way.
    pub(crate) fn inline_or_catalog<T>(
        &mut self,
        cx: &Cx,
        wrapper: &Elem,
        element: &str,
        kind: CatalogKind,
        read: impl FnOnce(&mut Reader, &Cx, &Elem, &[(String, String)]) -> Result<T, Error>,
    ) -> Result<T, Error> {
        let c = cx.choice(wrapper, &format!("{element} or CatalogReference"))?;
        match c.name.as_str() {
            "CatalogReference" => self.catalog_entry(cx, c, &[kind], read),
            name if name == element => read(self, cx, c, &[]),
            _ => Err(cx.unexpected(c, &wrapper.name, &format!("{element}, CatalogReference"))),
        }
    }
}

/// One entry of a catalog file read on its own.
pub(crate) fn read_catalog_entry(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Option<crate::catalog_file::CatalogEntry>, Error> {
    use crate::catalog_file::CatalogEntry;
    Ok(Some(match e.name.as_str() {
        "Vehicle" | "Pedestrian" | "MiscObject" => CatalogEntry::Object(entity::read_entity_object_entry(r, cx, e, &[])?),
        "Controller" => CatalogEntry::Controller(entity::read_controller(r, cx, e, &[])?),
        "Environment" => CatalogEntry::Environment(environment::read_environment(r, cx, e, &[])?),
        "Maneuver" => CatalogEntry::Maneuver(storyboard::read_maneuver(r, cx, e, &[])?),
        "Trajectory" => CatalogEntry::Trajectory(trajectory::read_trajectory(r, cx, e, &[])?),
        "Route" => CatalogEntry::Route(trajectory::read_route(r, cx, e, &[])?),
        _ => {
            r.unsupported(cx, e, "Catalog");
            return Ok(None);
        }
    }))
}
