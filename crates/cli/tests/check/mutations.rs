//! Seeded mutations of the valid corpus scenarios: one reference or attribute broken at a known
//! place per file and kind — an undefined entity, road, lane or storyboard element, a bad
//! enumeration value, a missing required attribute, an undeclared parameter, a number that is
//! text, an unknown element, an unknown catalog entry, a bad boolean — and `osc2cr check` must
//! report an error at the mutated line (and column: the attribute's value, or the element).
//! Prints the figures per kind; asserts at least 97 % at the mutated line overall, and per kind.
//!
//! A mutated file is written beside a mirror of its corpus folder (symbolic links to the
//! originals), so its road network and catalogs resolve as for the original.
//! `OSC2CR_CHECK_BINARY=path` measures another build of osc2cr (the figures of a baseline).

use crate::common::{checker_suite_valid, tmp};

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Runs `check` with `args` (this build's binary, or `$OSC2CR_CHECK_BINARY`).
fn check(args: &[String]) -> std::process::Output {
    let bin = std::env::var_os("OSC2CR_CHECK_BINARY").map_or_else(|| PathBuf::from(env!("CARGO_BIN_EXE_osc2cr")), PathBuf::from);
    std::process::Command::new(bin).arg("check").arg("--json").args(args).output().expect("osc2cr runs")
}

/// An attribute in the text: its element, name, value and where they start (byte offsets).
struct Attr {
    element: String,
    element_at: usize,
    name: String,
    value: String,
    value_at: usize,
}

/// Every attribute of every start tag of `text`, in order (comments and declarations skipped).
fn attributes(text: &str) -> Vec<Attr> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(lt) = text[i..].find('<').map(|k| k + i) {
        if text[lt..].starts_with("<!--") {
            i = text[lt..].find("-->").map_or(text.len(), |k| lt + k + 3);
            continue;
        }
        let name_end = text[lt + 1..].find(|c: char| !(c.is_alphanumeric() || c == '_')).map_or(text.len(), |k| lt + 1 + k);
        if name_end == lt + 1 {
            i = lt + 1;
            continue;
        }
        let element = text[lt + 1..name_end].to_string();
        let mut j = name_end;
        loop {
            while j < b.len() && b[j].is_ascii_whitespace() {
                j += 1;
            }
            if j >= b.len() || b[j] == b'>' || b[j] == b'/' {
                break;
            }
            let Some(eq) = text[j..].find('=').map(|k| k + j) else { break };
            let name = text[j..eq].trim().to_string();
            let quote = b.get(eq + 1).copied().unwrap_or(b'"');
            let Some(close) = text[eq + 2..].find(quote as char).map(|k| k + eq + 2) else { break };
            out.push(Attr { element: element.clone(), element_at: lt, name, value: text[eq + 2..close].to_string(), value_at: eq + 2 });
            j = close + 1;
        }
        i = name_end;
    }
    out
}

/// 1-based line and column (in characters) of byte offset `at`.
fn position(text: &str, at: usize) -> (u64, u64) {
    let before = &text[..at];
    (before.matches('\n').count() as u64 + 1, before.rsplit('\n').next().map_or(0, |l| l.chars().count()) as u64 + 1)
}

