//! `osc2cr.Simulation` from Python, on esmini's cut-in: a run stepped to its end with
//! observations of commonroad-io objects (2024.3 and 2026.1), wrong inputs refused by name
//! with no step run, the ego fed its open-loop states writing the batch's bytes, an ego that
//! brakes moving the storyboard's events, the same inputs giving the same XML, observations
//! every N steps, the external entity a controller chooses, and the Gymnasium environment
//! through Gymnasium's own checker.

use serde_json::Value;

use super::{corpus, env, python};

fn json(out: &str) -> Value {
    let line = out.lines().rev().find(|l| l.starts_with('{')).unwrap_or_else(|| panic!("no JSON in:\n{out}"));
    serde_json::from_str(line).unwrap_or_else(|e| panic!("{e}: {line}"))
}

fn cut_in() -> std::path::PathBuf {
    corpus("esmini/xosc/cut-in.xosc")
}

/// Steps cut-in to its end with Ego going on along its heading at its speed (so the time
/// steps can be counted), and prints what the observations and the conversion hold.
const RUN: &str = r#"
import sys, json, math, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path = sys.argv[1]
batch = osc2cr.convert_to_xml(path)
sim = osc2cr.Simulation(path, external=["Ego"])
obs = sim.reset()
first = obs
pp = obs.planning_problem
out = {
    "entities": sim.entity_names, "external": sim.external, "ego": sim.ego, "ids": sim.obstacle_ids,
    "t0": obs.time, "k0": obs.time_step,
    "lanelets": len(obs.lanelet_network.lanelets),
    "obstacles": [[o.obstacle_id, o.obstacle_type.value] for o in obs.obstacles],
    "shapes_as_batch": all(
        (o.obstacle_shape.length, o.obstacle_shape.width) == (b.obstacle_shape.length, b.obstacle_shape.width)
        for o in obs.obstacles for b in [osc2cr.read_xml(batch)[0].obstacle_by_id(o.obstacle_id)]),
    "ego_at_problem_start": float(abs(obs.ego.position - pp.initial_state.position).max()),
    "ego_speed": float(obs.ego.velocity), "problem_speed": float(pp.initial_state.velocity),
    "external_states": sorted(obs.external),
}
times, steps = [], 0
while not sim.done:
    e = obs.ego
    x, y = e.position
    obs = sim.step({"Ego": osc2cr.EntityState(x + 0.1 * e.velocity * math.cos(e.orientation),
                                              y + 0.1 * e.velocity * math.sin(e.orientation), e.orientation, e.velocity)})
    steps += 1
    times.append(obs.time)
out["steps"] = steps
out["final_time"] = sim.time
out["final_step"] = obs.time_step
out["dt_ok"] = all(abs(b - a - 0.1) < 1e-9 for a, b in zip(times, times[1:-1]))
out["same_network"] = obs.lanelet_network is first.lanelet_network
try:
    sim.step({"Ego": "hold"})
    out["after_done"] = "stepped"
except RuntimeError as e:
    out["after_done"] = "RuntimeError"
scenario, problems = sim.to_commonroad()
ego = scenario.obstacle_by_id(sim.obstacle_ids["Ego"])
out["ego_final_time_step"] = ego.prediction.final_time_step
out["cr_obstacles"] = sorted(o.obstacle_id for o in scenario.dynamic_obstacles)
out["events"] = [e.element for e in sim.events if e.transition == "start" and e.element.endswith("Event")]
out["xml_differs_from_batch"] = sim.to_xml() != batch
out["batch_lanelets"] = batch.count("<lanelet id=")
print(json.dumps(out))
"#;

