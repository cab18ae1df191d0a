//! The paper's evaluation end to end (issue 7): `examples/evaluate_pedestrian_collision.py`
//! converts esmini's `pedestrian_collision.xosc` with this binary and runs CommonRoad's own
//! tools on the result — commonroad-drivability-checker (collision over time, kinematic
//! feasibility) and commonroad-crime (TTC and the measures that run beside it). The script is
//! the shipped example; this test holds it to what the paper reports.

use std::path::Path;
use std::process::Command;

use serde_json::Value;

fn f(v: &Value) -> Option<f64> {
    v.as_f64()
}

#[test]
fn pedestrian_collision_collides_at_about_5_5_s_feasibly_with_falling_ttc() {
    let Some(shared) = testkit::shared_dir() else {
        return;
    };
    let xosc = shared.join("corpus/esmini/xosc/pedestrian_collision.xosc");
    assert!(xosc.is_file(), "{} missing from the corpus", xosc.display());
    let envs = testkit::python_envs().unwrap_or_else(|e| panic!("Python environments: {e}"));
    let script = testkit::workspace_root().join("examples/evaluate_pedestrian_collision.py");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("evaluation");
    let _ = std::fs::remove_dir_all(&out);
    let run =
        Command::new(&envs.crd).arg(&script).arg(&xosc).args(["--osc2cr", env!("CARGO_BIN_EXE_osc2cr"), "--out"]).arg(&out).output().expect("python runs");
    assert!(run.status.success(), "{} failed ({}):\n{}", script.display(), run.status, String::from_utf8_lossy(&run.stderr));
    let j: Value = serde_json::from_slice(&run.stdout).unwrap_or_else(|e| panic!("not JSON ({e}):\n{}", String::from_utf8_lossy(&run.stdout)));
    let summary = serde_json::to_string_pretty(&j).unwrap_or_default();

    // The ego is the car the planning problem starts from; the other obstacle the pedestrian.
    let ego = j["ego_id"].as_u64().expect("ego found");
    let obstacles = j["obstacles"].as_array().expect("obstacles");
    let type_of = |id: u64| obstacles.iter().find(|o| o["id"].as_u64() == Some(id)).and_then(|o| o["type"].as_str()).unwrap_or("?").to_string();
    assert_eq!(type_of(ego), "car", "{summary}");
    assert_eq!(j["dt"].as_f64(), Some(0.1));

    // Collision. esmini 3.6.0 detects it at 5.43 s (its reference event log: the
    // CollisionCondition fires then, at its 0.01 s step, on its bounding boxes — the car
    // 5.04 × 2.0 m, the pedestrian 0.6 × 0.5 m). CommonRoad samples every 0.1 s, so the first
    // time step whose boxes overlap is the first multiple of 0.1 s at or after the contact:
    // 5.5 s for a contact at 5.43 s, as the paper reports. We accept one CommonRoad step either
    // side (5.4–5.6 s): our engine's trajectory following and the resampling of the boxes to
    // the CommonRoad step move the contact by a few hundredths of a second, and a contact that
    // lands just before or after a step boundary then shifts the first step by one.
    let col = &j["collision"];
    assert_eq!(col["collides"], true, "no collision found:\n{summary}");
    let t = f(&col["first_time_s"]).expect("first collision time");
    assert!((5.35..=5.65).contains(&t), "first collision at {t} s, expected 5.4–5.6 s:\n{summary}");
    let hit = col["with"].as_array().expect("with");
    assert_eq!(hit.len(), 1, "{summary}");
    assert_eq!(type_of(hit[0].as_u64().expect("id")), "pedestrian", "{summary}");

    // Kinematic feasibility: the car drives straight at a constant 9 m/s; both the kinematic
    // single-track and the point-mass model of commonroad_dc.feasibility must reproduce every
    // transition of its trajectory.
    let feas = &j["feasibility"];
    assert_eq!(feas["KS"]["feasible"], true, "{summary}");
    assert_eq!(feas["PM"]["feasible"], true, "{summary}");

    // Criticality. TTC* (commonroad-crime: the time until the ego's own trajectory collides)
    // at t = 0 must be the collision time the drivability checker found: two tools, one answer.
    let crit = &j["criticality"];
    let ttc_star0 = f(&crit["values"]["TTCStar"][0]).expect("TTC* at t = 0");
    assert!((ttc_star0 - t).abs() < 0.05, "TTC* {ttc_star0} s vs collision at {t} s:\n{summary}");
    // TTC (constant-acceleration model along the ego's lanelet) is finite once the pedestrian is
    // ahead of the car in its lane's coordinate system (from about 4.5 s: before, the pedestrian
    // on the far pavement is outside the projection domain, TTC is infinite) and must fall
    // towards the collision, since the car keeps its 9 m/s and the gap closes.
    let trend = &j["ttc_trend"];
    assert_eq!(trend["falls"], true, "TTC does not fall:\n{summary}");
    let last = f(&trend["last"]["ttc_s"]).expect("last TTC");
    let first = f(&trend["first"]["ttc_s"]).expect("first TTC");
    assert!(last < first, "{summary}");
    // Just before the contact the time to it is short: less than a second.
    assert!(last < 1.0, "TTC {last} s just before the collision:\n{summary}");
}
