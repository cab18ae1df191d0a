//! Malformed input: messages name what was expected, with the right line and column.

use opendrive::{parse_str, Error};
use std::path::Path;

fn err(text: &str) -> Error {
    match parse_str(text, Path::new("bad.xodr")) {
        Ok(_) => panic!("expected an error"),
        Err(e) => e,
    }
}

const ROAD_HEAD: &str = "<OpenDRIVE>\n<header revMajor=\"1\" revMinor=\"6\"/>\n<road id=\"1\" length=\"10\" junction=\"-1\">\n<planView>\n";
const ROAD_TAIL: &str =
    "</planView>\n<lanes><laneSection s=\"0\"><center><lane id=\"0\" type=\"none\"/></center></laneSection></lanes>\n</road>\n</OpenDRIVE>\n";

#[test]
fn unclosed_tag() {
    let e = err("<OpenDRIVE>\n  <header revMajor=\"1\" revMinor=\"6\">\n</OpenDRIVE>\n");
    let msg = e.to_string();
    assert!(matches!(e, Error::Xml { .. }), "{msg}");
    assert!(msg.starts_with("bad.xodr:3:"), "{msg}");
}

#[test]
fn not_a_number() {
    let text = format!("{ROAD_HEAD}  <geometry s=\"0\" x=\"abc\" y=\"0\" hdg=\"0\" length=\"10\"><line/></geometry>\n{ROAD_TAIL}");
    let e = err(&text);
    let msg = e.to_string();
    // x's value starts at line 5, column 22 (two spaces, `<geometry s="0" x="` is 19 more)
    assert_eq!(e.position().map(|p| (p.line, p.col)), Some((5, 22)), "{msg}");
    assert!(msg.contains("expected a number") && msg.contains("`abc`") && msg.contains("`x`"), "{msg}");
}

#[test]
fn non_finite_number() {
    let text = format!("{ROAD_HEAD}<geometry s=\"0\" x=\"0\" y=\"NaN\" hdg=\"0\" length=\"10\"><line/></geometry>\n{ROAD_TAIL}");
    let msg = err(&text).to_string();
    assert!(msg.starts_with("bad.xodr:5:26:") && msg.contains("finite"), "{msg}");
    let text = format!("{ROAD_HEAD}<geometry s=\"0\" x=\"0\" y=\"1e999\" hdg=\"0\" length=\"10\"><line/></geometry>\n{ROAD_TAIL}");
    assert!(err(&text).to_string().contains("finite"));
}

#[test]
fn missing_attribute() {
    let text = format!("{ROAD_HEAD}<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\"><line/></geometry>\n{ROAD_TAIL}");
    let msg = err(&text).to_string();
    assert!(msg.starts_with("bad.xodr:5:1:"), "{msg}");
    assert!(msg.contains("missing the required attribute `length`"), "{msg}");
}

#[test]
fn missing_file_names_the_path() {
    let e = opendrive::load("/nonexistent/dir/map.xodr").expect_err("error");
    assert!(e.to_string().contains("/nonexistent/dir/map.xodr"), "{e}");
}

#[test]
fn wrong_root_element() {
    let msg = err("<OpenSCENARIO/>").to_string();
    assert!(msg.contains("expected the root element <OpenDRIVE>"), "{msg}");
}

#[test]
fn a_file_cut_off_is_reported_where_it_ends() {
    // Cut inside the fourth line, 5 characters into `<planView>`: the error is at 4:6.
    let text = format!("{ROAD_HEAD}{ROAD_TAIL}");
    let cut_at = ROAD_HEAD.len() - "iew>\n".len() - 1;
    let e = err(&text[..cut_at]);
    let msg = e.to_string();
    assert!(matches!(e, Error::Xml { line: 4, col: 6, .. }), "{msg}");
    // And a file whose root is never closed, ending after a newline: the position after it.
    let e = err("<OpenDRIVE>\n<header revMajor=\"1\" revMinor=\"6\"/>\n");
    assert!(matches!(e, Error::Xml { line: 3, col: 1, .. }), "{}", e);
}

#[test]
fn superelevation_warning_says_what_is_flat_and_what_is_banked() {
    let text = ROAD_HEAD.to_string()
        + "<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"10\"><line/></geometry>\n"
        + "</planView>\n<lateralProfile><superelevation s=\"0\" a=\"0.1\" b=\"0\" c=\"0\" d=\"0\"/></lateralProfile>\n"
        + &ROAD_TAIL["</planView>\n".len()..];
    let loaded = parse_str(&text, Path::new("banked.xodr")).expect("a banked road parses");
    let w: Vec<String> = loaded.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("the simulation banks the road") && w[0].contains("lanelet borders"), "{w:?}");
    assert!(w[0].contains("banked.xodr:7:17:"), "the warning carries file:line:col: {w:?}");
    assert_eq!(loaded.network.roads[0].superelevation.len(), 1);
}
