#!/usr/bin/env python3
"""Closed loop: a small planner drives the ego of an OpenSCENARIO scenario, and CommonRoad's
tools judge the run.

esmini's `cut-in.xosc` has an OverTaker pass the ego at 1.2 times its speed, cut in ahead of it
once the ego's time headway to it exceeds 0.4 s, and brake to a stop once it exceeds 0.7 s. In
the scenario as written the ego keeps its 30 m/s and runs into the OverTaker. Here the ego is
driven by the planner below instead (`osc2cr.Simulation`, stepped every 0.1 s), and the
storyboard reacts to it (the OverTaker's speed follows the ego's, and the headway conditions
see the ego where the planner put it). The script

1. runs the scenario with the planner driving the ego: IDM for the speed (the vehicle ahead in
   the ego's lane — the lane centre from the lanelet network, following successors) and pure
   pursuit on the lane centre for the steering, integrated as a kinematic single-track model
   into the state the ego is to have 0.1 s later,
2. turns the run into a CommonRoad scenario (`Simulation.to_commonroad`, the ego's trajectory
   the one driven) and checks it with commonroad-drivability-checker (does the ego's box
   overlap another obstacle's at any time step?) and commonroad-crime (TTC, headway HW and
   time headway THW of the ego to the OverTaker at every time step, up to a collision), and
   does the same for the scenario as written (`osc2cr.convert`). commonroad-crime 0.4.5's TTC
   takes the other vehicle's acceleration without its sign, so while the vehicle ahead brakes
   it sees it speeding up and mostly finds no collision (infinite TTC); the summary adds the
   TTC at constant speeds, HW over the closing speed,
3. draws the run as an animated GIF with osc2cr's renderer (`Simulation.render`),
4. prints a JSON summary on stdout (non-finite values are `null`).

It needs commonroad-io 2024.3, commonroad-drivability-checker and commonroad-crime (the `crd`
environment of `../shared/tools/setup-venvs.sh`) and the osc2cr package:

    bash ../shared/tools/setup-venvs.sh target/py
    target/py/crd/bin/pip install .          # or put an installed osc2cr on PYTHONPATH
    target/py/crd/bin/python examples/closed_loop.py ../shared/corpus/esmini/xosc/cut-in.xosc \\
        --gif cut_in_closed_loop.gif

Exit status: 0 when the run and every tool ran (whatever they found), 2 on bad input.
"""

import argparse
import json
import logging
import math
import os
import sys
import warnings

import numpy as np

import osc2cr

# IDM (Treiber's intelligent driver model) and pure pursuit
TIME_GAP = 1.5  # s
MIN_GAP = 2.0  # m, bumper to bumper at a standstill
MAX_ACC = 1.5  # m/s², comfortable acceleration
COMFORT_DEC = 2.0  # m/s², comfortable deceleration
MAX_DEC = 9.0  # m/s², the most the planner brakes
DELTA = 4.0
LOOK_AHEAD_TIME = 0.8  # s: pure pursuit aims this far ahead on the lane centre (at least 6 m)
WHEELBASE = 2.6  # m
MAX_STEER = 0.6  # rad
LANE_HALF_WIDTH = 2.5  # m: an obstacle whose centre is this close to the ego's lane centre is in its lane


