//! What no reader looked at: after a file is read, every element and attribute the reader never
//! asked for is reported as ignored, with its position. This makes "nothing unsupported passes
//! unannounced" hold by construction: a new element of the standard, or one the reader skips,
//! is a warning the first time a file carries it, without a list to keep up to date.
//!
//! Some content has no bearing on a run — who wrote the file, licences, descriptive text,
//! properties meant for a renderer — and is not reported ([`NO_BEARING`]). The complete list of
//! the OpenSCENARIO 1.3 schema's elements and attributes with what osc2cr does with each is
//! `tests/data/schema_coverage_1_3.tsv`, checked against the schema and this mechanism by
//! `tests/schema_coverage.rs`.

use crate::error::{Diagnostic, Location};
use crate::xml::{Doc, Elem};
use std::collections::BTreeMap;

/// `(element, attribute or child element)` pairs that do not change what a scenario does, so
/// leaving them unread loses nothing; `*` matches any element.
pub const NO_BEARING: &[(&str, &str)] = &[
    // the file header: who, when, under which licence
    ("FileHeader", "author"),
    ("FileHeader", "description"),
    ("FileHeader", "date"),
    ("FileHeader", "revMajor"),
    ("FileHeader", "revMinor"),
    ("FileHeader", "License"),
    ("FileHeader", "Properties"),
    ("License", "name"),
    ("License", "resource"),
    ("License", "spdxId"),
    // a catalog file's header (a scenario's is read for its version)
    ("OpenSCENARIO", "FileHeader"),
    // names of 3D models, for renderers
    ("Vehicle", "model3d"),
    ("Pedestrian", "model"),
    ("Pedestrian", "model3d"),
    ("MiscObject", "model3d"),
    // the catalog's own name: entries are found by the file and the entry name
    ("Catalog", "name"),
];

fn no_bearing(element: &str, member: &str) -> bool {
    NO_BEARING.iter().any(|(e, m)| (*e == element || *e == "*") && *m == member)
}

/// One kind of unread content in one file: where it first occurs and how often.
struct Finding {
    first: crate::xml::Pos,
    count: usize,
}

/// The warnings for what the reader left unread in `doc` (all of it) — one per kind of
/// content and file, at its first occurrence, with the number of further occurrences.
pub(crate) fn report_document(doc: &Doc) -> Vec<Diagnostic> {
    let mut found = BTreeMap::new();
    walk(&doc.root, &mut found);
    warnings(doc, found)
}

/// Like [`report_document`] for a catalog file: only the entries a scenario used are looked at
/// (an entry nobody referred to is not read, and that is not a loss).
pub(crate) fn report_catalog(doc: &Doc) -> Vec<Diagnostic> {
    let mut found = BTreeMap::new();
    for catalog in doc.root.children_unmarked().iter().filter(|c| c.name == "Catalog") {
        for entry in catalog.children_unmarked().iter().filter(|e| e.read.get()) {
            walk(entry, &mut found);
        }
    }
    warnings(doc, found)
}

/// Key: (parent element, member); a member is `@attribute` or `<Element>`.
type Found = BTreeMap<(String, String), Finding>;

fn walk(el: &Elem, found: &mut Found) {
    for a in &el.attrs {
        if !a.read.get() && !no_bearing(&el.name, &a.name) {
            note(found, &el.name, format!("attribute '{}'", a.name), a.pos);
        }
    }
    for c in el.children_unmarked() {
        if c.read.get() {
            walk(c, found);
        } else if (!c.attrs.is_empty() || !c.children_unmarked().is_empty()) && !no_bearing(&el.name, &c.name) {
            // An element with neither attributes nor children carries nothing to lose.
            note(found, &el.name, format!("element <{}>", c.name), c.pos);
        }
    }
}

fn note(found: &mut Found, parent: &str, member: String, pos: crate::xml::Pos) {
    found.entry((parent.to_string(), member)).and_modify(|f| f.count += 1).or_insert(Finding { first: pos, count: 1 });
}

fn warnings(doc: &Doc, found: Found) -> Vec<Diagnostic> {
    let mut out: Vec<(crate::xml::Pos, Diagnostic)> = found
        .into_iter()
        .map(|((parent, member), f)| {
            let more = match f.count {
                1 => String::new(),
                n => format!(" (and {} more in this file)", n - 1),
            };
            let location = Location { file: doc.file.clone(), line: f.first.line, col: f.first.col };
            let message = format!("{member} of <{parent}> is not read by osc2cr and has no effect{more}");
            (f.first, Diagnostic { location, message })
        })
        .collect();
    out.sort_by_key(|(p, _)| (p.line, p.col));
    out.into_iter().map(|(_, w)| w).collect()
}
