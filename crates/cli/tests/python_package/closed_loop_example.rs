//! `examples/closed_loop.py`, the example a planner author copies: its IDM + pure-pursuit
//! planner drives cut-in's ego through `osc2cr.Simulation`, and CommonRoad's tools (the `crd`
//! environment: commonroad-drivability-checker, commonroad-crime) judge the run and the
//! scenario as written; the run is drawn as a GIF. The package comes from the wheel these
//! tests built (`pip install --target`), on `PYTHONPATH`.

use std::process::Command;

use serde_json::Value;

use super::{corpus, env, tmp};

fn gif_frames(path: &std::path::Path) -> (u16, usize) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut d = gif::DecodeOptions::new().read_info(bytes.as_slice()).expect("a GIF");
    let width = d.width();
    let mut n = 0;
    while d.read_next_frame().expect("a frame").is_some() {
        n += 1;
    }
    (width, n)
}

#[test]
fn the_planner_drives_cut_in_without_collision_where_the_script_collides() {
    let Some(env) = env() else { return };
    let crd = testkit::python_envs().unwrap_or_else(|e| panic!("Python environments: {e}")).crd;
    let script = testkit::workspace_root().join("examples/closed_loop.py");
    let out = tmp("closed-loop-example");
    let gif = out.join("cut_in_closed_loop.gif");
    let run = Command::new(&crd)
        .arg(&script)
        .arg(corpus("esmini/xosc/cut-in.xosc"))
        .arg("--gif")
        .arg(&gif)
        .env("PYTHONPATH", &env.package_only)
        .output()
        .expect("python runs");
    assert!(run.status.success(), "{} failed ({}):\n{}", script.display(), run.status, String::from_utf8_lossy(&run.stderr));
    let j: Value = serde_json::from_slice(&run.stdout).unwrap_or_else(|e| panic!("not JSON ({e}):\n{}", String::from_utf8_lossy(&run.stdout)));
    let summary = serde_json::to_string_pretty(&j).unwrap_or_default();
    let f = |v: &Value| v.as_f64().unwrap_or_else(|| panic!("not a number: {v}\n{summary}"));

    // As written, the ego keeps 30 m/s and runs into the OverTaker, which cut in and braked
    // to a stop ahead of it (commonroad-drivability-checker).
    let scripted = &j["as_written"];
    assert_eq!(scripted["collision"]["collides"], true, "{summary}");
    assert_eq!(scripted["collision"]["with"], serde_json::json!([j["other_id"]]), "{summary}");
    // Driven by the planner, it follows the OverTaker and stops behind it.
    let closed = &j["closed_loop"];
    assert_eq!(closed["collision"]["collides"], false, "{summary}");
    assert!(f(&j["planner"]["final_speed_ms"]) < 1.0, "the ego stops behind the OverTaker: {summary}");
    assert!(f(&j["planner"]["min_gap_m"]) > 1.0, "{summary}");
    assert!(f(&j["planner"]["hardest_braking_ms2"]) < -1.0, "the planner brakes for the cut-in: {summary}");
    // the storyboard ran its course: the cut-in and the braking happened in the closed loop
    for event in ["CutInEvent", "OvertakerBrakeEvent"] {
        assert!(j["events"]["closed_loop"][event].is_number(), "{event}: {summary}");
    }
    // commonroad-crime: the headway to the OverTaker never closes in the closed loop, and the
    // time to collision at constant speeds stays above a second, while the scripted ego's
    // falls to nothing just before its collision
    let crit = &closed["criticality"];
    assert!(f(&crit["HW"]["min"]) > 1.0, "{summary}");
    let ttc = f(&crit["TTC_constant_speed"]["min"]);
    assert!(ttc > 1.0, "closed loop TTC {ttc} s: {summary}");
    assert!(f(&scripted["criticality"]["TTC_constant_speed"]["min"]) < 0.5, "{summary}");
    assert!(crit["TTC"]["finite"].as_u64().is_some(), "commonroad-crime's TTC ran: {summary}");

    // the GIF of the run: a frame per CommonRoad step, or every k-th of them
    let (width, frames) = gif_frames(&gif);
    assert_eq!(width, 800);
    let steps = (f(&j["duration_s"]) / f(&j["dt"])) as usize;
    assert!(frames >= 50 && frames <= steps + 1, "{frames} frames for {steps} steps");
}