#[test]
fn a_run_stepped_to_its_end_observed_as_commonroad_objects() {
    let Some(env) = env() else { return };
    let file = cut_in();
    let check = |got: &Value| {
        let _ = got["steps"].as_u64().expect("steps");
        assert_eq!(got["entities"], serde_json::json!(["Ego", "OverTaker"]), "{got}");
        assert_eq!(got["external"], serde_json::json!(["Ego"]));
        assert_eq!(got["ego"], "Ego");
        assert_eq!(got["t0"], 0.0);
        assert_eq!(got["k0"], 0);
        // the lanelet network of the conversion, once for every observation
        assert_eq!(got["lanelets"], got["batch_lanelets"], "{got}");
        assert_eq!(got["same_network"], true);
        // the other road user with its conversion id, type and shape; the ego where its
        // planning problem starts, at its speed
        let overtaker = got["ids"]["OverTaker"].as_u64().expect("an id");
        assert_eq!(got["obstacles"], serde_json::json!([[overtaker, "car"]]), "{got}");
        assert_eq!(got["shapes_as_batch"], true, "{got}");
        assert!(got["ego_at_problem_start"].as_f64().expect("a number") < 1e-6, "{got}");
        assert_eq!(got["ego_speed"], got["problem_speed"]);
        assert_eq!(got["external_states"], serde_json::json!(["Ego"]));
        // cut-in's stop trigger fires 5 s after the OverTaker's manoeuvre ends (16.73 s), at
        // 21.74 s: within the 218th step of 0.1 s, which ends there; its time step is 217
        assert!((got["final_time"].as_f64().expect("time") - 21.74).abs() < 1e-6, "{got}");
        assert_eq!(got["steps"], 218, "{got}");
        assert_eq!(got["final_step"], 217, "{got}");
        assert_eq!(got["dt_ok"], true);
        assert_eq!(got["after_done"], "RuntimeError");
        // the run as CommonRoad: the ego's trajectory over every step driven
        assert_eq!(got["ego_final_time_step"], got["final_step"], "{got}");
        assert_eq!(got["cr_obstacles"].as_array().map(Vec::len), Some(2));
        assert_eq!(got["events"], serde_json::json!(["OverTakerStartSpeedEvent", "CutInEvent", "OvertakerBrakeEvent"]), "{got}");
        assert_eq!(got["xml_differs_from_batch"], true, "the ego did not drive the script's path");
    };
    let got = json(&python(&env.python, RUN, &[&file]));
    check(&got);
    // commonroad-io 2026.1 builds the observations and reads the run too
    let cr = testkit::python_envs().expect("python envs").cr;
    let script = format!("import sys; sys.path.insert(0, {:?})\n{RUN}", env.package_only.display().to_string());
    let got26 = json(&python(&cr, &script, &[&file]));
    check(&got26);
    assert_eq!(got26["steps"], got["steps"]);
}

const WRONG: &str = r#"
import sys, json, math, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
sim = osc2cr.Simulation(sys.argv[1], external=["Ego"])
sim.reset()
sim.step({"Ego": "hold"})
out = []
nan = float("nan")
for inputs in [
    {"Ego": (1.0, 2.0, nan, 3.0)},
    {"Ego": {"x": 1.0, "y": 2.0, "heading": 0.0, "speed": math.inf}},
    {},
    {"Ego": "hold", "OverTaker": "hold"},
    {"Egoo": "hold"},
    {"Ego": osc2cr.DriverInput(throttle=1.5)},
    {"Ego": osc2cr.DriverInput(steering=2.0)},
    {"Ego": "fly"},
    {"Ego": {"x": 1.0, "y": 2.0}},
    {"Ego": (1.0, 2.0, "north", 3.0)},
    {"Ego": object()},
]:
    before = (sim.time, sim.states_array().tolist())
    try:
        sim.step(inputs)
        out.append(["stepped", ""])
    except (ValueError, TypeError) as e:
        out.append([type(e).__name__, str(e)])
    assert (sim.time, sim.states_array().tolist()) == before, "a refused step moved the run"