const ENUMS: &[(&str, &str)] = &[
    ("SpeedActionDynamics", "dynamicsShape"),
    ("SpeedActionDynamics", "dynamicsDimension"),
    ("LaneChangeActionDynamics", "dynamicsShape"),
    ("Condition", "conditionEdge"),
    ("Event", "priority"),
    ("SimulationTimeCondition", "rule"),
    ("SpeedCondition", "rule"),
    ("TriggeringEntities", "triggeringEntitiesRule"),
    ("StoryboardElementStateCondition", "state"),
    ("RelativeDistanceCondition", "relativeDistanceType"),
    ("RelativeTargetSpeed", "speedTargetValueType"),
];
const REQUIRED: &[(&str, &str)] = &[
    ("AbsoluteTargetSpeed", "value"),
    ("SpeedActionDynamics", "dynamicsDimension"),
    ("Condition", "delay"),
    ("SimulationTimeCondition", "rule"),
    ("LanePosition", "laneId"),
    ("WorldPosition", "x"),
    ("ManeuverGroup", "maximumExecutionCount"),
];
const NUMBERS: &[(&str, &str)] = &[
    ("AbsoluteTargetSpeed", "value"),
    ("SpeedActionDynamics", "value"),
    ("LaneChangeActionDynamics", "value"),
    ("SimulationTimeCondition", "value"),
    ("Condition", "delay"),
    ("LanePosition", "s"),
    ("LanePosition", "offset"),
    ("WorldPosition", "x"),
    ("WorldPosition", "y"),
    ("RelativeObjectPosition", "dx"),
    ("SpeedCondition", "value"),
];
const BOOLEANS: &[&str] = &["freespace", "continuous", "selectTriggeringEntities", "alongRoute", "oppositeLanes", "freeSpace"];

fn literal(v: &str) -> bool {
    !v.is_empty() && !v.starts_with('$')
}

fn numeric(v: &str) -> bool {
    v.trim().parse::<f64>().is_ok()
}

/// One mutation: its kind, the text it makes, and where the error is expected (line, column).
struct Mutation {
    kind: &'static str,
    text: String,
    at: (u64, u64),
}

fn replace_value(text: &str, a: &Attr, new: &str) -> (String, (u64, u64)) {
    let mut t = text.to_string();
    t.replace_range(a.value_at..a.value_at + a.value.len(), new);
    (t, position(text, a.value_at))
}

/// FNV-1a, to pick a candidate from the file's name and the kind (the seed of the mutations).
fn pick<'a, T>(candidates: &'a [T], file: &str, kind: &str) -> Option<&'a T> {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in file.bytes().chain(kind.bytes()) {
        h = (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3);
    }
    (!candidates.is_empty()).then(|| &candidates[(h % candidates.len() as u64) as usize])
}