class LaneCentre:
    """The centre line of the lanelet the ego starts in and its successors, as a polyline
    with arc lengths; projection of points onto it."""

    def __init__(self, network, position, heading, length=2000.0):
        ids = network.find_lanelet_by_position([np.asarray(position, dtype=float)])[0]
        if not ids:
            raise SystemExit("the ego starts on no lanelet")

        def misalignment(lid):
            v = network.find_lanelet_by_id(lid).center_vertices
            i = int(np.argmin(np.linalg.norm(v - position, axis=1)))
            d = v[min(i + 1, len(v) - 1)] - v[max(i - 1, 0)]
            return abs(math.remainder(math.atan2(d[1], d[0]) - heading, 2 * math.pi))

        lanelet = network.find_lanelet_by_id(min(ids, key=misalignment))
        points = [lanelet.center_vertices]
        total = _length(lanelet.center_vertices)
        seen = {lanelet.lanelet_id}
        while lanelet.successor and total < length:
            lanelet = network.find_lanelet_by_id(lanelet.successor[0])
            if lanelet.lanelet_id in seen:
                break
            seen.add(lanelet.lanelet_id)
            points.append(lanelet.center_vertices[1:])
            total += _length(lanelet.center_vertices)
        p = np.vstack(points)
        keep = np.concatenate([[True], np.linalg.norm(np.diff(p, axis=0), axis=1) > 1e-6])
        self.p = p[keep]
        self.s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(self.p, axis=0), axis=1))])

    def project(self, point):
        """(arc length, signed lateral offset: left positive) of `point`."""
        a, b = self.p[:-1], self.p[1:]
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", point - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
        foot = a + t[:, None] * ab
        d = np.linalg.norm(point - foot, axis=1)
        i = int(np.argmin(d))
        cross = ab[i, 0] * (point[1] - a[i, 1]) - ab[i, 1] * (point[0] - a[i, 0])
        return self.s[i] + t[i] * math.hypot(*ab[i]), math.copysign(d[i], cross)

    def at(self, s):
        """The point at arc length `s` (straight on beyond the end)."""
        if s >= self.s[-1]:
            d = self.p[-1] - self.p[-2]
            return self.p[-1] + (s - self.s[-1]) * d / np.linalg.norm(d)
        return np.array([np.interp(s, self.s, self.p[:, 0]), np.interp(s, self.s, self.p[:, 1])])


def _length(v):
    return float(np.sum(np.linalg.norm(np.diff(v, axis=0), axis=1)))


def _half_length(obstacle):
    shape = obstacle.obstacle_shape
    return 0.5 * getattr(shape, "length", 2 * getattr(shape, "radius", 0.5))


class Planner:
    """IDM speed keeping behind the vehicle ahead in the lane, pure pursuit on the lane centre."""

    def __init__(self, observation, ego_length, desired_speed=None):
        ego = observation.ego
        self.lane = LaneCentre(observation.lanelet_network, ego.position, ego.orientation)
        self.v0 = desired_speed if desired_speed is not None else max(float(ego.velocity), 1.0)
        self.half_length = 0.5 * ego_length
        self.min_gap = math.inf  # bumper to bumper, to the vehicle ahead in the lane
        self.hardest_braking = 0.0

    def leader(self, observation, s_ego):
        """(gap bumper to bumper, speed) of the nearest road user ahead in the ego's lane."""
        best = None
        for o in observation.obstacles:
            s, d = self.lane.project(o.initial_state.position)
            if s > s_ego and abs(d) < LANE_HALF_WIDTH:
                gap = s - s_ego - self.half_length - _half_length(o)
                if best is None or gap < best[0]:
                    best = (gap, float(o.initial_state.velocity))
        return best

    def acceleration(self, v, leader):
        free = 1.0 - (v / self.v0) ** DELTA
        if leader is None:
            return max(-MAX_DEC, min(MAX_ACC, MAX_ACC * free))
        gap, v_leader = leader
        self.min_gap = min(self.min_gap, gap)
        wanted = MIN_GAP + max(0.0, v * TIME_GAP + v * (v - v_leader) / (2 * math.sqrt(MAX_ACC * COMFORT_DEC)))
        acc = MAX_ACC * (free - (wanted / max(gap, 0.1)) ** 2)
        return max(-MAX_DEC, min(MAX_ACC, acc))

    def next_state(self, observation, dt):
        """The state the ego is to have `dt` later (box centre, heading, speed)."""
        ego = observation.ego
        x, y = map(float, ego.position)
        h, v = float(ego.orientation), float(ego.velocity)
        s, _ = self.lane.project(np.array([x, y]))
        acc = self.acceleration(v, self.leader(observation, s))
        self.hardest_braking = min(self.hardest_braking, acc)
        # pure pursuit: the curvature of the arc to the point ahead on the lane centre
        look = max(6.0, LOOK_AHEAD_TIME * v)
        tx, ty = self.lane.at(s + look)
        alpha = math.atan2(ty - y, tx - x) - h
        steer = max(-MAX_STEER, min(MAX_STEER, math.atan2(2 * WHEELBASE * math.sin(alpha), look)))
        # kinematic single-track model over dt (midpoint rule)
        v1 = max(0.0, v + acc * dt)
        travelled = 0.5 * (v + v1) * dt
        turn = travelled * math.tan(steer) / WHEELBASE
        mid = h + 0.5 * turn
        return osc2cr.EntityState(x + travelled * math.cos(mid), y + travelled * math.sin(mid),
                                  math.remainder(h + turn, 2 * math.pi), v1)