arrays = []
for values, kind in [([1.0, 2.0, 3.0], "state"), ([0.5, 0.0], "driver"), ([0.0, 0.0, 0.0], "walk"), (b"\0" * 7, "state")]:
    try:
        sim.step_array(values, kind)
        arrays.append(["stepped", ""])
    except (ValueError, TypeError) as e:
        arrays.append([type(e).__name__, str(e)])
# a row of NaN holds; driver input rows of three
assert sim.step_array([math.nan] * 4)
assert sim.step_array([0.3, 0.0, 0.0], kind="driver")
for call in [lambda: osc2cr.Simulation(sys.argv[1], external=["Nobody"]),
             lambda: osc2cr.Simulation(sys.argv[1], dt=0.1, step=0.03),
             lambda: osc2cr.Simulation(sys.argv[1], motion="ignored"),
             lambda: osc2cr.Simulation(sys.argv[1], observe_every=0),
             lambda: osc2cr.Simulation(sys.argv[1], no_such_option=1)]:
    try:
        call()
        arrays.append(["made", ""])
    except (ValueError, TypeError) as e:
        arrays.append([type(e).__name__, str(e)])
print(json.dumps({"steps": out, "arrays": arrays, "time": sim.time}))
"#;

#[test]
fn wrong_inputs_are_refused_by_name_and_run_no_step() {
    let Some(env) = env() else { return };
    let got = json(&python(&env.python, WRONG, &[&cut_in()]));
    let expect = |list: &Value, i: usize, kind: &str, text: &str| {
        let e = &list[i];
        assert_eq!(e[0], kind, "#{i}: {e}");
        assert!(e[1].as_str().is_some_and(|m| m.contains(text)), "#{i}: {e} does not say {text:?}");
    };
    let steps = &got["steps"];
    // the engine's messages
    expect(steps, 0, "ValueError", "input for `Ego`: h is NaN, not a finite number");
    expect(steps, 1, "ValueError", "input for `Ego`: speed is inf, not a finite number");
    expect(steps, 2, "ValueError", "no input for `Ego`, which is driven from outside");
    expect(steps, 3, "ValueError", "`OverTaker` is not driven from outside (Ego is)");
    expect(steps, 4, "ValueError", "no entity named `Egoo`; the scenario has Ego, OverTaker");
    expect(steps, 5, "ValueError", "input for `Ego`: throttle is 1.5, outside 0..=1");
    expect(steps, 6, "ValueError", "input for `Ego`: steering is 2, outside -pi/2..=pi/2");
    // the forms Python accepts
    expect(steps, 7, "ValueError", "'fly' is not an input");
    expect(steps, 8, "TypeError", "heading is missing");
    expect(steps, 9, "TypeError", "heading must be a number, got 'north'");
    expect(steps, 10, "TypeError", "object is not an input");
    let arrays = &got["arrays"];
    expect(arrays, 0, "ValueError", "3 numbers for 1 external entities: expected 4 (x, y, heading, speed) or 8");
    expect(arrays, 1, "ValueError", "2 numbers for 1 external entities: expected 3 (throttle, brake, steering)");
    expect(arrays, 2, "ValueError", "kind must be \"state\" or \"driver\"");
    expect(arrays, 3, "ValueError", "7 bytes are not a whole number of float64 values");
    expect(arrays, 4, "ValueError", "no entity named `Nobody` to drive from outside; the scenario has Ego, OverTaker");
    expect(arrays, 5, "ValueError", "dt (0.1 s) must be a whole multiple of step (0.03 s)");
    expect(arrays, 6, "ValueError", "motion must be \"overridden\"");
    expect(arrays, 7, "ValueError", "observe_every must be an int >= 1");
    expect(arrays, 8, "TypeError", "unexpected keyword argument \"no_such_option\"");
    // one step before the refused ones, two after them (hold, driver input)
    assert!((got["time"].as_f64().expect("time") - 0.3).abs() < 1e-9, "{got}");
}

