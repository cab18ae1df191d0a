//! `osc2cr.export` from Python: a CommonRoad file given by its path gives the very files
//! `osc2cr export FILE -o DIR` writes; a commonroad-io `Scenario` (with its planning problems)
//! is exported through commonroad-io's own 2020a writer and gives the same road users, the
//! same trajectories (to the writer's 4 decimals) and the ego carrying its planning problem —
//! with commonroad-io 2024.3 and 2026.1; a bad option or input raises.

use std::path::Path;
use std::process::Command;

use super::{env, python, tmp};

fn commonroad_scenario(rel: &str) -> std::path::PathBuf {
    testkit::shared_dir().expect("shared").join("commonroad-scenarios").join(rel)
}

const EXPORT: &str = r#"
import os, sys, warnings
import osc2cr
from commonroad.common.file_reader import CommonRoadFileReader
import inspect
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path, by_path, by_object = sys.argv[1], sys.argv[2], sys.argv[3]
done = osc2cr.export(path, by_path)
print("path", os.path.basename(done.xosc), done.xodr is not None and os.path.exists(done.xodr), len(done.warnings) > 0)
if "filename_2020a" in inspect.signature(CommonRoadFileReader.__init__).parameters:
    scenario, problems = CommonRoadFileReader(filename_2020a=path).open()
else:
    scenario, problems = CommonRoadFileReader(path).open()
done2 = osc2cr.export(scenario, by_object, problems)
print("object", os.path.basename(done2.xosc), done2.xodr is not None and os.path.exists(done2.xodr))
try:
    osc2cr.export(path, by_path, osc="2.0")
except ValueError as e:
    print("bad option", "2.0" in str(e))
try:
    osc2cr.export(os.path.join(by_path, "missing.xml"), by_path)
except osc2cr.ConversionError as e:
    print("missing file", "missing.xml" in str(e))
"#;

/// The `<Vertex .../>` positions of every entity of an exported scenario, by entity name.
fn vertices(xosc: &Path) -> std::collections::BTreeMap<String, Vec<(f64, f64, f64)>> {
    let text = std::fs::read_to_string(xosc).expect("xosc written");
    let doc = roxmltree::Document::parse(&text).expect("xml");
    let mut out = std::collections::BTreeMap::new();
    for t in doc.descendants().filter(|n| n.has_tag_name("Trajectory")) {
        let name = t.attribute("name").unwrap_or("").trim_end_matches("_trajectory").to_string();
        let v: Vec<(f64, f64, f64)> = t
            .descendants()
            .filter(|n| n.has_tag_name("Vertex"))
            .map(|v| {
                let w = v.descendants().find(|n| n.has_tag_name("WorldPosition")).expect("world position");
                let f = |n: &roxmltree::Node, a: &str| n.attribute(a).and_then(|x| x.parse::<f64>().ok()).expect("number");
                (f(&v, "time"), f(&w, "x"), f(&w, "y"))
            })
            .collect();
        out.insert(name, v);
    }
    out
}

fn check_environment(interpreter: &Path, prefix: &str) {
    let file = commonroad_scenario("tests/test_scenarios/USA_US101-4_1_T-1.xml");
    let (by_path, by_object, cli) = (tmp(&format!("{prefix}-export-path")), tmp(&format!("{prefix}-export-object")), tmp(&format!("{prefix}-export-cli")));
    let got = python(interpreter, EXPORT, &[&file, &by_path, &by_object]);
    let expected = "path USA_US101-4_1_T-1.xosc True True\nobject USA_US101-4_1_T-1.xosc True\nbad option True\nmissing file True\n";
    assert_eq!(got, expected, "{prefix}");
    // by path: the CLI's bytes
    let r = Command::new(env!("CARGO_BIN_EXE_osc2cr")).arg("export").arg(&file).arg("-o").arg(&cli).output().expect("osc2cr runs");
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let name = "USA_US101-4_1_T-1.xosc";
    assert_eq!(std::fs::read(by_path.join(name)).expect("python's"), std::fs::read(cli.join(name)).expect("the CLI's"), "{prefix}: the CLI's bytes");
    // by object: the same road users on the same trajectories, to commonroad-io's 4 decimals
    let (a, b) = (vertices(&by_path.join(name)), vertices(&by_object.join(name)));
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>(), "{prefix}: the same entities");
    assert!(a.len() >= 20, "{prefix}: US101's obstacles");
    for (entity, va) in &a {
        let vb = &b[entity];
        assert_eq!(va.len(), vb.len(), "{prefix} {entity}");
        for (p, q) in va.iter().zip(vb) {
            assert!((p.0 - q.0).abs() < 1e-9 && (p.1 - q.1).abs() < 1e-3 && (p.2 - q.2).abs() < 1e-3, "{prefix} {entity}: {p:?} vs {q:?}");
        }
    }
    let text = std::fs::read_to_string(by_object.join(name)).expect("xosc");
    assert!(text.contains("osc2cr:commonRoadPlanningProblem"), "{prefix}: the ego carries the planning problem");
}

#[test]
fn export_takes_a_path_or_a_commonroad_io_scenario() {
    let Some(env) = env() else { return };
    check_environment(&env.python, "2024.3");
    // commonroad-io 2026.1's reader and writer, the package from the same wheel
    let cr = testkit::python_envs().expect("python envs").cr;
    let script = format!("import sys; sys.path.insert(0, {:?})\n{EXPORT}", env.package_only.display().to_string());
    let file = commonroad_scenario("tests/test_scenarios/USA_US101-4_1_T-1.xml");
    let (p, o) = (tmp("2026.1-export-path"), tmp("2026.1-export-object"));
    let got = python(&cr, &script, &[&file, &p, &o]);
    assert_eq!(got, "path USA_US101-4_1_T-1.xosc True True\nobject USA_US101-4_1_T-1.xosc True\nbad option True\nmissing file True\n", "2026.1");
    let name = "USA_US101-4_1_T-1.xosc";
    assert_eq!(vertices(&p.join(name)).len(), vertices(&o.join(name)).len(), "2026.1: the same entities");
}