def drive(path, ego_name, desired_speed):
    """Runs the scenario with the planner driving `ego_name`; returns the simulation."""
    sim = osc2cr.Simulation(path, external=[ego_name])
    observation = sim.reset()
    # the ego's box length, for the gaps (the observation has the other road users' shapes)
    planner = Planner(observation, sim.boxes[ego_name][2], desired_speed)
    while not sim.done:
        target = planner.next_state(observation, sim.dt)
        observation = sim.step({ego_name: target})
    return sim, planner


def finite_or_none(v):
    try:
        f = float(v)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) else None


def collisions(scenario, ego_id):
    """The time steps at which the ego's box overlaps another obstacle's, by obstacle."""
    import commonroad_dc.pycrcc as pycrcc
    from commonroad_dc.collision.collision_detection.pycrcc_collision_dispatch import create_collision_object

    ego = scenario.obstacle_by_id(ego_id)
    ego_co = create_collision_object(ego)
    others = {o.obstacle_id: create_collision_object(o) for o in scenario.obstacles if o.obstacle_id != ego_id}
    hits = {}
    for t in range(ego.initial_state.time_step, ego.prediction.final_time_step + 1):
        probe = pycrcc.TimeVariantCollisionObject(t)
        probe.append_obstacle(ego_co.obstacle_at_time(t))
        for oid, co in others.items():
            if co.collide(probe):
                hits.setdefault(oid, []).append(t)
    first = min((min(v) for v in hits.values()), default=None)
    return {"collides": bool(hits), "first_time_step": first,
            "first_time_s": None if first is None else round(first * scenario.dt, 6),
            "with": sorted(oid for oid, v in hits.items() if min(v) == first)}


def lowest(values, dt):
    """The smallest finite positive value of a per-time-step series and when, s."""
    finite = [(v, t) for t, v in enumerate(values) if v is not None and v > 0]
    low = min(finite, default=None)
    return {"finite": len(finite), "min": None if low is None else round(low[0], 4),
            "at_s": None if low is None else round(low[1] * dt, 6)}


def criticality(scenario, ego_id, other_id, last_step):
    """commonroad-crime's TTC, headway (HW, m) and time headway (THW, s) of the ego to
    `other_id` at every time step up to `last_step`, and the TTC at constant speeds (HW over
    the closing speed): the smallest value of each and when."""
    import commonroad_crime.measure as measures
    from commonroad_crime.data_structure.configuration import CriMeConfiguration

    config = CriMeConfiguration()
    config.update(ego_id=ego_id, sce=scenario)
    ego, other = scenario.obstacle_by_id(ego_id), scenario.obstacle_by_id(other_id)
    series = {}
    for name in ("TTC", "HW", "THW"):
        measure = getattr(measures, name)(config)
        values = []
        for t in range(0, last_step + 1):
            try:
                values.append(finite_or_none(measure.compute(vehicle_id=other_id, time_step=t, verbose=False)))
            except Exception:  # noqa: BLE001  (a step the measure cannot evaluate counts as none)
                values.append(None)
        series[name] = values
    constant_speed = []
    for t, hw in enumerate(series["HW"]):
        a, b = ego.state_at_time(t), other.state_at_time(t)
        closing = None if a is None or b is None else float(a.velocity) - float(b.velocity)
        constant_speed.append(hw / closing if hw is not None and closing is not None and closing > 1e-6 else None)
    out = {"other": other_id, "time_steps": last_step + 1}
    for name, values in (*series.items(), ("TTC_constant_speed", constant_speed)):
        out[name] = lowest(values, scenario.dt)
    return out