/// The ego's open-loop states, recorded from a run nobody drives, fed back: at the engine's
/// step as plain numbers (`step_array`) with the outside replacing the script, the batch's
/// bytes; every 0.1 s as commonroad-io states from `osc2cr.convert` (the poses in between
/// interpolated), the same storyboard events at the same times.
const REPLAY: &str = r#"
import sys, json, warnings
import numpy as np
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path = sys.argv[1]
out = {}
nobody = osc2cr.Simulation(path, external=[], dt=0.01, step=0.01)
ego = nobody.entity_names.index("Ego")
rows = []
while nobody.step_array(b""):
    rows.append(nobody.states_array()[ego])
rows.append(nobody.states_array()[ego])
out["nobody_is_batch"] = nobody.to_xml() == osc2cr.convert_to_xml(path, dt=0.01)
fed = osc2cr.Simulation(path, external=["Ego"], motion="replaced", dt=0.01, step=0.01)
k = 0
while not fed.done:
    fed.step_array(rows[k][:4])
    k += 1
out["replayed_is_batch"] = fed.to_xml() == osc2cr.convert_to_xml(path, dt=0.01)
out["engine_steps"] = k

scenario, _ = osc2cr.convert(path)
sim = osc2cr.Simulation(path, external=["Ego"], motion="replaced")
trajectory = scenario.obstacle_by_id(sim.obstacle_ids["Ego"]).prediction.trajectory
k = 1
sim.reset()
while not sim.done:
    state = trajectory.state_at_time_step(k)
    sim.step({"Ego": state if state is not None else "hold"})
    k += 1
starts = lambda s: [(e.element, e.time) for e in s.events if e.transition == "start" and e.element.endswith("Event")]
out["events"] = starts(sim)
out["batch_events"] = starts(nobody)
print(json.dumps(out))
"#;

#[test]
fn the_ego_fed_its_open_loop_states_gives_the_batch_run() {
    let Some(env) = env() else { return };
    let got = json(&python(&env.python, REPLAY, &[&cut_in()]));
    assert_eq!(got["nobody_is_batch"], true, "{got}");
    assert_eq!(got["replayed_is_batch"], true, "{got}");
    assert!(got["engine_steps"].as_u64().expect("steps") > 2000, "{got}");
    assert_eq!(got["events"], got["batch_events"], "{got}");
    assert_eq!(got["events"].as_array().map(Vec::len), Some(3), "{got}");
}

/// Cut-in with Ego on its open-loop path (recorded from a run nobody drives, by distance
/// travelled), at 30 m/s and from `brake_from` on braking at 6 m/s²; twice the same; and the
/// open loop.
const BRAKE: &str = r#"
import sys, json, math, warnings
import numpy as np
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path = sys.argv[1]
open_loop = osc2cr.Simulation(path, external=[], dt=0.01, step=0.01)
ego = open_loop.entity_names.index("Ego")
points = [open_loop.states_array()[ego]]
while open_loop.advance():
    points.append(open_loop.states_array()[ego])
p = np.array(points)
along = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1])))])
heading = np.unwrap(p[:, 2])
def at(d):
    return float(np.interp(d, along, p[:, 0])), float(np.interp(d, along, p[:, 1])), float(np.interp(d, along, heading))
def run(brake_from):
    sim = osc2cr.Simulation(path, external=["Ego"])
    d, v = 0.0, float(p[0, 3])
    while not sim.done:
        if sim.time + sim.dt > brake_from:
            v = max(0.0, v - 6.0 * sim.dt)
        d += v * sim.dt
        x, y, h = at(d)
        sim.advance({"Ego": (x, y, h, v)})
    return sim
a, b = run(2.0), run(2.0)
c = run(4.0)
out = {name: [open_loop.event_start(name), a.event_start(name), c.event_start(name)]
       for name in ("CutInEvent", "OvertakerBrakeEvent")}
out["same_xml"] = a.to_xml() == b.to_xml()
out["differs_when_braking_later"] = a.to_xml() != c.to_xml()
print(json.dumps(out))
"#;

