#!/usr/bin/env python3
"""What stepping a scenario from Python costs, against the batch engine on the same run.

Every measurement runs the same run of the scenario (esmini's cut-in by default): the ego is
fed its own open-loop states, the outside replacing the script, which the tests hold to
give the batch's bytes. Printed per engine step (µs) and as a ratio to the batch engine:

* batch engine — the run in Rust, nobody driving from outside (`engine::simulate_with`'s loop)
* Rust, ego replayed — the same session stepped in Rust with the ego's states: what driving an
  entity from outside costs the engine itself (relocating it on the road each step)
* Python, nobody outside — `Simulation.step_array` with no rows: the cost of a call from Python
* Python fast path — `step_array` with the ego's row (numpy, x y heading speed) and
  `states_view()` read back every step: one engine step per call (dt = step = 0.01 s) and one
  CommonRoad step per call (dt = 0.1 s, ten engine steps)
* Python `advance` with a dict input — the convenient path without observations, per 0.1 s
* observations — what building the commonroad-io `Observation` costs per CommonRoad step (and
  per step with `observe_every=N`)

Medians of several runs, interleaved; the machine's load moves the absolute figures, the
ratios less. Run it from an environment with osc2cr (and commonroad-io for the observation
figures) installed:

    python crates/python/benches/closed_loop.py ../shared/corpus/esmini/xosc/cut-in.xosc
"""

import argparse
import statistics
import time
import warnings

import numpy as np

import osc2cr
from osc2cr import _osc2cr


def recorded(path):
    """The ego's name and its open-loop states at every engine step (rows of 4)."""
    sim = osc2cr.Simulation(path, external=[], dt=0.01, step=0.01)
    ego = sim.entity_names.index(sim.ego)
    rows = [sim.states_array()[ego, :4].copy()]
    while sim.step_array(b""):
        rows.append(sim.states_array()[ego, :4].copy())
    return sim.ego, rows


def fast_path(path, ego, rows, per_call):
    """Seconds of one replayed run through step_array + states_view, and engine steps."""
    sim = osc2cr.Simulation(path, external=[ego], motion="replaced", dt=0.01 * per_call, step=0.01)
    feed = rows[per_call::per_call] + [rows[-1]]
    t = time.perf_counter()
    for row in feed:
        going = sim.step_array(row)
        sim.states_view()
        if not going:
            break
    return time.perf_counter() - t, round(sim.time / 0.01)


def nobody(path):
    sim = osc2cr.Simulation(path, external=[], dt=0.01, step=0.01)
    step = sim.step_array
    t = time.perf_counter()
    while step(b""):
        pass
    return time.perf_counter() - t, round(sim.time / 0.01)


def advance(path, ego, rows):
    sim = osc2cr.Simulation(path, external=[ego], motion="replaced")
    feed = [osc2cr.EntityState(*map(float, r)) for r in rows[10::10]] + [osc2cr.EntityState(*map(float, rows[-1]))]
    t = time.perf_counter()
    for state in feed:
        if not sim.advance({ego: state}):
            break
    return time.perf_counter() - t, round(sim.time / 0.01)


def observations(path, ego, rows, count=60):
    """Seconds per observation, built after each of `count` steps (the first one, which reads
    the open-loop conversion and the lanelet network, not counted)."""
    sim = osc2cr.Simulation(path, external=[ego], motion="replaced")
    sim.reset()
    spent = []
    for row in rows[10::10][:count]:
        sim.step_array(row)
        t = time.perf_counter()
        sim.observe()
        spent.append(time.perf_counter() - t)
    return statistics.median(spent)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenario", help="an OpenSCENARIO file, e.g. ../shared/corpus/esmini/xosc/cut-in.xosc")
    ap.add_argument("--runs", type=int, default=15, help="runs per figure (default 15)")
    args = ap.parse_args()
    warnings.simplefilter("ignore", osc2cr.ConversionWarning)
    path = args.scenario
    ego, rows = recorded(path)

    samples = {k: [] for k in ("batch", "rust", "nobody", "fast1", "fast10", "advance")}
    steps = {}
    for _ in range(args.runs):  # interleaved, so that the machine's load falls on all alike
        n, (s,) = _osc2cr.engine_timing(path, 1)
        samples["batch"].append(s / n)
        n, (s,) = _osc2cr.engine_timing(path, 1, replay=True)
        samples["rust"].append(s / n)
        for key, (s, n) in (("nobody", nobody(path)), ("fast1", fast_path(path, ego, rows, 1)),
                            ("fast10", fast_path(path, ego, rows, 10)), ("advance", advance(path, ego, rows))):
            samples[key].append(s / n)
            steps[key] = n
    med = {k: statistics.median(v) for k, v in samples.items()}
    batch = med["batch"]
    print(f"{path}: {len(rows)} engine steps of 0.01 s, median of {args.runs} runs; per engine step:")
    rows_out = [
        ("batch engine (Rust)", "batch"),
        ("Rust, ego replayed from outside", "rust"),
        ("Python step_array, nobody outside", "nobody"),
        ("Python step_array + states_view, 1 engine step/call", "fast1"),
        ("Python step_array + states_view, 10 engine steps/call", "fast10"),
        ("Python advance({ego: EntityState}), 10 engine steps/call", "advance"),
    ]
    for label, key in rows_out:
        us = med[key] * 1e6
        print(f"  {label:<58} {us:7.2f} µs  {med[key] / batch:5.2f}x  (+{us - batch * 1e6:5.2f} µs)")
    print(f"  Python's own share at 1 engine step/call (fast path − Rust replay): "
          f"{(med['fast1'] - med['rust']) * 1e6:.2f} µs per call")
    try:
        obs = observations(path, ego, rows)
    except ImportError as e:
        print(f"observations: not measured ({e})")
        return
    step10 = med["fast10"] * 10
    print(f"per CommonRoad step (0.1 s): fast path {step10 * 1e6:.1f} µs; building the commonroad-io "
          f"Observation {obs * 1e6:.0f} µs ({obs / step10:.0f}x the step)")
    for n in (1, 5, 10):
        print(f"  observe_every={n:<3} {obs / n * 1e6:7.0f} µs of observations per step")


if __name__ == "__main__":
    main()