def evaluate(scenario, ego_id, other_id):
    col = collisions(scenario, ego_id)
    ego = scenario.obstacle_by_id(ego_id)
    last = col["first_time_step"] if col["collides"] else ego.prediction.final_time_step
    return {"collision": col, "criticality": criticality(scenario, ego_id, other_id, last)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenario", help="the OpenSCENARIO file (.xosc), e.g. esmini's cut-in.xosc")
    ap.add_argument("--ego", default="Ego", help="the entity the planner drives (default Ego)")
    ap.add_argument("--other", default="OverTaker", help="the road user TTC is measured to (default OverTaker)")
    ap.add_argument("--speed", type=float, help="the planner's desired speed, m/s (default: the ego's initial speed)")
    ap.add_argument("--gif", help="write the closed-loop run as an animated GIF here")
    ap.add_argument("--xml", help="write the closed-loop run as a CommonRoad file here")
    args = ap.parse_args()
    if not os.path.isfile(args.scenario):
        ap.error(f"{args.scenario}: no such file")

    # The tools print deprecation notes and progress, some of it from C++ straight to file
    # descriptor 1: send all of that to stderr and keep stdout for the JSON summary only.
    warnings.filterwarnings("ignore")
    logging.disable(logging.WARNING)
    sys.stdout.flush()
    out_json = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)

    sim, planner = drive(args.scenario, args.ego, args.speed)
    if args.other not in sim.entity_names:
        sys.exit(f"--other {args.other}: no such entity; the scenario has {', '.join(sim.entity_names)}")
    ids = sim.obstacle_ids
    closed, _ = sim.to_commonroad(lanelet_assignment=True)
    if args.xml:
        with open(args.xml, "w", encoding="utf-8") as f:
            f.write(sim.to_xml())
    scripted, _ = osc2cr.read_xml(osc2cr.convert_to_xml(args.scenario), lanelet_assignment=True)
    open_events = osc2cr.Simulation(args.scenario, external=[])
    while open_events.advance():
        pass

    def event_starts(s):
        return {e.element: e.time for e in s.events if e.transition == "start" and "Event" in e.element}

    summary = {
        "scenario": os.path.abspath(args.scenario),
        "ego": args.ego,
        "ego_id": ids[args.ego],
        "other_id": ids[args.other],
        "dt": sim.dt,
        "duration_s": round(sim.time, 6),
        "planner": {"min_gap_m": finite_or_none(round(planner.min_gap, 3)),
                    "hardest_braking_ms2": round(planner.hardest_braking, 3),
                    "final_speed_ms": round(float(sim.states_array()[sim.entity_names.index(args.ego)][3]), 3)},
        "events": {"closed_loop": event_starts(sim), "as_written": event_starts(open_events)},
        "closed_loop": evaluate(closed, ids[args.ego], ids[args.other]),
        "as_written": evaluate(scripted, ids[args.ego], ids[args.other]),
    }
    if args.gif:
        summary["gif"] = os.path.abspath(sim.render(args.gif, width=800))
    json.dump(summary, out_json, indent=1)
    out_json.write("\n")
    out_json.flush()


if __name__ == "__main__":
    main()