#[test]
fn an_ego_that_brakes_moves_the_events_and_the_same_inputs_give_the_same_xml() {
    let Some(env) = env() else { return };
    let got = json(&python(&env.python, BRAKE, &[&cut_in()]));
    let t = |event: &str, i: usize| got[event][i].as_f64().unwrap_or_else(|| panic!("{event} never starts: {got}"));
    // the OverTaker keeps 1.2 times the ego's speed: with an ego that brakes, the 0.4 s
    // headway at which it cuts in comes at another time, and the 0.7 s headway at which it
    // brakes more than a second sooner (the ego falls back fast)
    assert!((t("CutInEvent", 1) - t("CutInEvent", 0)).abs() > 0.05, "{got}");
    assert!(t("OvertakerBrakeEvent", 1) < t("OvertakerBrakeEvent", 0) - 1.0, "{got}");
    assert!(t("OvertakerBrakeEvent", 2) < t("OvertakerBrakeEvent", 0) - 1.0, "braking from 4 s: {got}");
    assert_eq!(got["same_xml"], true, "the same inputs, another run: {got}");
    assert_eq!(got["differs_when_braking_later"], true);
}

const OBSERVE_EVERY: &str = r#"
import sys, json, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
sim = osc2cr.Simulation(sys.argv[1], external=["Ego"], observe_every=5)
sim.reset()
seen, steps = [], 0
while not sim.done:
    obs = sim.step({"Ego": osc2cr.DriverInput(throttle=0.2)})
    steps += 1
    if obs is not None:
        seen.append([obs.time_step, steps, len(obs.obstacles)])
print(json.dumps({"seen": seen, "steps": steps}))
"#;

#[test]
fn observations_come_every_n_steps_and_at_the_end() {
    let Some(env) = env() else { return };
    let got = json(&python(&env.python, OBSERVE_EVERY, &[&cut_in()]));
    let steps = got["steps"].as_u64().expect("steps");
    let seen = got["seen"].as_array().expect("list");
    let at: Vec<u64> = seen.iter().map(|s| s[1].as_u64().expect("step count")).collect();
    // every fifth step, and the last (the stop trigger ends cut-in within its 218th step)
    let mut expected: Vec<u64> = (5..=steps).step_by(5).collect();
    if !steps.is_multiple_of(5) {
        expected.push(steps);
    }
    assert_eq!(at, expected, "{got}");
    for s in &seen[..seen.len() - 1] {
        assert_eq!(s[0], s[1], "the observation is of the time step just run: {s}");
    }
    for s in seen {
        assert_eq!(s[2], 1, "the OverTaker in every observation: {s}");
    }
}

const CONTROLLER: &str = r#"
import sys, json, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
sim = osc2cr.Simulation(sys.argv[1])
out = {"rows": sim.external_rows, "at_start": sim.external}
while not sim.external:
    sim.step({})
out["taken_over_at"] = sim.time
out["now"] = sim.external
out["rows_now"] = sim.external_rows
try:
    sim.step({})
    out["without_input"] = "stepped"
except ValueError as e:
    out["without_input"] = str(e)
sim.step({"Ego": "dead_reckon"})
sim.step_array([0.0, 0.5, 0.0], kind="driver")
out["ego"] = sim.ego
print(json.dumps(out))
"#;

#[test]
fn by_default_the_entity_an_outside_driver_controls_is_external_once_its_controller_is_active() {
    let Some(env) = env() else { return };
    // esmini's controller_test: an InteractiveController takes Ego over when the time exceeds 10 s
    let got = json(&python(&env.python, CONTROLLER, &[&corpus("esmini/xosc/controller_test.xosc")]));
    // nobody at first: the controller is assigned at 10 s too
    assert_eq!(got["rows"], serde_json::json!([]), "{got}");
    assert_eq!(got["at_start"], serde_json::json!([]), "{got}");
    assert_eq!(got["rows_now"], serde_json::json!(["Ego"]), "{got}");
    assert!((got["taken_over_at"].as_f64().expect("time") - 10.1).abs() < 1e-6, "{got}");
    assert_eq!(got["now"], serde_json::json!(["Ego"]));
    assert!(got["without_input"].as_str().is_some_and(|m| m.contains("no input for `Ego`")), "{got}");
    assert_eq!(got["ego"], "Ego");
}