fn mutations(text: &str, file: &str, catalogs_resolve: bool) -> Vec<Mutation> {
    let storyboard = text.find("<Storyboard").unwrap_or(text.len());
    let all = attributes(text);
    let attrs: Vec<&Attr> = all.iter().collect();
    let story: Vec<&Attr> = attrs.iter().copied().filter(|a| a.value_at > storyboard).collect();
    let mut out = Vec::new();
    let mut value = |kind: &'static str, candidates: Vec<&Attr>, new: &dyn Fn(&Attr) -> String| {
        if let Some(a) = pick(&candidates, file, kind) {
            let (text, at) = replace_value(text, a, &new(a));
            out.push(Mutation { kind, text, at });
        }
    };
    value(
        "undefined entity",
        story.iter().copied().filter(|a| matches!(a.name.as_str(), "entityRef" | "masterEntityRef") && literal(&a.value)).collect(),
        &|a| format!("{}_undefined", a.value),
    );
    if text.contains("<LogicFile") {
        value(
            "undefined road",
            attrs
                .iter()
                .copied()
                .filter(|a| a.name == "roadId" && matches!(a.element.as_str(), "LanePosition" | "RoadPosition") && literal(&a.value))
                .collect(),
            &|_| "no_such_road".into(),
        );
        value("undefined lane", attrs.iter().copied().filter(|a| a.name == "laneId" && a.element == "LanePosition" && numeric(&a.value)).collect(), &|_| {
            "-97".into()
        });
    }
    value("undefined storyboard element", story.iter().copied().filter(|a| a.name == "storyboardElementRef" && literal(&a.value)).collect(), &|a| {
        format!("{}_undefined", a.value)
    });
    value(
        "bad enumeration value",
        attrs.iter().copied().filter(|a| ENUMS.contains(&(a.element.as_str(), a.name.as_str())) && literal(&a.value)).collect(),
        &|_| "bogusValue".into(),
    );
    value(
        "undeclared parameter",
        story.iter().copied().filter(|a| NUMBERS.contains(&(a.element.as_str(), a.name.as_str())) && numeric(&a.value)).collect(),
        &|_| "$UndeclaredParameter".into(),
    );
    value(
        "number that is text",
        attrs.iter().copied().filter(|a| NUMBERS.contains(&(a.element.as_str(), a.name.as_str())) && numeric(&a.value)).collect(),
        &|_| "abc".into(),
    );
    if catalogs_resolve {
        value("unknown catalog entry", attrs.iter().copied().filter(|a| a.name == "entryName" && literal(&a.value)).collect(), &|a| {
            format!("{}_undefined", a.value)
        });
    }
    value(
        "bad boolean",
        attrs.iter().copied().filter(|a| BOOLEANS.contains(&a.name.as_str()) && matches!(a.value.as_str(), "true" | "false")).collect(),
        &|_| "maybe".into(),
    );
    // a required attribute removed: the error is at its element
    let required: Vec<&Attr> = attrs.iter().copied().filter(|a| REQUIRED.contains(&(a.element.as_str(), a.name.as_str()))).collect();
    if let Some(a) = pick(&required, file, "missing required attribute") {
        let start = text[..a.value_at].rfind(char::is_whitespace).unwrap_or(a.value_at);
        let end = a.value_at + a.value.len() + 1;
        let mut t = text.to_string();
        t.replace_range(start..end, "");
        out.push(Mutation { kind: "missing required attribute", text: t, at: position(text, a.element_at) });
    }
    // an unknown element as the first child of a container
    let containers: Vec<usize> =
        ["<Actions>", "<Entities>", "<ConditionGroup>"].iter().flat_map(|tag| text.match_indices(tag).map(move |(i, _)| i + tag.len())).collect();
    if let Some(&at) = pick(&containers, file, "unknown element") {
        let mut t = text.to_string();
        t.insert_str(at, "<NoSuchElement/>");
        out.push(Mutation { kind: "unknown element", text: t, at: position(text, at) });
    }
    out
}

/// Mirrors `root` below `mirror`: real folders on the way to each of `dirs`, symbolic links to
/// everything else.
fn mirror(root: &Path, mirror: &Path, dirs: &BTreeSet<PathBuf>) {
    let on_the_way = |p: &Path| dirs.iter().any(|d| d.starts_with(p));
    let mut stack = vec![PathBuf::new()];
    while let Some(rel) = stack.pop() {
        std::fs::create_dir_all(mirror.join(&rel)).expect("mirror folder");
        for e in std::fs::read_dir(root.join(&rel)).expect("corpus folder").flatten() {
            let child = rel.join(e.file_name());
            if e.path().is_dir() && on_the_way(&child) {
                stack.push(child);
            } else {
                #[cfg(unix)]
                std::os::unix::fs::symlink(e.path(), mirror.join(&child)).expect("symlink");
            }
        }
    }
}

/// Kind → the mutated files with the line and column where the error is expected.
type Planned = BTreeMap<&'static str, Vec<(PathBuf, (u64, u64))>>;

