//! The coverage table: each OpenSCENARIO 1.3 element the engine acts on — actions,
//! conditions, position types, in-route positions, trajectory shapes — and each driver model,
//! whether the generator emits it, and its agreement with esmini on the last measured seeds.
//!
//! Nothing here is a hand list. The elements are the schema's (the `schema` crate's 1.3
//! tables: the leaves under PrivateAction, GlobalAction, EntityCondition, ByValueCondition,
//! Position, InRoutePosition and Shape). What the engine acts on is read from its source: the
//! model variants (`PrivateAction::Speed`, …; their element names from the `openscenario`
//! model's `element_name` tables) the engine matches on, except where the arm only warns that
//! the element "is not supported"; the controller types and ALKS R157 models its
//! `assign_controller`/`AlksR157Rt::new` accept. Whether the generator emits an element is
//! found by generating scenarios and reading their tags. The agreement comes from
//! `measured.tsv`, written by `difftest measure` from its reports.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

/// The categories of the table, in its order.
pub const CATEGORIES: [&str; 6] = ["action", "condition", "position", "in-route-position", "trajectory-shape", "controller"];

/// Elements the generator leaves out although esmini has a name for them, and why (shown in
/// the table; the test still requires every element the engine acts on to be generated).
pub const NOT_GENERATED_WHY: [(&str, &str); 1] = [("GeoPosition", "esmini 3.6.0 cannot read it (its reader quits: \"Failed parse position\")")];

/// The prefix of a driver model among a scenario's elements (`controller:ACCController`).
pub const CONTROLLER: &str = "controller:";

/// One row of the table.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Row {
    pub category: &'static str,
    pub element: String,
    pub engine: bool,
    pub generated: bool,
}

/// The schema's elements by category.
pub fn schema_elements() -> BTreeMap<&'static str, BTreeSet<String>> {
    let mut out: BTreeMap<&'static str, BTreeSet<String>> = BTreeMap::new();
    let Some(s) = schema::for_minor(3) else { return out };
    let children = |ty: &str| -> Vec<(String, String)> {
        s.complex_type(ty).map(|t| s.child_elements(t).into_iter().map(|e| (e.name.clone(), e.type_name.clone())).collect()).unwrap_or_default()
    };
    // actions: leaves below the wrappers whose children are all actions
    let mut stack: Vec<(String, String, String)> = ["PrivateAction", "GlobalAction"].iter().map(|t| (t.to_string(), t.to_string(), String::new())).collect();
    while let Some((_, ty, prefix)) = stack.pop() {
        for (name, child_ty) in children(&ty) {
            let grand = children(&child_ty);
            let wrapper = !grand.is_empty() && grand.iter().all(|(n, _)| n.ends_with("Action"));
            if wrapper {
                // ParameterAction/VariableAction hold SetAction and ModifyAction
                let p = if name == "ParameterAction" || name == "VariableAction" { name.trim_end_matches("Action").to_string() } else { String::new() };
                stack.push((name, child_ty, p));
            } else if name.ends_with("Action") {
                out.entry("action").or_default().insert(format!("{prefix}{name}"));
            }
        }
    }
    for ty in ["EntityCondition", "ByValueCondition"] {
        out.entry("condition").or_default().extend(children(ty).into_iter().map(|(n, _)| n));
    }
    out.entry("position").or_default().extend(children("Position").into_iter().map(|(n, _)| n));
    out.entry("in-route-position").or_default().extend(children("InRoutePosition").into_iter().map(|(n, _)| n));
    out.entry("trajectory-shape").or_default().extend(children("Shape").into_iter().map(|(n, _)| n));
    out
}

