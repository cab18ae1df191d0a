//! Malformed and hostile inputs end in a clear error or a correct file — never a panic, a hang
//! or a partial file. Each runs the real binary with a wall-clock limit.

use crate::common::*;

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// Converts `xosc` (written into a fresh folder with the example's road) and returns (exit
/// code, stderr, files written), failing if it takes longer than `limit`.
fn convert(name: &str, xosc: &str, limit: Duration) -> (Option<i32>, String, Vec<String>) {
    let dir = tmp("hostile", name);
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("road");
    let file = dir.join(format!("{name}.xosc"));
    std::fs::write(&file, xosc).expect("write");
    let out = dir.join("out");
    let start = Instant::now();
    // stderr to a file: a pipe nobody reads while waiting could block the child
    let err_path = dir.join("stderr.txt");
    let mut child = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(["convert", s(&file), "-o", s(&out), "--timeout", "20"])
        .stdout(std::process::Stdio::null())
        .stderr(std::fs::File::create(&err_path).expect("stderr file"))
        .spawn()
        .expect("runs");
    loop {
        if child.try_wait().expect("wait").is_some() {
            break;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            panic!("{name}: still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let status = child.wait().expect("status");
    let err = std::fs::read_to_string(&err_path).unwrap_or_default();
    let files = std::fs::read_dir(&out).map(|r| r.flatten().map(|e| e.file_name().to_string_lossy().to_string()).collect()).unwrap_or_default();
    (status.code(), err, files)
}

/// A clear error: exit 1 or 2, a message, no panic, and nothing (or nothing partial) written.
fn assert_clear_error(name: &str, (code, err, files): &(Option<i32>, String, Vec<String>)) {
    assert!(matches!(code, Some(1 | 2)), "{name}: exit {code:?}\n{err}");
    assert!(!err.contains("panicked"), "{name}: panic\n{err}");
    assert!(err.contains("error") || err.contains("failed"), "{name}: no message\n{err}");
    assert!(files.iter().all(|f| f.ends_with(".xml") && !f.contains("tmp")), "{name}: partial files {files:?}");
}

fn example() -> String {
    std::fs::read_to_string(testkit::workspace_root().join("examples/cut_in.xosc")).expect("example")
}

#[test]
fn entity_expansion_is_refused() {
    let laughs = r#"<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;"><!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;"><!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;"><!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;"><!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;"><!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;"><!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;"><!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">]>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="&lol9;" author=""/></OpenSCENARIO>"#;
    assert_clear_error("laughs", &convert("laughs", laughs, Duration::from_secs(30)));
}

#[test]
fn a_million_nested_elements_are_refused() {
    let deep = format!("<OpenSCENARIO>{}{}</OpenSCENARIO>", "<a>".repeat(1_000_000), "</a>".repeat(1_000_000));
    assert_clear_error("deep", &convert("deep", &deep, Duration::from_secs(30)));
}

#[test]
fn huge_nan_and_infinite_numbers_are_errors() {
    for (name, from, to) in [
        (
            "nan_speed",
            r#"<ParameterDeclaration name="EgoSpeed" parameterType="double" value="15"/>"#,
            r#"<ParameterDeclaration name="EgoSpeed" parameterType="double" value="NaN"/>"#,
        ),
        (
            "inf_speed",
            r#"<ParameterDeclaration name="EgoSpeed" parameterType="double" value="15"/>"#,
            r#"<ParameterDeclaration name="EgoSpeed" parameterType="double" value="inf"/>"#,
        ),
        ("huge_s", r#"<LanePosition roadId="1" laneId="-1" s="30" offset="0"/>"#, r#"<LanePosition roadId="1" laneId="-1" s="1e308" offset="0"/>"#),
    ] {
        let text = example();
        assert_eq!(text.matches(from).count(), 1, "{name}");
        let r = convert(name, &text.replace(from, to), Duration::from_secs(60));
        // a clear error, or a file that the audit passed
        if r.0 != Some(0) {
            assert_clear_error(name, &r);
        } else {
            assert_eq!(r.2.len(), 1, "{name}: {:?}", r.2);
        }
    }
}

#[test]
fn a_billion_step_stop_time_is_capped() {
    let text = example().replace(r#"<SimulationTimeCondition value="14" rule="greaterThan"/>"#, r#"<SimulationTimeCondition value="1e7" rule="greaterThan"/>"#);
    // the run stops at --max-time (60 s by default): a correct file, quickly
    let (code, err, files) = convert("long", &text, Duration::from_secs(60));
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(files, ["long.xml"]);
}

#[test]
fn a_road_with_a_hundred_thousand_geometries_is_handled() {
    let mut road = String::from(r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="100000" junction="-1"><planView>"#);
    for i in 0..100_000 {
        road.push_str(&format!(r#"<geometry s="{i}" x="{i}" y="0" hdg="0" length="1"><line/></geometry>"#));
    }
    road.push_str(r#"</planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#);
    let dir = tmp("hostile", "geometries_map");
    let map = dir.join("many.xodr");
    std::fs::write(&map, road).expect("write");
    let text = example().replace("two_lane_curve.xodr", s(&map)).replace(r#"laneId="-2""#, r#"laneId="-1""#);
    let r = convert("geometries", &text, Duration::from_secs(120));
    if r.0 != Some(0) {
        assert_clear_error("geometries", &r);
    }
}

#[test]
fn zero_length_roads_and_self_referencing_catalogs_end_cleanly() {
    let zero = r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="0" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="0"><line/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;
    let dir = tmp("hostile", "zero_map");
    let map = dir.join("zero.xodr");
    std::fs::write(&map, zero).expect("write");
    let r = convert("zero", &example().replace("two_lane_curve.xodr", s(&map)), Duration::from_secs(60));
    if r.0 != Some(0) {
        assert_clear_error("zero", &r);
    }
    // a catalog entry that refers to itself
    let cat_dir = tmp("hostile", "selfcat");
    std::fs::write(
        cat_dir.join("Self.xosc"),
        r#"<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/><Catalog name="Self"><Vehicle name="loop"><CatalogReference catalogName="Self" entryName="loop"/></Vehicle></Catalog></OpenSCENARIO>"#,
    )
    .expect("write");
    let text = example().replace(
        "<CatalogLocations/>",
        &format!(r#"<CatalogLocations><VehicleCatalog><Directory path="{}"/></VehicleCatalog></CatalogLocations>"#, s(&cat_dir)),
    );
    let text = text.replacen(
        "<ScenarioObject name=\"Ego\">",
        "<ScenarioObject name=\"Loop\"><CatalogReference catalogName=\"Self\" entryName=\"loop\"/></ScenarioObject><ScenarioObject name=\"Ego\">",
        1,
    );
    let r = convert("selfcat", &text, Duration::from_secs(60));
    assert_clear_error("selfcat", &r);
    let _ = Path::new("");
}

#[test]
fn deeply_nested_expressions_are_errors() {
    let expr = format!("${{{}1{}}}", "(".repeat(100_000), ")".repeat(100_000));
    let text = example().replace(r#"value="15"/>"#, &format!(r#"value="{expr}"/>"#));
    let r = convert("expr", &text, Duration::from_secs(30));
    assert_clear_error("expr", &r);
    // the message quotes the start of the expression, not all 200,000 characters
    assert!(r.1.len() < 2_000, "{} bytes of messages", r.1.len());
}
