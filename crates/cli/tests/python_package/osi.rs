//! `Simulation.osi_ground_truth()`: the current frame as an OSI GroundTruth message (bytes),
//! decoded here with osc2cr's OSI types: cut-in's Ego and OverTaker with esmini's OSI ids
//! (36, 37: after the road's 36 items), the host vehicle, the road's 14 lanes, the timestamp of
//! the session's time, and Ego's box centre where the session's state puts it.

use prost::Message;

use super::{corpus, env, python};

const OSI: &str = r#"
import sys, json, math
import osc2cr
sim = osc2cr.Simulation(sys.argv[1], external=["Ego"])
obs = sim.reset()
for _ in range(5):
    e = obs.ego
    x, y = e.position
    obs = sim.step({"Ego": osc2cr.EntityState(x + 0.1 * e.velocity * math.cos(e.orientation),
                                              y + 0.1 * e.velocity * math.sin(e.orientation), e.orientation, e.velocity)})
gt = sim.osi_ground_truth()
print(json.dumps({"time": sim.time, "ego": [float(v) for v in obs.ego.position], "bytes": gt.hex()}))
"#;

#[test]
fn osi_ground_truth_gives_the_current_frame() {
    let Some(env) = env() else { return };
    let out = python(&env.python, OSI, &[&corpus("esmini/xosc/cut-in.xosc")]);
    let line = out.lines().rev().find(|l| l.starts_with('{')).unwrap_or_else(|| panic!("no JSON in:\n{out}"));
    let v: serde_json::Value = serde_json::from_str(line).expect("JSON");
    let hex = v["bytes"].as_str().expect("hex");
    let bytes: Vec<u8> = (0..hex.len()).step_by(2).map(|i| u8::from_str_radix(&hex[i..i + 2], 16).expect("hex")).collect();
    let gt = osi::osi3::GroundTruth::decode(bytes.as_slice()).expect("a GroundTruth");
    let time = v["time"].as_f64().expect("time");
    let ts = gt.timestamp.expect("timestamp");
    assert!((ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9 - time).abs() < 1e-6);
    let ids: Vec<u64> = gt.moving_object.iter().filter_map(|o| o.id.and_then(|i| i.value)).collect();
    assert_eq!(ids, [36, 37], "esmini's OSI ids");
    assert_eq!(gt.host_vehicle_id.and_then(|i| i.value), Some(36));
    assert_eq!(gt.lane.len(), 14, "the road's lanes, in every message");
    let p = gt.moving_object[0].base.as_ref().and_then(|b| b.position).expect("Ego's position");
    let (x, y) = (v["ego"][0].as_f64().expect("x"), v["ego"][1].as_f64().expect("y"));
    // OSI's 3D box centre and CommonRoad's 2D one differ by the pitch (a few millimetres here)
    assert!((p.x.unwrap_or(0.0) - x).hypot(p.y.unwrap_or(0.0) - y) < 5e-3, "Ego at {p:?}, the session's ({x}, {y})");
}
