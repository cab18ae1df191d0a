#!/usr/bin/env python3
"""The paper's evaluation, end to end: CommonRoad's own tools on a converted scenario.

esmini's `pedestrian_collision.xosc` has a car (the ego) drive at 9 m/s through a junction
while a pedestrian crosses its lane; the car does not brake and hits the pedestrian at about
5.5 s. This script

1. converts the scenario with `osc2cr convert` (or takes an already converted .xml),
2. reads it with commonroad-io,
3. with commonroad-drivability-checker: checks the ego's trajectory against every other
   obstacle over time (the first colliding time step, the obstacles hit, how long they stay
   in contact) and checks that the trajectory is kinematically feasible (kinematic
   single-track and point-mass models of a BMW 320i, `commonroad_dc.feasibility`),
4. with commonroad-crime: computes time-to-collision (TTC) and the measures that run on the
   same scenario (TTC*, THW, HW, DCE, …) for the ego against the obstacle it hits, at every
   time step up to the collision, and checks that TTC falls towards the collision,
5. prints a JSON summary on stdout (non-finite values, e.g. an infinite TTC, are `null`).

It needs the `crd` environment of `../shared/tools/setup-venvs.sh` (commonroad-io 2024.3,
commonroad-drivability-checker 2025.3.1, commonroad-crime 0.4.5):

    bash ../shared/tools/setup-venvs.sh target/py
    cargo build --release -p osc2cr
    target/py/crd/bin/python examples/evaluate_pedestrian_collision.py \\
        ../shared/corpus/esmini/xosc/pedestrian_collision.xosc --osc2cr target/release/osc2cr

Exit status: 0 when every tool ran (whatever it found), 2 on bad input or a failed conversion.
"""

import argparse
import json
import logging
import math
import os
import shutil
import subprocess
import sys
import tempfile
import warnings

# Ego vehicle model of the feasibility checks. Its wheelbase is the KS model's own for this
# vehicle type (vehiclemodels parameters_vehicle2: a + b = 2.578 m).
VEHICLE = "BMW_320i"
WHEELBASE = 2.578
MAX_STEER = 0.9  # rad, a little under the BMW 320i's steering limit (0.91)

# Measures of commonroad-crime computed against the obstacle the ego hits.
MEASURES = ["TTC", "TTCStar", "THW", "HW", "DCE", "WTTC", "TTCE"]


def finite_or_none(v):
    try:
        f = float(v)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) else None