#[test]
fn mutations_are_reported_at_the_mutated_line() {
    let Some(shared) = testkit::shared_dir() else { return };
    let corpus = shared.join("corpus");
    let scenarios: Vec<PathBuf> = testkit::files_with_ext(&corpus, "xosc")
        .into_iter()
        .filter(|p| std::fs::read_to_string(p).is_ok_and(|t| t.contains("<Storyboard") && !t.contains("<Catalog ") && !t.contains("<Catalog>")))
        .collect();
    // the originals: valid (no error), and whether their catalogs resolve
    let originals: Vec<String> = scenarios.iter().map(|p| p.display().to_string()).collect();
    let r = check(&originals);
    let found: serde_json::Value = serde_json::from_slice(&r.stdout).expect("json");
    let findings = found.as_array().cloned().unwrap_or_default();
    // (but for what they name and the corpus does not ship, which convert refuses as well)
    let not_shipped = |f: &serde_json::Value| f["message"].as_str().is_some_and(checker_suite_valid::not_shipped);
    assert!(!findings.iter().any(|f| f["severity"] == "error" && !not_shipped(f)), "the originals have errors");
    let unresolved: BTreeSet<String> = findings
        .iter()
        .filter(|f| f["message"].as_str().is_some_and(|m| m.contains("not found; looked in")))
        .filter_map(|f| f["file"].as_str().map(String::from))
        .collect();

    let out = tmp("check_mutations", "mirror");
    let dirs: BTreeSet<PathBuf> = scenarios.iter().filter_map(|p| p.parent()?.strip_prefix(&corpus).ok().map(Path::to_path_buf)).collect();
    mirror(&corpus, &out, &dirs);
    let mut planned: Planned = BTreeMap::new();
    for p in &scenarios {
        let text = std::fs::read_to_string(p).expect("scenario");
        let rel = p.strip_prefix(&corpus).expect("in the corpus");
        let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("x");
        let catalogs_resolve = !unresolved.contains(&p.display().to_string());
        for m in mutations(&text, &rel.display().to_string(), catalogs_resolve) {
            let file = out.join(rel).with_file_name(format!("{stem}__{}.xosc", m.kind.replace(' ', "_")));
            std::fs::write(&file, &m.text).expect("mutated file");
            planned.entry(m.kind).or_default().push((file, m.at));
        }
    }

    let (mut total, mut at_line_total) = (0, 0);
    let mut report = Vec::new();
    let mut misses = Vec::new();
    for (kind, cases) in &planned {
        let args: Vec<String> = cases.iter().map(|(f, _)| f.display().to_string()).collect();
        let r = check(&args);
        let json: serde_json::Value = serde_json::from_slice(&r.stdout).expect("json");
        let errors: Vec<(String, u64, u64)> = json
            .as_array()
            .cloned()
            .unwrap_or_default()
            .iter()
            .filter(|f| f["severity"] == "error" && !not_shipped(f))
            .map(|f| (f["file"].as_str().unwrap_or_default().to_string(), f["line"].as_u64().unwrap_or(0), f["column"].as_u64().unwrap_or(0)))
            .collect();
        let (mut detected, mut at_line, mut at_column) = (0, 0, 0);
        for (file, (line, col)) in cases {
            let mine: Vec<&(String, u64, u64)> = errors.iter().filter(|(f, _, _)| Path::new(f) == file).collect();
            detected += usize::from(!mine.is_empty());
            let line_hit = mine.iter().any(|(_, l, _)| l == line);
            at_line += usize::from(line_hit);
            at_column += usize::from(mine.iter().any(|(_, l, c)| l == line && c == col));
            if !line_hit {
                misses.push(format!("{kind}: {}:{line}:{col}, errors at {:?}", file.display(), mine.iter().map(|(_, l, c)| (l, c)).collect::<Vec<_>>()));
            }
        }
        let n = cases.len();
        report.push(format!(
            "{kind:<30} {n:>4}  detected {detected:>4}  at the line {at_line:>4} ({:.1} %)  and column {at_column:>4}",
            100.0 * at_line as f64 / n as f64
        ));
        total += n;
        at_line_total += at_line;
    }
    eprintln!("{}\n{:<30} {total:>4}  at the line {at_line_total:>4} ({:.1} %)", report.join("\n"), "all", 100.0 * at_line_total as f64 / total as f64);
    eprintln!("not at the mutated line:\n{}", misses.join("\n"));
    assert!(total > 1000, "only {total} mutations made");
    assert!(at_line_total * 100 >= total * 97, "{at_line_total} of {total} at the mutated line");
    for (kind, cases) in &planned {
        let missed = misses.iter().filter(|m| m.starts_with(&format!("{kind}:"))).count();
        assert!((cases.len() - missed) * 100 >= cases.len() * 97, "{kind}: {missed} of {} not at the mutated line", cases.len());
    }
}
