//! Nothing unsupported passes unannounced. `data/schema_coverage_1_3.tsv` lists every element and
//! attribute of the OpenSCENARIO 1.3 schema, by the element that holds it, with what osc2cr does
//! with it:
//!
//! - `read`: the reader reads it (seen read in a corpus file);
//! - `read-not-in-corpus`: no corpus file has it; the reader's source asks for that name;
//! - `no-bearing`: it does not change what a scenario does and is deliberately not read
//!   (`openscenario::NO_BEARING`: authors, licences, descriptions);
//! - `ignored`: the reader leaves it unread, and a file that has it gets a warning at its
//!   position (seen in a corpus file);
//! - `ignored-not-in-corpus`: no corpus file has it and the reader's source never names it: a
//!   file that has it gets the same warning (the unread report covers everything the reader did
//!   not ask for, by construction — `unread_content_is_a_positioned_warning` shows it).
//!
//! The list is recomputed from the schema, the corpus and the reader's source on every run; a
//! difference fails the test (run with `OSC2CR_BLESS=1` to rewrite the file after a change to the
//! reader, and review the diff: it is the change in coverage).

use crate::common;

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use openscenario::{load, LoadOptions};

/// (element, member) → member kind: `@name` for an attribute, `<Name>` for a child element.
fn schema_pairs() -> BTreeSet<(String, String)> {
    let s = schema::for_minor(3).expect("the 1.3 schema");
    // element name → type names it is declared with
    let mut types_of: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for r in &s.roots {
        types_of.entry(r.name.clone()).or_default().insert(r.type_name.clone());
    }
    for t in s.types() {
        for e in s.child_elements(t) {
            types_of.entry(e.name.clone()).or_default().insert(e.type_name.clone());
        }
    }
    let mut pairs = BTreeSet::new();
    for (element, types) in &types_of {
        for ty in types.iter().filter_map(|t| s.complex_type(t)) {
            for a in &ty.attributes {
                pairs.insert((element.clone(), format!("@{}", a.name)));
            }
            for c in s.child_elements(ty) {
                pairs.insert((element.clone(), format!("<{}>", c.name)));
            }
        }
    }
    pairs
}

/// Every string literal of the reader's source (names it may ask for).
fn reader_literals() -> BTreeSet<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = BTreeSet::new();
    for f in testkit::files_with_ext(&src, "rs") {
        if f.components().any(|c| c.as_os_str() == "validate") {
            continue; // the schema pass looks at everything; it reads nothing into the model
        }
        let text = std::fs::read_to_string(&f).expect("read source");
        for (i, part) in text.split('"').enumerate() {
            if i % 2 == 1 && !part.is_empty() && part.len() < 60 && part.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                out.insert(part.to_string());
            }
        }
    }
    out
}

/// From the unread report's message: (element, member).
fn unread_pair(message: &str) -> Option<(String, String)> {
    let (member, rest) = message.split_once(" of <")?;
    let (element, tail) = rest.split_once('>')?;
    if !tail.starts_with(" is not read by osc2cr") {
        return None;
    }
    let member =
        if let Some(a) = member.strip_prefix("attribute '") { format!("@{}", a.trim_end_matches('\'')) } else { member.strip_prefix("element ")?.to_string() };
    Some((element.to_string(), member))
}

/// Every (element, member) occurring in a file, by walking its XML.
fn present_pairs(path: &Path, out: &mut BTreeSet<(String, String)>) {
    let Ok(text) = std::fs::read_to_string(path) else { return };
    let Ok(doc) = roxmltree::Document::parse(&text) else { return };
    for n in doc.descendants().filter(|n| n.is_element()) {
        let name = n.tag_name().name().to_string();
        for a in n.attributes().filter(|a| a.namespace().is_none()) {
            out.insert((name.clone(), format!("@{}", a.name())));
        }
        for c in n.children().filter(|c| c.is_element()) {
            out.insert((name.clone(), format!("<{}>", c.tag_name().name())));
        }
    }
}