const GYM: &str = r#"
import sys, json, warnings
import numpy as np
import gymnasium as gym
from gymnasium.utils.env_checker import check_env
import osc2cr, osc2cr.gym
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
env = gym.make("osc2cr/Scenario-v0", path=sys.argv[1], render_mode="rgb_array")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    check_env(env.unwrapped)
notes = sorted({str(w.message) for w in caught if "infinity" not in str(w.message)})
obs, info = env.reset(seed=3)
out = {"shape": list(obs.shape), "entities": info["entities"], "notes": notes,
       "action": [env.action_space.shape[0], float(env.action_space.low[0]), float(env.action_space.high[0])]}
# coasting (no pedal): the ego slows, the OverTaker cuts in and stops ahead of it
total, steps = 0.0, 0
while True:
    obs, reward, terminated, truncated, info = env.step(np.zeros(2, dtype=np.float32))
    total += reward
    steps += 1
    if terminated or truncated:
        break
out.update(steps=steps, time=info["time"], collision=info["collision"], terminated=terminated,
           truncated=truncated, last_reward=reward, total=total)
frame = env.render()
out["frame"] = [int(frame.shape[0]), int(frame.shape[1]), int(frame.shape[2]), str(frame.dtype), int(frame.std() > 0)]
# a parameter of the scenario for one episode: the OverTaker's speed factor
obs2, _ = env.reset(options={"params": {"TargetSpeedFactor": 1.5}})
o1, *_ = env.step(np.zeros(2, dtype=np.float32))
out["faster_overtaker"] = float(o1[1][3])
env.reset()
o2, *_ = env.step(np.zeros(2, dtype=np.float32))
out["default_overtaker"] = float(o2[1][3])
env.close()
print(json.dumps(out))
"#;

#[test]
fn the_gymnasium_environment_passes_gymnasiums_checker_and_ends_in_a_collision_when_coasting() {
    let Some(env) = env() else { return };
    let got = json(&python(&env.python, GYM, &[&cut_in()]));
    // only the notes on unbounded positions (a map has no fixed extent)
    assert_eq!(got["notes"], serde_json::json!([]), "{got}");
    assert_eq!(got["shape"], serde_json::json!([2, 8]));
    assert_eq!(got["entities"], serde_json::json!(["Ego", "OverTaker"]));
    assert_eq!(got["action"], serde_json::json!([2, -1.0, 1.0]));
    // an ego without throttle slows; the OverTaker, at 1.2 times its speed, cuts in and brakes
    // to a stop ahead of it, and the ego runs into it
    assert_eq!(got["collision"], serde_json::json!(["OverTaker"]), "{got}");
    assert_eq!(got["terminated"], true);
    assert_eq!(got["truncated"], false);
    assert!(got["last_reward"].as_f64().expect("reward") < -50.0, "the collision penalty: {got}");
    let time = got["time"].as_f64().expect("time");
    assert!(time > 8.0 && time < 21.0, "{got}");
    let frame = &got["frame"];
    assert_eq!(frame[1], 640);
    assert_eq!(frame[2], 3);
    assert_eq!(frame[3], "uint8");
    assert_eq!(frame[4], 1, "the frame is not blank");
    let (fast, default) = (got["faster_overtaker"].as_f64().expect("speed"), got["default_overtaker"].as_f64().expect("speed"));
    assert!(fast > default + 1.0, "TargetSpeedFactor 1.5 for one episode: {fast} vs {default}");
}