def convert(xosc, osc2cr, out_dir):
    """Runs `osc2cr convert` and returns (the .xml path, the report entry)."""
    report = os.path.join(out_dir, "report.json")
    cmd = [osc2cr, "convert", xosc, "-o", out_dir, "--report", report]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("osc2cr convert failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
    with open(report, encoding="utf-8") as f:
        entry = json.load(f)["scenarios"][0]
    return entry["output"], entry


def find_osc2cr(given):
    if given:
        return given
    here = os.path.dirname(os.path.abspath(__file__))
    built = os.path.join(here, "..", "target", "release", "osc2cr")
    return built if os.path.exists(built) else (shutil.which("osc2cr") or "osc2cr")


def read(path):
    from commonroad.common.file_reader import CommonRoadFileReader
    # the lanelet assignment of every obstacle state is what commonroad-crime projects on
    return CommonRoadFileReader(path).open(lanelet_assignment=True)


def find_ego(sc, pps, ego_id):
    """The ego obstacle: `ego_id` if given, else the dynamic obstacle whose initial state is the
    planning problem's (osc2cr writes the ego both as an obstacle and as the planning problem)."""
    if ego_id is not None:
        ego = sc.obstacle_by_id(ego_id)
        if ego is None:
            sys.exit("--ego-id %d: no such obstacle" % ego_id)
        return ego, None
    for pid, pp in sorted(pps.planning_problem_dict.items()):
        s = pp.initial_state
        for o in sc.dynamic_obstacles:
            i = o.initial_state
            if i.time_step == s.time_step and math.dist(i.position, s.position) < 1e-3:
                return o, pid
    sys.exit("no dynamic obstacle starts where a planning problem does; pass --ego-id")


def ego_states(ego):
    return [ego.initial_state] + list(ego.prediction.trajectory.state_list)


def collisions(sc, ego):
    """First and last time step at which the ego's box overlaps another obstacle's, and which."""
    import commonroad_dc.pycrcc as pycrcc
    from commonroad_dc.collision.collision_detection.pycrcc_collision_dispatch import (
        create_collision_object)
    ego_co = create_collision_object(ego)
    others = {}
    for o in sc.obstacles:
        if o.obstacle_id != ego.obstacle_id:
            others[o.obstacle_id] = (o, create_collision_object(o))
    steps = [s.time_step for s in ego_states(ego)]
    hits = {}  # obstacle id -> time steps in contact
    for t in steps:
        probe = pycrcc.TimeVariantCollisionObject(t)
        probe.append_obstacle(ego_co.obstacle_at_time(t))
        for oid, (_, co) in others.items():
            if co.collide(probe):
                hits.setdefault(oid, []).append(t)
    res = {"collides": bool(hits), "first_time_step": None, "first_time_s": None,
           "with": [], "contact": []}
    if hits:
        first = min(min(v) for v in hits.values())
        res["first_time_step"] = first
        res["first_time_s"] = round(first * sc.dt, 6)
        res["with"] = sorted(oid for oid, v in hits.items() if min(v) == first)
        for oid, v in sorted(hits.items()):
            res["contact"].append({"obstacle": oid, "type": others[oid][0].obstacle_type.value,
                                   "first_time_step": min(v), "last_time_step": max(v),
                                   "steps": len(v)})
    return res


def closest_approach(sc, ego, other):
    """Smallest distance between the two reference points (centres), and when."""
    best = None
    for s in ego_states(ego):
        o = other.state_at_time(s.time_step)
        if o is None:
            continue
        d = math.dist(s.position, o.position)
        if best is None or d < best[0]:
            best = (d, s.time_step)
    if best is None:
        return None
    return {"distance_m": round(best[0], 4), "time_step": best[1],
            "time_s": round(best[1] * sc.dt, 6)}


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def feasibility(sc, ego):
    """The ego's trajectory checked with the kinematic single-track (KS) and point-mass (PM)
    models: commonroad_dc.feasibility reconstructs an input for every transition and checks
    that it reaches the next state within the checker's tolerances."""
    import numpy as np
    from commonroad.common.solution import VehicleType
    from commonroad.scenario.state import KSState, PMState
    from commonroad.scenario.trajectory import Trajectory
    from commonroad_dc.feasibility.feasibility_checker import trajectory_feasibility
    from commonroad_dc.feasibility.vehicle_dynamics import VehicleDynamics

    states = ego_states(ego)
    vt = getattr(VehicleType, VEHICLE)
    out = {"vehicle": VEHICLE, "transitions": len(states) - 1}

    ks = []
    for i, s in enumerate(states):
        v = float(getattr(s, "velocity", 0.0) or 0.0)
        # the steering angle the KS model needs for the heading change to the next state
        dth = wrap(float(states[i + 1].orientation) - float(s.orientation)) / sc.dt if i + 1 < len(states) else 0.0
        delta = math.atan(WHEELBASE * dth / v) if abs(v) > 0.1 else 0.0
        ks.append(KSState(time_step=s.time_step, position=np.array(s.position[:2], dtype=float),
                          velocity=v, orientation=float(s.orientation),
                          steering_angle=max(-MAX_STEER, min(MAX_STEER, delta))))
    pm = []
    for s in states:
        v = float(getattr(s, "velocity", 0.0) or 0.0)
        th = float(s.orientation)
        pm.append(PMState(time_step=s.time_step, position=np.array(s.position[:2], dtype=float),
                          velocity=v * math.cos(th), velocity_y=v * math.sin(th)))

    for name, model, sl in (("KS", VehicleDynamics.KS(vt), ks), ("PM", VehicleDynamics.PM(vt), pm)):
        try:
            ok, inputs = trajectory_feasibility(Trajectory(sl[0].time_step, sl), model, sc.dt)
            r = {"feasible": bool(ok)}
            if not ok:
                r["first_infeasible_transition"] = len(inputs.state_list) - 1 if inputs is not None else None
        except Exception as e:  # noqa: BLE001  (a checker failure is reported, not fatal)
            r = {"feasible": None, "error": "%s: %s" % (type(e).__name__, str(e)[:300])}
        out[name] = r
    return out


def criticality(sc, ego, other_id, last_step, stride):
    """commonroad-crime measures of the ego against obstacle `other_id` at time steps
    0, stride, 2·stride, … up to `last_step`."""
    import commonroad_crime.measure as measures
    from commonroad_crime.data_structure.configuration import CriMeConfiguration

    config = CriMeConfiguration()
    config.update(ego_id=ego.obstacle_id, sce=sc)
    steps = list(range(ego.initial_state.time_step, last_step + 1, stride))
    if steps and steps[-1] != last_step:
        steps.append(last_step)
    res = {"other": other_id, "time_steps": steps, "time_s": [round(t * sc.dt, 6) for t in steps],
           "values": {}, "errors": {}}
    for name in MEASURES:
        cls = getattr(measures, name, None)
        if cls is None:
            res["errors"][name] = "not in this commonroad-crime"
            continue
        try:
            m = cls(config)
        except Exception as e:  # noqa: BLE001
            res["errors"][name] = "%s: %s" % (type(e).__name__, str(e)[:300])
            continue
        vals = []
        for t in steps:
            try:
                vals.append(finite_or_none(m.compute(vehicle_id=other_id, time_step=t, verbose=False)))
            except Exception as e:  # noqa: BLE001
                vals.append(None)
                res["errors"].setdefault(name, "at time step %d: %s: %s" % (t, type(e).__name__, str(e)[:300]))
        res["values"][name] = vals
    return res


def ttc_trend(crit):
    """Does TTC fall towards the collision? Over the steps where it is finite and positive:
    the last value is below the first and at least 90 % of consecutive pairs do not rise."""
    pairs = [(t, v) for t, v in zip(crit["time_s"], crit["values"].get("TTC", [])) if v is not None and v > 0]
    out = {"finite_samples": len(pairs), "falls": False}
    if len(pairs) >= 3:
        vs = [v for _, v in pairs]
        down = sum(1 for a, b in zip(vs, vs[1:]) if b <= a + 1e-9)
        out.update(first={"time_s": pairs[0][0], "ttc_s": vs[0]},
                   last={"time_s": pairs[-1][0], "ttc_s": vs[-1]},
                   non_rising_share=round(down / (len(vs) - 1), 4),
                   falls=vs[-1] < vs[0] and down >= 0.9 * (len(vs) - 1))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenario", help="the OpenSCENARIO file (.xosc) to convert, or a converted CommonRoad .xml")
    ap.add_argument("--osc2cr", help="the osc2cr binary (default: target/release/osc2cr, else on PATH)")
    ap.add_argument("--ego-id", type=int, help="obstacle id of the ego (default: the obstacle that starts at the planning problem's initial state)")
    ap.add_argument("--out", help="folder for the converted file (default: a temporary folder, removed)")
    ap.add_argument("--stride", type=int, default=1, help="time steps between criticality evaluations (default 1)")
    args = ap.parse_args()
    if args.stride < 1:
        sys.exit("--stride must be at least 1")

    # The tools print deprecation notes and progress, some of it from C++ straight to file
    # descriptor 1 (pycrcc's "BVH Error! ..." when a road boundary has an empty part): send
    # all of that to stderr and keep the real stdout for the JSON summary only.
    warnings.filterwarnings("ignore")
    logging.disable(logging.WARNING)
    sys.stdout.flush()
    out_json = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)

    summary = {"input": os.path.abspath(args.scenario)}
    tmp = None
    try:
        if args.scenario.lower().endswith(".xml"):
            xml = args.scenario
        else:
            out = args.out or tempfile.mkdtemp(prefix="osc2cr-eval-")
            tmp = None if args.out else out
            xml, entry = convert(args.scenario, find_osc2cr(args.osc2cr), out)
            summary["conversion"] = {"output": None if tmp else xml, "ego_entity": entry.get("ego"),
                                     "engine_warnings": [w["message"] for w in entry.get("warnings", [])
                                                         if w.get("stage") == "engine"]}
        sc, pps = read(xml)
        import importlib.metadata as md
        summary["tools"] = {p: md.version(p) for p in
                            ("commonroad-io", "commonroad-drivability-checker", "commonroad-crime")}
        ego, pid = find_ego(sc, pps, args.ego_id)
        summary.update(scenario=str(sc.scenario_id), dt=sc.dt, ego_id=ego.obstacle_id,
                       planning_problem_id=pid,
                       obstacles=[{"id": o.obstacle_id, "type": o.obstacle_type.value} for o in sc.obstacles],
                       ego_final_time_step=ego.prediction.final_time_step)

        col = collisions(sc, ego)
        summary["collision"] = col
        # the obstacle the measures look at: the first one hit, else the nearest one
        others = [o for o in sc.dynamic_obstacles if o.obstacle_id != ego.obstacle_id]
        if col["with"]:
            other = sc.obstacle_by_id(col["with"][0])
        elif others:
            other = min(others, key=lambda o: (closest_approach(sc, ego, o) or {"distance_m": math.inf})["distance_m"])
        else:
            other = None
        summary["closest_approach"] = closest_approach(sc, ego, other) if other is not None else None
        summary["feasibility"] = feasibility(sc, ego)
        if other is not None:
            last = col["first_time_step"] if col["first_time_step"] is not None else summary["closest_approach"]["time_step"]
            crit = criticality(sc, ego, other.obstacle_id, int(last), args.stride)
            summary["criticality"] = crit
            summary["ttc_trend"] = ttc_trend(crit)
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)
    json.dump(summary, out_json, indent=1)
    out_json.write("\n")
    out_json.flush()


if __name__ == "__main__":
    main()