fn no_bearing(element: &str, member: &str) -> bool {
    let m = member.trim_start_matches('@').trim_start_matches('<').trim_end_matches('>');
    openscenario::NO_BEARING.iter().any(|(e, n)| (*e == element || *e == "*") && *n == m)
}

#[test]
fn every_element_and_attribute_of_1_3_is_read_or_announced() {
    let Some(shared) = common::shared() else { return };
    let pairs = schema_pairs();
    assert!(pairs.len() > 800, "only {} pairs read from the 1.3 schema", pairs.len());
    let literals = reader_literals();

    let mut unread = BTreeSet::new();
    let mut present = BTreeSet::new();
    for dir in ["corpus", "checker-suite"] {
        for f in common::xosc_files(&shared.join(dir)) {
            let Ok(l) = load(&f, &LoadOptions::default()) else { continue };
            unread.extend(l.warnings.iter().filter_map(|w| unread_pair(&w.message)));
            // catalogs are read through their scenarios; their files are counted as present too
            present_pairs(&f, &mut present);
        }
    }

    let mut table = String::from("element\tmember\tstatus\n");
    for (element, member) in &pairs {
        let key = (element.clone(), member.clone());
        let name = member.trim_start_matches('@').trim_start_matches('<').trim_end_matches('>');
        let status = if no_bearing(element, member) {
            "no-bearing"
        } else if unread.contains(&key) {
            "ignored"
        } else if present.contains(&key) {
            "read"
        } else if literals.contains(name) {
            "read-not-in-corpus"
        } else {
            "ignored-not-in-corpus"
        };
        table.push_str(&format!("{element}\t{member}\t{status}\n"));
    }
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/schema_coverage_1_3.tsv");
    if std::env::var_os("OSC2CR_BLESS").is_some() {
        std::fs::write(&file, &table).expect("write the coverage table");
        return;
    }
    let committed = std::fs::read_to_string(&file).unwrap_or_default();
    if committed != table {
        let old: BTreeSet<&str> = committed.lines().collect();
        let new: BTreeSet<&str> = table.lines().collect();
        let gone: Vec<_> = old.difference(&new).take(20).collect();
        let added: Vec<_> = new.difference(&old).take(20).collect();
        panic!("the coverage of the 1.3 schema changed (OSC2CR_BLESS=1 rewrites {}):\n- {gone:#?}\n+ {added:#?}", file.display());
    }
}

#[test]
fn unread_content_is_a_positioned_warning() {
    let dir = common::temp_dir("unread");
    let path = dir.join("unread.xosc");
    // an attribute no version has on a vehicle; the header's author, date and description
    let vehicle = common::VEHICLE.replacen(r#"vehicleCategory="car""#, r#"vehicleCategory="car" colour="mauve""#, 1);
    let entities = format!(r#"<ScenarioObject name="Ego">{vehicle}</ScenarioObject>"#);
    let init = r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0" h="0"/></Position></TeleportAction></PrivateAction></Private>"#;
    let text = common::scenario("", "", &entities, init, "<StopTrigger/>");
    std::fs::write(&path, &text).expect("write");
    let l = load(&path, &LoadOptions::default()).expect("loads");
    let w = l
        .warnings
        .iter()
        .find(|w| w.message.contains("attribute 'colour' of <Vehicle> is not read"))
        .unwrap_or_else(|| panic!("no warning for the unknown attribute: {:#?}", l.warnings));
    assert_eq!((w.location.line, w.location.col), common::pos_of(&text, "mauve"), "{w}");
    // the header's author, date and description have no bearing: no warning
    assert!(!l.warnings.iter().any(|w| w.message.contains("FileHeader")), "{:#?}", l.warnings);
    // nothing else is unread in this file
    let unread: Vec<_> = l.warnings.iter().filter(|w| w.message.contains("is not read by osc2cr")).collect();
    assert_eq!(unread.len(), 1, "{unread:#?}");
}
