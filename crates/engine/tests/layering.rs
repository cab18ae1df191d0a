//! The run state sits below the behaviours that change it (ARCHITECTURE.md, "Inside the
//! engine"): `sim.rs` and every `state` module name only data — no module that holds behaviour
//! (an `impl … Sim` block) — so a frame reads top-down in `run.rs` and the state can be
//! understood without the code that changes it.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Every source file of the engine by module path (`actions::speed::state`, `` for lib.rs).
fn modules() -> BTreeMap<String, String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).expect("src readable").flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    walk(&src, &mut files);
    files
        .into_iter()
        .map(|f| {
            let rel = f.strip_prefix(&src).expect("under src").with_extension("");
            let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
            if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
                parts.pop();
            }
            let text = std::fs::read_to_string(&f).expect("source readable");
            // only the code, not the tests
            let code = text.split("#[cfg(test)]").next().unwrap_or("").to_string();
            (parts.join("::"), code)
        })
        .collect()
}

/// The modules `code` (of module `module`) refers to by `crate::…` or `super::…` paths.
fn references(module: &str, code: &str, known: &BTreeMap<String, String>) -> Vec<String> {
    let mut out = Vec::new();
    let code: String = code.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
    let code = code.replace("pub(in crate::", "pub(in ");
    let is_file = |m: &str| known.contains_key(m);
    let mut push = |path: Vec<&str>| {
        // the longest prefix that is a module
        for k in (1..=path.len()).rev() {
            let m = path[..k].join("::");
            if is_file(&m) {
                out.push(m);
                return;
            }
        }
    };
    let words = |s: &str| -> Vec<String> { s.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')).map(str::to_string).collect() };
    for w in words(&code) {
        if let Some(rest) = w.strip_prefix("crate::") {
            push(rest.split("::").filter(|p| !p.is_empty()).collect());
        } else if let Some(rest) = w.strip_prefix("super::") {
            let mut base: Vec<&str> = module.split("::").collect();
            base.pop();
            let mut path = base;
            path.extend(rest.split("::").filter(|p| !p.is_empty()));
            push(path);
        }
    }
    out
}

#[test]
fn the_run_state_names_no_behaviour() {
    let known = modules();
    let behaviour: Vec<&String> = known.iter().filter(|(_, code)| code.contains("impl<'a> Sim<'a>") || code.contains("impl Sim<'_>")).map(|(m, _)| m).collect();
    assert!(behaviour.len() > 20, "found only {} behaviour modules: {behaviour:?}", behaviour.len());
    let state: Vec<&String> = known.keys().filter(|m| *m == "sim" || m.ends_with("::state") || *m == "state").collect();
    assert!(state.len() > 15, "found only {} state modules", state.len());
    let mut wrong = Vec::new();
    for m in &state {
        for r in references(m, &known[*m], &known) {
            if behaviour.contains(&&r) {
                wrong.push(format!("{m} names {r}, which changes the run state"));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
