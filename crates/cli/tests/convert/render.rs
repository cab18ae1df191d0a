//! `osc2cr convert --render`: a PNG beside each converted scenario, named like it; a picture
//! that cannot be written is a warning of the report, never a failed conversion.

use crate::common::*;

use std::collections::BTreeSet;
use std::path::Path;

fn report(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(path).expect("report written")).expect("report is JSON")
}

#[test]
fn a_picture_appears_beside_the_scenario() {
    let out = tmp("convert_render", "beside");
    let rep = out.join("report.json");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--render", "--report", s(&rep)]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    assert!(out.join("cut_in.xml").is_file());
    let png = out.join("cut_in.png");
    let bytes = std::fs::read(&png).expect("picture written beside the xml");
    let (w, h, rgba) = render::decode_png(&bytes).expect("a valid PNG");
    // the default width; the height follows the scene's aspect, so only its range is known
    assert_eq!(w, render::RenderOptions::default().width);
    assert!(h >= 64 && h <= 2 * w, "height {h}");
    assert_eq!(rgba.len(), (w * h * 4) as usize);
    let colours: BTreeSet<[u8; 3]> = rgba.chunks_exact(4).map(|p| [p[0], p[1], p[2]]).collect();
    assert!(colours.len() > 10, "only {} colours: not a drawing", colours.len());
    // the road takes a real share of the picture: not a blank canvas with a few pixels
    let road = rgba.chunks_exact(4).filter(|p| p[..3] == [render::style::ROAD.r, render::style::ROAD.g, render::style::ROAD.b]).count();
    assert!(road * 50 > (w * h) as usize, "road covers {road} of {} pixels", w * h);

    let json = report(&rep);
    let sc = &json["scenarios"][0];
    assert_eq!(sc["picture"].as_str(), Some(s(&png)));
    assert!(!sc["warnings"].as_array().expect("warnings").iter().any(|w| w["stage"] == "render"), "{sc}");
}

#[test]
fn without_render_no_picture() {
    let out = tmp("convert_render", "none");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out)]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    assert!(out.join("cut_in.xml").is_file());
    assert!(!out.join("cut_in.png").exists());
}

#[test]
fn a_picture_that_cannot_be_written_is_a_warning() {
    let out = tmp("convert_render", "blocked");
    // a folder where the picture should go: the atomic rename onto it fails
    std::fs::create_dir_all(out.join("cut_in.png").join("x")).unwrap();
    let rep = out.join("report.json");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--render", "--report", s(&rep)]);
    assert!(r.status.success(), "status {:?}: {}", r.status, String::from_utf8_lossy(&r.stderr));
    assert!(out.join("cut_in.xml").is_file(), "the scenario is still written");
    let json = report(&rep);
    let sc = &json["scenarios"][0];
    assert_eq!(sc["status"], "converted");
    assert!(sc["picture"].is_null());
    let render_warnings: Vec<_> = sc["warnings"].as_array().expect("warnings").iter().filter(|w| w["stage"] == "render").collect();
    assert_eq!(render_warnings.len(), 1, "{sc}");
    assert!(render_warnings[0]["message"].as_str().unwrap().contains("picture not written"));
    // no temporary file is left behind
    let left: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n != "cut_in.xml" && n != "cut_in.png" && n != "report.json")
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}