/// Source text without `//` comments (doc comments name esmini's functions, not ours).
fn strip_comments(text: &str) -> String {
    text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

/// `(Enum, Variant) -> element` from the model's `element_name` arms
/// (`PrivateAction::Speed { .. } => "SpeedAction"`).
fn model_element_names(model_dir: &Path) -> BTreeMap<(String, String), String> {
    let mut out = BTreeMap::new();
    for f in ["action.rs", "condition.rs"] {
        let text = std::fs::read_to_string(model_dir.join(f)).unwrap_or_default();
        for line in text.lines() {
            let Some((lhs, rhs)) = line.split_once("=>") else { continue };
            let rhs = rhs.trim().trim_end_matches(',');
            if !(rhs.starts_with('"') && rhs.ends_with('"')) {
                continue;
            }
            let Some((enum_name, rest)) = lhs.trim().split_once("::") else { continue };
            let variant: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            out.insert((enum_name.to_string(), variant), rhs.trim_matches('"').to_string());
        }
    }
    out
}

/// The variants of `pub enum NAME` in a model file.
fn enum_variants(model_file: &Path, name: &str) -> Vec<String> {
    let text = std::fs::read_to_string(model_file).unwrap_or_default();
    let Some(start) = text.find(&format!("pub enum {name} {{")) else { return Vec::new() };
    let body = &text[start..];
    let mut depth = 0i32;
    let mut out = Vec::new();
    for line in body.lines() {
        let t = line.trim();
        if depth == 1 && !t.starts_with("//") && !t.starts_with('#') {
            let v: String = t.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if v.chars().next().is_some_and(|c| c.is_uppercase()) {
                out.push(v);
            }
        }
        depth += line.matches('{').count() as i32 - line.matches('}').count() as i32;
        if depth <= 0 && !out.is_empty() {
            break;
        }
    }
    out
}

/// Whether an occurrence at line `n` acts on its element: not when its arm (the line and the
/// lines below it, more indented, up to the next arm) says the element "is not supported", nor
/// when the arm is an empty `=> false` / `=> {}`.
fn acts(lines: &[&str], n: usize) -> bool {
    let indent = |l: &str| l.len() - l.trim_start().len();
    let own = indent(lines[n]);
    let mut arm = vec![lines[n]];
    for l in lines.iter().skip(n + 1).take(4) {
        if l.contains("=>") || indent(l) <= own {
            break;
        }
        arm.push(l);
    }
    let text = arm.join("\n");
    let body = lines[n].split_once("=>").map(|(_, b)| b.trim().trim_end_matches(',').trim());
    !text.contains("not supported") && !matches!(body, Some("false" | "{}" | "()"))
}

/// `Enum::Variant` occurrences of the engine's source, aliases resolved (`EntityCondition as
/// C`), each with whether it acts on its element (`acts`).
fn engine_variant_uses(engine_src: &Path) -> BTreeMap<(String, String), bool> {
    let mut out: BTreeMap<(String, String), bool> = BTreeMap::new();
    for f in crate::files_with_ext(engine_src, "rs") {
        let text = strip_comments(&std::fs::read_to_string(&f).unwrap_or_default());
        let mut alias: BTreeMap<String, String> = BTreeMap::new();
        let mut rest = text.as_str();
        while let Some(i) = rest.find("use openscenario::") {
            let stmt = &rest[i..rest[i..].find(';').map_or(rest.len(), |j| i + j)];
            let words: Vec<&str> = stmt.split(|c: char| !(c.is_alphanumeric() || c == '_')).filter(|w| !w.is_empty()).collect();
            for w in words.windows(3) {
                if w[1] == "as" {
                    alias.insert(w[2].to_string(), w[0].to_string());
                }
            }
            rest = &rest[i + 1..];
        }
        let lines: Vec<&str> = text.lines().collect();
        for (n, line) in lines.iter().enumerate() {
            let mut s = *line;
            while let Some(i) = s.find("::") {
                let before: String = s[..i].chars().rev().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<Vec<_>>().into_iter().rev().collect();
                let after: String = s[i + 2..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                s = &s[i + 2..];
                if before.is_empty() || after.is_empty() {
                    continue;
                }
                let enum_name = alias.get(&before).cloned().unwrap_or(before);
                let e = out.entry((enum_name, after)).or_insert(false);
                *e |= acts(&lines, n);
            }
        }
    }
    out
}

/// The string literals of the arms of the first `match` after `anchor` in `text`, up to the
/// arm `end` (`"ACCController" => …`).
fn match_literals(text: &str, anchor: &str, end: &str) -> BTreeSet<String> {
    let Some(i) = text.find(anchor) else { return BTreeSet::new() };
    let body = &text[i..];
    let body = &body[..body.find(end).unwrap_or(body.len())];
    body.split('"')
        .enumerate()
        .filter(|(k, _)| k % 2 == 1)
        .map(|(_, s)| s)
        .filter(|s| !s.is_empty() && s.chars().all(|c| c.is_alphanumeric() || c == '_'))
        .map(String::from)
        .collect()
}

/// What the engine acts on, by category, read from the workspace's sources under `crates`.
pub fn engine_elements(crates: &Path) -> BTreeMap<&'static str, BTreeSet<String>> {
    let model = crates.join("openscenario/src/model");
    let engine_src = crates.join("engine/src");
    let names = model_element_names(&model);
    let uses = engine_variant_uses(&engine_src);
    let mut out: BTreeMap<&'static str, BTreeSet<String>> = BTreeMap::new();
    for ((enum_name, variant), element) in &names {
        let category = match enum_name.as_str() {
            "PrivateAction" | "GlobalAction" => "action",
            "EntityCondition" | "ValueCondition" => "condition",
            _ => continue,
        };
        if uses.get(&(enum_name.clone(), variant.clone())) == Some(&true) {
            out.entry(category).or_default().insert(element.clone());
        }
    }
    for (enum_name, file, category, suffix) in [
        ("Position", "position.rs", "position", "Position"),
        ("InRoutePosition", "position.rs", "in-route-position", ""),
        ("Shape", "trajectory.rs", "trajectory-shape", ""),
    ] {
        for v in enum_variants(&model.join(file), enum_name) {
            if uses.get(&(enum_name.to_string(), v.clone())) == Some(&true) {
                let element = if v.ends_with(suffix) { v } else { format!("{v}{suffix}") };
                out.entry(category).or_default().insert(element);
            }
        }
    }
    let controllers = std::fs::read_to_string(engine_src.join("controllers/mod.rs")).unwrap_or_default();
    let types = match_literals(&controllers, "let rt = match kind {", "_ => None");
    let r157 = std::fs::read_to_string(engine_src.join("controllers/alks_r157.rs")).unwrap_or_default();
    let models = match_literals(&r157, "match name.as_str() {", "other =>");
    let c = out.entry("controller").or_default();
    for t in types {
        if t == "ALKS_R157SM_Controller" {
            c.extend(models.iter().map(|m| format!("{CONTROLLER}{t}/{m}")));
        } else {
            c.insert(format!("{CONTROLLER}{t}"));
        }
    }
    out
}

/// The coverage-relevant elements a scenario's text holds: element tags, and the driver
/// models (`esminiController`, with the ALKS R157 safety model).
pub fn elements_in(xosc: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for part in xosc.split('<').skip(1) {
        let name: String = part.chars().take_while(|c| c.is_alphanumeric()).collect();
        if !name.is_empty() {
            out.insert(name);
        }
    }
    // ParameterAction/VariableAction: their SetAction/ModifyAction as the model names them
    for holder in ["ParameterAction", "VariableAction"] {
        let prefix = holder.trim_end_matches("Action");
        for part in xosc.split(&format!("<{holder} ")).skip(1) {
            let inner = part.split('>').nth(1).unwrap_or("");
            for kind in ["SetAction", "ModifyAction"] {
                if inner.starts_with(&format!("<{kind}")) {
                    out.insert(format!("{prefix}{kind}"));
                }
            }
        }
    }
    for part in xosc.split(r#"name="esminiController" value=""#).skip(1) {
        let t: String = part.chars().take_while(|c| *c != '"').collect();
        if t == "ALKS_R157SM_Controller" {
            let model = part.split(r#"name="model" value=""#).nth(1).map(|m| m.chars().take_while(|c| *c != '"').collect::<String>()).unwrap_or_default();
            out.insert(format!("{CONTROLLER}{t}/{model}"));
        } else {
            out.insert(format!("{CONTROLLER}{t}"));
        }
    }
    out
}

/// The table's rows: every element of the schema (or a driver model) that the engine acts on
/// or the generator emits.
pub fn rows(crates: &Path, generated: &BTreeSet<String>) -> Vec<Row> {
    let schema = schema_elements();
    let engine = engine_elements(crates);
    let mut rows = Vec::new();
    for category in CATEGORIES {
        let universe: BTreeSet<String> = if category == "controller" {
            let known: BTreeSet<String> = engine.get(category).cloned().unwrap_or_default();
            known.into_iter().chain(generated.iter().filter(|g| g.starts_with(CONTROLLER)).cloned()).collect()
        } else {
            schema.get(category).cloned().unwrap_or_default()
        };
        for element in universe {
            let on = engine.get(category).is_some_and(|e| e.contains(&element));
            let gen = generated.contains(&element);
            let why = NOT_GENERATED_WHY.iter().any(|(e, _)| *e == element);
            if on || gen || why {
                rows.push(Row { category, element, engine: on, generated: gen });
            }
        }
    }
    rows
}

/// One element's measured agreement: scenarios holding it, and how many agreed (exact or close).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Measured {
    pub scenarios: usize,
    pub agreed: usize,
}

/// `measured.tsv`: a comment line naming the runs, then `element<TAB>scenarios<TAB>agreed`.
pub fn read_measured(text: &str) -> (String, BTreeMap<String, Measured>) {
    let mut runs = String::new();
    let mut out = BTreeMap::new();
    for line in text.lines() {
        if let Some(c) = line.strip_prefix("# ") {
            runs = c.to_string();
            continue;
        }
        let f: Vec<&str> = line.split('\t').collect();
        if let (Some(e), Some(n), Some(a)) = (f.first(), f.get(1).and_then(|v| v.parse().ok()), f.get(2).and_then(|v| v.parse().ok())) {
            out.insert(e.to_string(), Measured { scenarios: n, agreed: a });
        }
    }
    (runs, out)
}

pub fn write_measured(runs: &str, measured: &BTreeMap<String, Measured>) -> String {
    let mut out = format!("# {runs}\n");
    for (e, m) in measured {
        let _ = writeln!(out, "{e}\t{}\t{}", m.scenarios, m.agreed);
    }
    out
}

/// The table as markdown.
pub fn markdown(rows: &[Row], runs: &str, measured: &BTreeMap<String, Measured>) -> String {
    let mut out = String::from(
        "# What the differential generator covers\n\n\
         Generated by `cargo run --release -p osc2cr-difftest -- coverage --write` and checked by\n\
         `cargo test -p osc2cr-difftest` (do not edit by hand). Each OpenSCENARIO 1.3 element the\n\
         engine acts on (read from the engine's source) and each driver model, whether the\n\
         generator emits it (read from generated scenarios), and its agreement with esmini 3.6.0\n\
         (exact or close) on the last measured runs (`measured.tsv`, written by `difftest measure`).\n\n",
    );
    let _ = writeln!(out, "Last measured: {}\n", if runs.is_empty() { "never" } else { runs });
    let _ = writeln!(out, "| category | element | engine acts on it | generated | scenarios | agreement |");
    let _ = writeln!(out, "|---|---|---|---|---|---|");
    for r in rows {
        let m = measured.get(&r.element).copied().unwrap_or_default();
        let agreement = if m.scenarios > 0 { format!("{:.1} %", 100.0 * m.agreed as f64 / m.scenarios as f64) } else { "–".into() };
        let generated = match NOT_GENERATED_WHY.iter().find(|(e, _)| *e == r.element) {
            Some((_, why)) if !r.generated => format!("no: {why}"),
            _ if r.generated => "yes".into(),
            _ => "no".into(),
        };
        let name = r.element.strip_prefix(CONTROLLER).unwrap_or(&r.element);
        let _ = writeln!(out, "| {} | {name} | {} | {generated} | {} | {agreement} |", r.category, if r.engine { "yes" } else { "no (warns)" }, m.scenarios);
    }
    out
}
