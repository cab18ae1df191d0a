//! `osc2cr convert` as a user runs it: the shipped example, exit codes, parameter variations,
//! atomic output, and the same bytes whatever `-j`.

use crate::common::*;

use std::path::{Path, PathBuf};

#[test]
fn the_example_converts_and_passes_the_oracle() {
    let out = tmp("convert_cli", "example");
    let report = out.join("report.json");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--report", s(&report)]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let xml = out.join("cut_in.xml");
    let text = std::fs::read_to_string(&xml).expect("output written");
    assert!(text.contains(r#"benchmarkID="ZAM_cutin-1_1_T-1""#));
    assert!(text.contains(r#"date="2026-11-22""#), "date from the FileHeader");
    assert!(text.contains("<simulated/>"));
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    let sc = &json["scenarios"][0];
    assert_eq!(sc["status"], "converted");
    assert_eq!(sc["ego"], "Ego");
    assert_eq!(sc["obstacles"], 3);
    assert!((sc["duration_s"].as_f64().expect("duration") - 14.0).abs() < 0.02);
    let summary = String::from_utf8_lossy(&r.stdout);
    assert!(summary.contains("100.0 %"), "{summary}");
    if testkit::shared_dir().is_none() {
        return;
    }
    let checked = testkit::cr_check(&[&xml], &["--on-road", "--on-road-min", "0.99"]);
    assert!(checked[0].ok, "{}", checked[0].summary());
}

#[test]
fn drop_ego_and_options_reach_the_file() {
    let out = tmp("convert_cli", "options");
    let r = osc2cr(&[
        "convert",
        s(&example()),
        "-o",
        s(&out),
        "--drop-ego",
        "--country",
        "DEU",
        "--date",
        "2024-02-29",
        "--author",
        "A. Author",
        "--affiliation",
        "Lab",
        "--goal-length",
        "30",
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let text = std::fs::read_to_string(out.join("cut_in.xml")).expect("output");
    assert!(text.contains(r#"benchmarkID="DEU_cutin-1_1_T-1""#));
    assert!(text.contains(r#"date="2024-02-29""#));
    assert!(text.contains(r#"author="A. Author""#) && text.contains(r#"affiliation="Lab""#));
    assert_eq!(text.matches("<dynamicObstacle ").count(), 2, "the ego is dropped");
    assert!(text.contains("<length>30.0"), "goal length");
}

#[test]
fn exit_codes() {
    let out = tmp("convert_cli", "exit");
    // a path that does not exist: bad usage
    let r = osc2cr(&["convert", "/nonexistent/x.xosc", "-o", s(&out)]);
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("/nonexistent/x.xosc"));
    // a malformed single scenario: bad input, named with line and column
    let bad = out.join("bad.xosc");
    std::fs::write(&bad, "<OpenSCENARIO><FileHeader/><Storyboard>").expect("write");
    let r = osc2cr(&["convert", s(&bad), "-o", s(&out.join("o1"))]);
    assert_eq!(r.status.code(), Some(2));
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(err.contains("bad.xosc:1:"), "{err}");
    // a folder with a good and a bad scenario: the batch goes on, exit 1
    let dir = out.join("mixed");
    std::fs::create_dir_all(&dir).expect("dir");
    std::fs::copy(example(), dir.join("good.xosc")).expect("copy");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("copy road");
    std::fs::copy(&bad, dir.join("bad.xosc")).expect("copy");
    // a catalog is skipped and said so
    std::fs::write(dir.join("cat.xosc"), "<OpenSCENARIO><FileHeader/><Catalog name=\"c\"/></OpenSCENARIO>").expect("write");
    let o2 = out.join("o2");
    let r = osc2cr(&["convert", s(&dir), "-o", s(&o2)]);
    assert_eq!(r.status.code(), Some(1));
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(err.contains("skipped") && err.contains("catalog"), "{err}");
    assert!(o2.join("good.xml").is_file());
    assert!(!o2.join("bad.xml").exists());
    // only temporary-free, whole files
    assert_eq!(files(&o2), [PathBuf::from("good.xml")]);
    // nothing to convert: bad usage
    let cats = out.join("cats");
    std::fs::create_dir_all(&cats).expect("dir");
    std::fs::copy(dir.join("cat.xosc"), cats.join("cat.xosc")).expect("copy");
    let r = osc2cr(&["convert", s(&cats), "-o", s(&out.join("o3"))]);
    assert_eq!(r.status.code(), Some(2));
    // a bad option value
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--dt", "-1"]);
    assert_eq!(r.status.code(), Some(2));
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--ego", "Nobody"]);
    assert_eq!(r.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&r.stderr).contains("Nobody"));
}

#[test]
fn parameter_overrides_change_the_result() {
    let out = tmp("convert_cli", "param");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--param", "EgoSpeed=10", "--report", s(&out.join("r.json"))]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let text = std::fs::read_to_string(out.join("cut_in.xml")).expect("output");
    // the planning problem's initial velocity is the ego's initial speed
    let pp = &text[text.find("<planningProblem").expect("planning problem")..];
    assert!(pp.contains("<velocity>\n        <exact>10.0") || pp.contains("<exact>10.0"), "{pp}");
}

#[test]
fn distributions_convert_to_capped_variations_in_order() {
    let Some(shared) = testkit::shared_dir() else { return };
    let dist = shared.join("corpus/esmini/xosc/cut-in_parameter_set.xosc");
    let out = tmp("convert_cli", "dist");
    let report = out.join("r.json");
    let r = osc2cr(&["convert", s(&dist), "-o", s(&out), "--max-variations", "3", "--report", s(&report), "-j", "2"]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let names: Vec<PathBuf> = files(&out).into_iter().filter(|p| p.extension().is_some_and(|e| e == "xml")).collect();
    assert_eq!(names, ["cut-in_parameter_set_1.xml", "cut-in_parameter_set_2.xml", "cut-in_parameter_set_3.xml"].map(PathBuf::from));
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    let sc = json["scenarios"].as_array().expect("scenarios");
    assert_eq!(sc.len(), 3);
    for (k, v) in sc.iter().enumerate() {
        assert_eq!(v["variation"]["index"], k as u64 + 1);
        assert!(!v["variation"]["parameters"].as_array().expect("parameters").is_empty());
        assert!(v["warnings"].to_string().contains("--max-variations"), "capped: said so");
    }
    let text = std::fs::read_to_string(out.join("cut-in_parameter_set_2.xml")).expect("output");
    assert!(text.contains(r#"benchmarkID="ZAM_cutinparameterset-1_2_T-1""#));
    // the variations differ
    let one = std::fs::read(out.join("cut-in_parameter_set_1.xml")).expect("1");
    assert_ne!(one, text.as_bytes());
}

#[test]
fn same_bytes_whatever_the_number_of_threads() {
    let Some(shared) = testkit::shared_dir() else { return };
    let input = shared.join("corpus/esmini/xosc");
    let (a, b) = (tmp("convert_cli", "j1"), tmp("convert_cli", "j2"));
    let ra = osc2cr(&["convert", s(&input), "-o", s(&a), "-j", "1", "--max-variations", "4"]);
    let rb = osc2cr(&["convert", s(&input), "-o", s(&b), "-j", "2", "--max-variations", "4"]);
    assert_eq!(ra.status.code(), rb.status.code());
    let msgs = |r: &std::process::Output, dir: &Path| String::from_utf8_lossy(&r.stderr).replace(s(dir), "OUT");
    assert_eq!(msgs(&ra, &a), msgs(&rb, &b), "same messages");
    let (fa, fb) = (files(&a), files(&b));
    assert_eq!(fa, fb);
    assert!(fa.len() > 50, "{} files", fa.len());
    for f in &fa {
        let (x, y) = (std::fs::read(a.join(f)).expect("a"), std::fs::read(b.join(f)).expect("b"));
        assert!(x == y, "{} differs between -j 1 and -j 2", f.display());
    }
}

#[test]
fn a_scenario_over_its_time_limit_fails_with_a_timeout_and_writes_nothing() {
    let out = tmp("convert_cli", "timeout");
    let o = osc2cr(&["convert", s(&example()), "-o", s(&out), "--timeout", "0.00001"]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("timeout stage") && err.contains("--timeout"), "{err}");
    assert!(!files(&out).iter().any(|f| f.extension().is_some_and(|e| e == "xml")), "{:?}", files(&out));
    let _ = std::fs::remove_dir_all(&out);
}
