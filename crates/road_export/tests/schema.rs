//! Every export validates against the OpenDRIVE 1.8 schema of `../shared/spec`. The 1.8
//! schema is XSD 1.1 (xs:alternative, xs:assert), which libxml2 (xmllint, lxml) cannot
//! read: the test validates with xmlschema's XMLSchema11 in a virtual environment it makes
//! under `target/py-xsd`.

use crate::common::{exports, out_dir};
use std::path::{Path, PathBuf};
use std::process::Command;

fn python_with_xmlschema() -> Result<PathBuf, String> {
    let venv = testkit::workspace_root().join("target/py-xsd");
    let py = venv.join("bin/python");
    let ready = |py: &Path| Command::new(py).args(["-c", "import xmlschema"]).output().is_ok_and(|o| o.status.success());
    if ready(&py) {
        return Ok(py);
    }
    let made = Command::new("python3").args(["-m", "venv"]).arg(&venv).output().map_err(|e| format!("python3 -m venv: {e}"))?;
    if !made.status.success() {
        return Err(format!("python3 -m venv failed: {}", String::from_utf8_lossy(&made.stderr)));
    }
    let pip = Command::new(&py).args(["-m", "pip", "install", "-q", "xmlschema==4.3.2"]).output().map_err(|e| format!("pip: {e}"))?;
    if !pip.status.success() || !ready(&py) {
        return Err(format!("pip install xmlschema failed: {}", String::from_utf8_lossy(&pip.stderr)));
    }
    Ok(py)
}

#[test]
fn every_export_is_valid_opendrive_1_8() {
    let Some(exports) = exports() else { return };
    let Some(shared) = testkit::shared_dir() else { return };
    let py = match python_with_xmlschema() {
        Ok(p) => p,
        Err(e) if std::env::var_os("CI").is_none() => {
            eprintln!("notice: no Python with xmlschema ({e}); schema test skipped");
            return;
        }
        Err(e) => panic!("{e}"),
    };
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/py/validate_xodr.py");
    // a file the schema must refuse, so a validator that accepts everything fails the test
    let broken = out_dir().join("broken.xodr");
    let first = exports.first().expect("maps");
    std::fs::write(&broken, first.export.xodr.replacen("type=\"driving\"", "type=\"drivin\"", 1)).expect("writes");
    let out = Command::new(&py)
        .arg(&script)
        .arg(shared.join("spec/OpenDRIVE_1.8/local_schema"))
        .arg(&broken)
        .args(exports.iter().map(|e| &e.file))
        .output()
        .expect("runs the validator");
    let text = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<serde_json::Value> = text.lines().filter_map(|l| serde_json::from_str(l).ok()).collect();
    assert_eq!(lines.len(), exports.len() + 1, "validator output: {text}\n{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(lines[0]["valid"], false, "the broken file passed: {}", lines[0]);
    let invalid: Vec<String> = lines[1..].iter().filter(|l| l["valid"] != true).map(|l| l.to_string()).collect();
    eprintln!("{} of {} exports valid", exports.len() - invalid.len(), exports.len());
    assert!(invalid.is_empty(), "invalid exports:\n{}", invalid.join("\n"));
}
