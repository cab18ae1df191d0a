//! Every message names the real cause, in every command that meets it: a file that is not
//! there ("no such file"), a file that is not XML ("not well-formed XML" at its line:col), a
//! `--param` value that does not fit its parameter ("bad --param value", the parameter and its
//! type — and never "the declared value is kept" while the run fails), a road network that is not
//! there (at the line:col of the `<LogicFile>` naming it), a negative number (the option's own
//! check, not "unexpected argument"); none of them is announced as errors "against the
//! OpenSCENARIO schema" that `--lenient` would read as warnings. And what a newcomer reads
//! around them: the summary table says which time is which and has no empty folder cell, a
//! failed batch prints no table, an input that does not exist leaves no output folder behind,
//! `render` takes `--lenient`, `simulate --help` states the CSV's columns, and `--country` and
//! `--date` mean the same to `map` as to `convert`.

use crate::common::*;

use std::path::{Path, PathBuf};
use std::process::Output;

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn out(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Nothing of the wrong cause: the schema headline, the `--lenient` hint, the kept value.
fn no_wrong_cause(what: &str, text: &str) {
    for wrong in ["against the OpenSCENARIO schema", "--lenient", "the declared value is kept"] {
        assert!(!text.contains(wrong), "{what}: {wrong:?} in:\n{text}");
    }
}

/// A folder with a file that is not XML and the example with its road network renamed away.
fn inputs(name: &str) -> (PathBuf, PathBuf, PathBuf) {
    let dir = tmp("messages", name);
    let not_xml = dir.join("notes.xosc");
    std::fs::write(&not_xml, "these are notes,\nnot a scenario\n").expect("write");
    let no_map = dir.join("no_map.xosc");
    let text = std::fs::read_to_string(example()).expect("example").replace("two_lane_curve.xodr", "gone.xodr");
    std::fs::write(&no_map, text).expect("write");
    (dir, not_xml, no_map)
}

#[test]
fn a_missing_file_is_no_such_file_everywhere() {
    let dir = tmp("messages", "missing");
    let missing = dir.join("missing.xosc");
    let m = s(&missing);
    for args in [
        vec!["convert", m, "-o", "OUT"],
        vec!["render", m, "-o", "x.png"],
        vec!["simulate", m, "--trace", "t.csv"],
        vec!["inspect", m],
        vec!["check", m],
        vec!["map", "missing.xodr", "-o", "m.xml"],
    ] {
        let args: Vec<&str> = args.into_iter().map(|a| if a == "OUT" { s(&dir) } else { a }).collect();
        let (o, what) = (osc2cr(&args), args[0]);
        assert_eq!(o.status.code(), Some(2), "{what}: {}", err(&o));
        assert!(err(&o).contains("no such file"), "{what}: {}", err(&o));
        no_wrong_cause(what, &err(&o));
    }
}

#[test]
fn a_file_that_is_not_xml_is_not_well_formed_at_its_line_and_column() {
    let (dir, not_xml, _) = inputs("not_xml");
    let at = format!("{}:1:1: not well-formed XML", not_xml.display());
    let o = osc2cr(&["convert", s(&not_xml), "-o", s(&dir.join("out"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains(&at), "{}", err(&o));
    no_wrong_cause("convert", &err(&o));
    let o = osc2cr(&["render", s(&not_xml), "-o", s(&dir.join("x.png"))]);
    assert!(err(&o).contains(&at), "{}", err(&o));
    no_wrong_cause("render", &err(&o));
    let o = osc2cr(&["simulate", s(&not_xml), "--trace", s(&dir.join("t.csv"))]);
    assert!(err(&o).contains(&at), "{}", err(&o));
}

#[test]
fn a_param_that_does_not_fit_is_a_bad_param_value_naming_parameter_and_type() {
    let dir = tmp("messages", "param");
    let ex = example();
    let declared = format!("{}:8:5: bad --param value EgoSpeed=abc: parameter 'EgoSpeed' is declared double", ex.display());
    for args in [
        vec!["convert", s(&ex), "-o", s(&dir), "--param", "EgoSpeed=abc"],
        vec!["simulate", s(&ex), "--trace", "t.csv", "--param", "EgoSpeed=abc"],
        vec!["inspect", s(&ex), "--param", "EgoSpeed=abc"],
        vec!["render", s(&ex), "-o", "x.png", "--param", "EgoSpeed=abc"],
    ] {
        let (o, what) = (osc2cr(&args), args[0]);
        assert_eq!(o.status.code(), Some(2), "{what}: {}", err(&o));
        assert!(err(&o).contains(&declared) && err(&o).contains("'abc' is not a valid double"), "{what}: {}", err(&o));
        no_wrong_cause(what, &err(&o));
    }
    assert!(std::fs::read_dir(&dir).expect("dir").next().is_none(), "nothing written");
}

#[test]
fn a_missing_road_network_is_said_at_the_logic_file_that_names_it() {
    let (dir, _, no_map) = inputs("no_map");
    // line 13, column 5 of examples/cut_in.xosc: <LogicFile filepath="two_lane_curve.xodr"/>
    let at = format!("{}:13:5: the road network (LogicFile) {}: no such file", no_map.display(), dir.join("gone.xodr").display());
    for args in [
        vec!["convert", s(&no_map), "-o", s(&dir)],
        vec!["simulate", s(&no_map), "--trace", "t.csv"],
        vec!["render", s(&no_map), "-o", "x.png"],
        vec!["render", s(&no_map), "-o", "x.png", "--lenient"],
    ] {
        let (o, what) = (osc2cr(&args), args[0]);
        assert_eq!(o.status.code(), Some(2), "{what}: {}", err(&o));
        assert!(err(&o).contains(&at), "{what} (without -v): {}", err(&o));
    }
}

#[test]
fn render_takes_lenient_and_passes_it_to_the_conversion() {
    let dir = tmp("messages", "render_lenient");
    let file = dir.join("walkr.xosc");
    let text = std::fs::read_to_string(example()).expect("example").replace(r#"<Private entityRef="Walker">"#, r#"<Private entityRef="Walkr">"#);
    std::fs::write(&file, text).expect("write");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("road");
    let png = dir.join("w.png");
    let o = osc2cr(&["render", s(&file), "-o", s(&png)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("`Walkr` is not an entity") && err(&o).contains("--lenient"), "{}", err(&o));
    assert!(!png.exists());
    let o = osc2cr(&["render", s(&file), "-o", s(&png), "--lenient"]);
    assert_ok(&o);
    assert!(png.exists());
    let help = out(&osc2cr(&["render", "--help"]));
    assert!(help.contains("--lenient") && help.contains("--param"), "{help}");
}

#[test]
fn a_negative_number_reaches_the_option_s_own_check() {
    let dir = tmp("messages", "negative");
    let ex = example();
    let e = s(&ex);
    for (args, says) in [
        (vec!["convert", e, "-o", s(&dir), "--dt", "-1"], "--dt must be at least"),
        (vec!["convert", e, "-o", s(&dir), "--step", "-0.01"], "--step must be > 0"),
        (vec!["convert", e, "-o", s(&dir), "--max-time", "-5"], "--max-time must be > 0"),
        (vec!["convert", e, "-o", s(&dir), "--goal-length", "-1"], "--goal-length must be > 0"),
        (vec!["convert", e, "-o", s(&dir), "--goal-speed-margin", "-1"], "--goal-speed-margin must be >= 0"),
        (vec!["convert", e, "-o", s(&dir), "--timeout", "-1"], "--timeout must be a positive number"),
        (vec!["convert", e, "-o", s(&dir), "--map-tolerance", "-1"], "--map-tolerance must be > 0"),
        (vec!["convert", e, "-o", s(&dir), "--max-variations", "-1"], "expected a whole number of at least 0"),
        (vec!["convert", e, "-o", s(&dir), "--engine-seed", "-1"], "expected a whole number of at least 0"),
        (vec!["simulate", e, "--trace", "t.csv", "--max-time", "-1"], "max time must be a non-negative number"),
        (vec!["render", e, "-o", "x.png", "--time", "-1"], "--time must be a finite number of seconds >= 0"),
        (vec!["render", e, "-o", "x.png", "--trail", "-1"], "--trail must be"),
        (vec!["map", "m.xodr", "-o", "m.xml", "--tolerance", "-1"], "--tolerance -1 must be a positive number"),
    ] {
        let o = osc2cr(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", err(&o));
        assert!(err(&o).contains(says), "{args:?}: {}", err(&o));
        assert!(!err(&o).contains("unexpected argument"), "{args:?}: {}", err(&o));
    }
    assert!(std::fs::read_dir(&dir).expect("dir").next().is_none(), "nothing written");
}

#[test]
fn the_summary_says_which_time_is_which_and_a_failed_batch_has_no_table() {
    let (dir, not_xml, _) = inputs("summary");
    // a file given from its own folder: the folder cell is `.`, not empty
    std::fs::copy(example(), dir.join("cut_in.xosc")).expect("copy");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("road");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_osc2cr")).args(["convert", "cut_in.xosc", "-o", "out"]).current_dir(&dir).output().expect("runs");
    assert_ok(&o);
    let table = out(&o);
    let mut lines = table.lines();
    let header = lines.next().expect("a header");
    assert!(header.contains("mean conversion time") && header.contains("mean simulated time"), "{table}");
    let row = lines.nth(1).expect("a row");
    assert!(row.starts_with(". "), "{table}");
    // every input failed: the failure and the count, no table
    let o = osc2cr(&["convert", s(&not_xml), "-o", s(&dir.join("out2"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(out(&o).is_empty(), "{}", out(&o));
    assert!(err(&o).contains("0 converted, 1 failed"), "{}", err(&o));
    // the only input does not exist: no output folder
    let never = dir.join("never");
    let o = osc2cr(&["convert", s(&dir.join("missing.xosc")), "-o", s(&never)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!never.exists(), "{} was created", never.display());
}

#[test]
fn simulate_help_states_the_csv_columns() {
    let help = out(&osc2cr(&["simulate", "--help"]));
    assert!(!help.contains("conformance"), "{help}");
    for column in ["time (s)", "entity", "h (heading, rad)", "speed (m/s)", "bb_cx", "length", "lane_id", "lane_offset", "s (m along the road"] {
        assert!(help.contains(column), "{column} missing from:\n{help}");
    }
}

/// The header attribute `name` of a CommonRoad file.
fn header_attr(xml: &Path, name: &str) -> String {
    let text = std::fs::read_to_string(xml).expect("written");
    let doc = roxmltree::Document::parse(&text).expect("xml");
    doc.root_element().attribute(name).expect("attribute").to_string()
}

#[test]
fn country_and_date_mean_the_same_to_map_and_convert() {
    let dir = tmp("messages", "country");
    let xodr = testkit::workspace_root().join("examples/two_lane_curve.xodr");
    // the benchmark id's country, ZAM or ISO alpha-3, in both
    let m = dir.join("m.xml");
    assert_ok(&osc2cr(&["map", s(&xodr), "-o", s(&m), "--country", "DEU", "--date", "2024-05-06"]));
    assert!(header_attr(&m, "benchmarkID").starts_with("DEU_"), "{}", header_attr(&m, "benchmarkID"));
    assert_eq!(header_attr(&m, "date"), "2024-05-06");
    let c = dir.join("c");
    assert_ok(&osc2cr(&["convert", s(&example()), "-o", s(&c), "--country", "DEU", "--date", "2024-05-06"]));
    assert!(header_attr(&c.join("cut_in.xml"), "benchmarkID").starts_with("DEU_"));
    assert_eq!(header_attr(&c.join("cut_in.xml"), "date"), "2024-05-06");
    // a two-letter code is refused by both, with the same words
    for args in [vec!["map", s(&xodr), "-o", s(&m), "--country", "DE"], vec!["convert", s(&example()), "-o", s(&c), "--country", "DE"]] {
        let o = osc2cr(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(err(&o).contains("ZAM or an ISO 3166 alpha-3 code"), "{args:?}: {}", err(&o));
    }
    // the default date: the file's own header (OpenDRIVE's here), never today
    let text = std::fs::read_to_string(&xodr).expect("map");
    let declared = text.split("date=\"").nth(1).map(|d| d[..10].to_string());
    assert_ok(&osc2cr(&["map", s(&xodr), "-o", s(&m)]));
    assert_eq!(Some(header_attr(&m, "date")), declared.filter(|d| convert::parse_date(d).is_ok()).or(Some("1970-01-01".into())));
    let dated = dir.join("undated.xodr");
    std::fs::write(&dated, text.replacen("date=\"", "x-date=\"", 1)).expect("write");
    assert_ok(&osc2cr(&["map", s(&dated), "-o", s(&m)]));
    assert_eq!(header_attr(&m, "date"), "1970-01-01");
}
