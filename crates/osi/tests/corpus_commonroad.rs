//! An OSI trace of a corpus scenario against its CommonRoad output: the trace osc2cr writes of
//! esmini's acc-test opens with the osi3 Python bindings, holds one message per engine frame
//! (0.01 s apart from 0), and at every CommonRoad time step (0.1 s) each dynamic obstacle of the
//! conversion's 2020a file is a moving object of the message at that time: the same box centre
//! and orientation (within the XML's 6 decimals), and a speed within 0.05 m/s (OSI's velocity is
//! the displacement over the last 0.01 s step, CommonRoad's the speed at the step's end). The
//! road is flat: on a slope OSI's box centre is the 3D one, turned by the pitch, and lies up to
//! `cz · sin(pitch)` from CommonRoad's 2D centre (1.1 mm on cut-in's road).

use crate::common::*;

#[test]
fn a_corpus_trace_matches_the_commonroad_output_at_every_commonroad_step() {
    let Some(shared) = shared() else { return };
    let xosc = shared.join("corpus/esmini/xosc/acc-test.xosc");
    let dir = work_dir("corpus_commonroad");
    let trace = dir.join("acc-test.osi");
    let frames = write_trace(&xosc, &trace);
    let (conversion, _) = convert::convert(&convert::Request::file(&xosc), &convert::ConvertOptions::default());
    let xml = conversion.result.as_ref().ok().and_then(convert::Output::xml).expect("the conversion");
    let xml_path = dir.join("acc-test.xml");
    std::fs::write(&xml_path, xml).expect("written");
    let dynamic = xml.windows(b"<dynamicObstacle ".len()).filter(|w| w == b"<dynamicObstacle ").count();

    let json: serde_json::Value = serde_json::from_str(&run_py("osi_vs_commonroad.py", &[&trace, &xml_path, std::path::Path::new("0.01")])).expect("JSON");
    eprintln!("acc-test: {json}");
    let n = |k: &str| json[k].as_f64().unwrap_or(f64::INFINITY);
    assert_eq!(json["messages"].as_u64(), Some(frames as u64), "every message opens");
    assert!(frames > 3000, "one message per 0.01 s frame of the 33 s run: {frames}");
    assert!(n("timestamp_max") < 1e-6, "message k at k · 0.01 s");
    assert_eq!(json["unmatched"], serde_json::json!([]), "every obstacle is a moving object");
    assert_eq!(json["obstacles"].as_u64(), Some(dynamic as u64), "all {dynamic} dynamic obstacles compared");
    assert!(n("states") > 600.0, "every CommonRoad state compared");
    assert!(n("position_max") < 1e-5 && n("orientation_max") < 1e-5, "states: {json}");
    assert!(n("speed_max") < 0.05, "speeds: {json}");
}
