"""Read a scenario in both CommonRoad formats with one commonroad-io and compare, object by object.

    python compare_2024.py CASES.json

CASES.json is a list of {"xml": ..., "map": ..., "scenario": ..., "dynamic": ...}: the 2020a
file of a conversion and the three 2024 files of the same conversion. For each case one JSON
line is printed: {"xml", "ok", "differences" (the first 25), "n_differences", "counted" (objects
compared), "error" (a reader's exception, if any)}. Exit status 0 when every case is ok.

The 2020a file is read with CommonRoadFileReader(filename_2020a=...).open(), the 2024 files
with CommonRoadFileReader(filename_map=..., filename_scenario=..., filename_dynamic=...).open_all().
Every attribute the two readings hold is compared; a difference names the object and the field.

Tolerance: the 2020a XML writes decimals with 6 digits (osc2cr's writer rounds to 0.5e-6), the
2024 files hold the doubles; a real number may differ by at most 5.000001e-7 — nothing else is
forgiven.

Where the two formats keep the same fact in different places, the comparison follows the fact:
  * scenario tags: 2020a on the scenario, 2024 on every planning problem (the 2024 reader leaves
    Scenario.tags unset);
  * the file date: the 2020a reader does not keep it (it sets "now"), so the 2024 date is
    compared with the XML's date attribute;
  * a sign's `virtual`: the 2020a reader ignores the <virtual> element (always False), so the
    2024 value is compared with the element's text;
  * a stop line's sign/light references: the 2024 StopLine has none, so every reference the
    2020a stop line holds must be a reference of its lanelet in the 2024 reading;
  * ids of bounds and stop lines: 2024 objects of their own, which the 2020a reader numbers after
    the scenario's highest id and the 2024 map in its own range; the ids are not compared, the
    bounds' vertices and line markings are;
  * crossing groups: the 2020a reader gives them random ids (and reads only the first
    <crossing>), so crossings are compared by their lanelets;
  * the lanelet network's map meta information: a 2024 map is shared and named by its content,
    so its name is not the scenario's; its country is compared.
"""
import dataclasses
import enum
import json
import math
import sys
import traceback
import xml.etree.ElementTree as ET

import numpy as np

TOL = 5.000001e-7
MAX_LISTED = 25


class Diff:
    def __init__(self):
        self.items = []
        self.counted = {}

    def add(self, path, msg):
        self.items.append(f"{path}: {msg}")

    def count(self, what, n=1):
        self.counted[what] = self.counted.get(what, 0) + n


def is_num(x):
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


def shapely_coords(g):
    import shapely

    if isinstance(g, shapely.Point):
        return np.array(g.coords)
    if isinstance(g, shapely.Polygon):
        return np.array(g.exterior.coords)
    if hasattr(g, "geoms"):
        return [shapely_coords(x) for x in g.geoms]
    return np.array(g.coords)


def same(a, b, path, d):
    """Compare two values of the readings, recording differences under `path`."""
    try:
        import shapely

        if isinstance(a, shapely.Geometry) or isinstance(b, shapely.Geometry):
            if type(a) is not type(b):
                d.add(path, f"{type(a).__name__} vs {type(b).__name__}")
                return
            return same(shapely_coords(a), shapely_coords(b), path, d)
    except ImportError:
        pass
    if a is None or b is None:
        if not (a is None and b is None):
            d.add(path, f"{short(a)} vs {short(b)}")
        return
    if isinstance(a, enum.Enum) or isinstance(b, enum.Enum):
        na = getattr(a, "name", a)
        nb = getattr(b, "name", b)
        if na != nb or type(a).__name__ != type(b).__name__:
            d.add(path, f"{type(a).__name__}.{na} vs {type(b).__name__}.{nb}")
        return
    # booleans before numbers (a bool is an int), strings before arrays: equal, or named as they are
    if isinstance(a, (bool, str)) or isinstance(b, (bool, str)):
        if a != b:
            d.add(path, f"{a!r} vs {b!r}")
        return
    if is_num(a) and is_num(b):
        if isinstance(a, (int, np.integer)) and isinstance(b, (int, np.integer)):
            if int(a) != int(b):
                d.add(path, f"{a} vs {b}")
        elif not (math.isfinite(a) and math.isfinite(b) and abs(float(a) - float(b)) <= TOL):
            d.add(path, f"{a!r} vs {b!r}")
        return
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if a.shape != b.shape:
            d.add(path, f"shape {a.shape} vs {b.shape}")
        elif a.size and not np.all(np.abs(a - b) <= TOL):
            i = int(np.argmax(np.abs(a - b)))
            d.add(path, f"differs by {float(np.max(np.abs(a - b))):.3g} (at flat index {i})")
        return
    if isinstance(a, (set, frozenset)) or isinstance(b, (set, frozenset)):
        if set(a) != set(b):
            d.add(path, f"{sorted(a, key=str)} vs {sorted(b, key=str)}")
        return
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            d.add(path, f"keys {sorted(a, key=str)} vs {sorted(b, key=str)}")
            return
        for k in a:
            same(a[k], b[k], f"{path}[{k}]", d)
        return
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        if len(a) != len(b):
            d.add(path, f"{len(a)} vs {len(b)} items")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]", d)
        return
    if type(a) is not type(b):
        d.add(path, f"{type(a).__name__} vs {type(b).__name__}")
        return
    name = type(a).__name__
    if name in ("Interval", "AngleInterval"):
        same(a.start, b.start, f"{path}.start", d)
        same(a.end, b.end, f"{path}.end", d)
        return
    if name == "Time":
        for f in ("year", "month", "day", "hours", "minutes"):
            same(getattr(a, f, None), getattr(b, f, None), f"{path}.{f}", d)
        return
    if dataclasses.is_dataclass(a):
        if "State" in name or hasattr(a, "attributes"):
            ka, kb = list(a.attributes), list(b.attributes)
            if sorted(ka) != sorted(kb):
                d.add(path, f"fields {sorted(ka)} vs {sorted(kb)}")
                return
            for f in ka:
                same(getattr(a, f), getattr(b, f), f"{path}.{f}", d)
            return
        for f in dataclasses.fields(a):
            if f.compare:
                same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}", d)
        return
    d.add(path, f"cannot compare {name} values: {short(a)} vs {short(b)}")


def short(x):
    s = repr(x)
    return s if len(s) < 80 else s[:77] + "..."


def by_id(items, key):
    return {key(x): x for x in items}


def compare_ids(a, b, path, d):
    if set(a) != set(b):
        d.add(path, f"ids only in 2020a {sorted(set(a) - set(b))}, only in 2024 {sorted(set(b) - set(a))}")
    return sorted(set(a) & set(b))


def props(a, b, names, path, d):
    for n in names:
        same(getattr(a, n), getattr(b, n), f"{path}.{n}", d)


def compare_bound(net_a, net_b, la, lb, side, path, d):
    # the bound objects: vertices and marking as the lanelet's own, in both readings
    for net, l, which in ((net_a, la, "2020a"), (net_b, lb, "2024")):
        bid = getattr(l, f"{side}_bound")
        bound = net.find_boundary_by_id(bid) if bid is not None else None
        if bound is None:
            d.add(f"{path}.{side}_bound", f"{which}: no bound object {bid}")
            continue
        same(bound.vertices, getattr(l, f"{side}_vertices"), f"{path}.{side}_bound({which}).vertices", d)


def compare_network(sa, sb, xml_root, d):
    na, nb = sa.lanelet_network, sb.lanelet_network
    la_by, lb_by = by_id(na.lanelets, lambda l: l.lanelet_id), by_id(nb.lanelets, lambda l: l.lanelet_id)
    for i in compare_ids(la_by, lb_by, "lanelets", d):
        a, b, p = la_by[i], lb_by[i], f"lanelet {i}"
        d.count("lanelets")
        props(a, b, ["left_vertices", "right_vertices", "center_vertices", "predecessor", "successor",
                     "adj_left", "adj_left_same_direction", "adj_right", "adj_right_same_direction",
                     "line_marking_left_vertices", "line_marking_right_vertices", "lanelet_type",
                     "user_one_way", "user_bidirectional", "traffic_signs", "traffic_lights",
                     "adjacent_areas"], p, d)
        compare_bound(na, nb, a, b, "left", p, d)
        compare_bound(na, nb, a, b, "right", p, d)
        sla, slb = a.stop_line, b.stop_line
        if (sla is None) != (slb is None):
            d.add(f"{p}.stop_line", f"{short(sla)} vs {short(slb)}")
        elif sla is not None:
            d.count("stop lines")
            props(sla, slb, ["start", "end", "line_marking"], f"{p}.stop_line", d)
            # 2024: no references on the stop line; they must be the lanelet's
            for ref, on_lanelet in ((sla.traffic_sign_ref, b.traffic_signs), (sla.traffic_light_ref, b.traffic_lights)):
                missing = set(ref or ()) - set(on_lanelet)
                if missing:
                    d.add(f"{p}.stop_line", f"references {sorted(missing)} are lost in 2024")
            for ref in (slb.traffic_sign_ref, slb.traffic_light_ref):
                if ref:
                    d.add(f"{p}.stop_line", f"2024 stop line has references {ref}")
    virtual_xml = {}
    for node in xml_root.findall("trafficSign"):
        v = node.find("virtual")
        virtual_xml[int(node.get("id"))] = v is not None and v.text == "true"
    ta, tb = by_id(na.traffic_signs, lambda t: t.traffic_sign_id), by_id(nb.traffic_signs, lambda t: t.traffic_sign_id)
    for i in compare_ids(ta, tb, "traffic signs", d):
        a, b, p = ta[i], tb[i], f"trafficSign {i}"
        d.count("traffic signs")
        props(a, b, ["position"], p, d)
        same([(e.traffic_sign_element_id, list(e.additional_values)) for e in a.traffic_sign_elements],
             [(e.traffic_sign_element_id, list(e.additional_values)) for e in b.traffic_sign_elements],
             f"{p}.traffic_sign_elements", d)
        same(virtual_xml.get(i, False), bool(b.virtual), f"{p}.virtual (2024 vs the XML element)", d)
    ga, gb = by_id(na.traffic_lights, lambda t: t.traffic_light_id), by_id(nb.traffic_lights, lambda t: t.traffic_light_id)
    for i in compare_ids(ga, gb, "traffic lights", d):
        a, b, p = ga[i], gb[i], f"trafficLight {i}"
        d.count("traffic lights")
        props(a, b, ["position", "color", "direction", "active"], p, d)
        ca, cb = a.traffic_light_cycle, b.traffic_light_cycle
        if (ca is None) != (cb is None):
            d.add(f"{p}.traffic_light_cycle", f"{short(ca)} vs {short(cb)}")
        elif ca is not None:
            same([(e.state, e.duration) for e in ca.cycle_elements], [(e.state, e.duration) for e in cb.cycle_elements],
                 f"{p}.cycle_elements", d)
            props(ca, cb, ["time_offset", "active"], f"{p}.traffic_light_cycle", d)
    ia, ib = by_id(na.intersections, lambda t: t.intersection_id), by_id(nb.intersections, lambda t: t.intersection_id)
    for i in compare_ids(ia, ib, "intersections", d):
        a, b, p = ia[i], ib[i], f"intersection {i}"
        d.count("intersections")
        inca, incb = by_id(a.incomings, lambda x: x.incoming_id), by_id(b.incomings, lambda x: x.incoming_id)
        for j in compare_ids(inca, incb, f"{p} incomings", d):
            props(inca[j], incb[j], ["incoming_lanelets", "outgoing_group_id", "outgoing_right", "outgoing_straight",
                                     "outgoing_left"], f"{p} incoming {j}", d)
        same(sorted(sorted(c.crossing_lanelets) for c in a.crossings), sorted(sorted(c.crossing_lanelets) for c in b.crossings),
             f"{p}.crossings (lanelets)", d)
        same(sorted(sorted(o.outgoing_lanelets) for o in a.outgoings), sorted(sorted(o.outgoing_lanelets) for o in b.outgoings),
             f"{p}.outgoings (lanelets)", d)
    same(len(na.areas), len(nb.areas), "areas", d)
    loc_a, loc_b = na.location, nb.location
    props(loc_a, loc_b, ["geo_name_id", "gps_latitude", "gps_longitude"], "location", d)
    gta, gtb = loc_a.geo_transformation, loc_b.geo_transformation
    if (gta is None) != (gtb is None):
        d.add("location.geo_transformation", f"{short(gta)} vs {short(gtb)}")
    elif gta is not None:
        props(gta, gtb, ["geo_reference", "x_translation", "y_translation", "z_rotation", "scaling"], "location.geo_transformation", d)
    same(na.meta_information.scenario_id.country_id, nb.meta_information.scenario_id.country_id, "map country", d)


def compare_obstacles(sa, sb, d):
    for kind in ("static_obstacles", "dynamic_obstacles", "environment_obstacle", "phantom_obstacle"):
        oa, ob = by_id(getattr(sa, kind), lambda o: o.obstacle_id), by_id(getattr(sb, kind), lambda o: o.obstacle_id)
        for i in compare_ids(oa, ob, kind, d):
            a, b, p = oa[i], ob[i], f"{kind[:-1] if kind.endswith('s') else kind} {i}"
            d.count(kind)
            props(a, b, ["obstacle_type", "obstacle_role"], p, d)
            if kind == "environment_obstacle":
                props(a, b, ["occupancy"], p, d)
                continue
            if kind == "phantom_obstacle":
                continue
            props(a, b, ["obstacle_shape", "initial_state", "initial_signal_state", "signal_series"], p, d)
            if kind == "dynamic_obstacles":
                pa, pb = a.prediction, b.prediction
                if type(pa) is not type(pb):
                    d.add(f"{p}.prediction", f"{type(pa).__name__} vs {type(pb).__name__}")
                    continue
                if pa is None:
                    continue
                props(pa, pb, ["shape"], f"{p}.prediction", d)
                ta, tb = pa.trajectory, pb.trajectory
                same(ta.initial_time_step, tb.initial_time_step, f"{p}.trajectory.initial_time_step", d)
                if len(ta.state_list) != len(tb.state_list):
                    d.add(f"{p}.trajectory", f"{len(ta.state_list)} vs {len(tb.state_list)} states")
                    continue
                for sa_, sb_ in zip(ta.state_list, tb.state_list):
                    d.count("trajectory states")
                    if type(sa_) is not type(sb_):
                        d.add(f"{p} state {sa_.time_step}", f"{type(sa_).__name__} vs {type(sb_).__name__}")
                        continue
                    same(sa_, sb_, f"{p} state {sa_.time_step}", d)


def compare_problems(sa, pa, pb, d):
    a_by, b_by = pa.planning_problem_dict, pb.planning_problem_dict
    for i in compare_ids(a_by, b_by, "planning problems", d):
        a, b, p = a_by[i], b_by[i], f"planningProblem {i}"
        d.count("planning problems")
        if type(a.initial_state) is not type(b.initial_state):
            d.add(f"{p}.initial_state", f"{type(a.initial_state).__name__} vs {type(b.initial_state).__name__}")
        else:
            same(a.initial_state, b.initial_state, f"{p}.initial_state", d)
        ga, gb = a.goal, b.goal
        if len(ga.state_list) != len(gb.state_list):
            d.add(f"{p}.goal", f"{len(ga.state_list)} vs {len(gb.state_list)} goal states")
        else:
            for k, (x, y) in enumerate(zip(ga.state_list, gb.state_list)):
                if type(x) is not type(y):
                    d.add(f"{p} goal {k}", f"{type(x).__name__} vs {type(y).__name__}")
                else:
                    same(x, y, f"{p} goal {k}", d)
        la, lb = ga.lanelets_of_goal_position, gb.lanelets_of_goal_position
        same({k: list(v) for k, v in (la or {}).items()}, {k: list(v) for k, v in (lb or {}).items()},
             f"{p}.goal.lanelets_of_goal_position", d)
        # 2020a keeps the tags on the scenario, 2024 on each planning problem
        same(set(sa.tags or ()), set(b.scenario_tags or ()), f"{p}.scenario_tags (2024) vs the 2020a scenario's tags", d)
        same(getattr(a, "ego_id", None), getattr(b, "ego_id", None), f"{p}.ego_id", d)


def compare_case(case):
    from commonroad.common.file_reader import CommonRoadFileReader

    d = Diff()
    sa, pa = CommonRoadFileReader(filename_2020a=case["xml"]).open()
    sb, pb, coop = CommonRoadFileReader(
        filename_map=case["map"], filename_scenario=case["scenario"], filename_dynamic=case["dynamic"]
    ).open_all()
    root = ET.parse(case["xml"]).getroot()
    same(str(sa.scenario_id), str(sb.scenario_id), "scenario_id", d)
    props(sa.scenario_id, sb.scenario_id, ["cooperative", "country_id", "map_name", "map_id", "configuration_id",
                                           "obstacle_behavior", "prediction_id", "scenario_version"], "scenario_id", d)
    props(sa, sb, ["dt"], "scenario", d)
    props(sa.file_information, sb.file_information, ["author", "affiliation", "source", "license_name", "license_text"],
          "scenario.file_information", d)
    y, m, dd = (int(x) for x in root.get("date").split("-"))
    date = sb.file_information.date
    same((date.year, date.month, date.day), (y, m, dd), "scenario date (2024 vs the XML attribute)", d)
    same(len(coop), 0, "cooperative planning problems", d)
    compare_network(sa, sb, root, d)
    compare_obstacles(sa, sb, d)
    compare_problems(sa, pa, pb, d)
    return d


def main(path):
    cases = json.load(open(path, encoding="utf-8"))
    all_ok = True
    for case in cases:
        out = {"xml": case["xml"]}
        try:
            d = compare_case(case)
            out.update(ok=not d.items, differences=d.items[:MAX_LISTED], n_differences=len(d.items), counted=d.counted)
        except Exception:
            out.update(ok=False, differences=[], n_differences=0, counted={}, error=traceback.format_exc(limit=6))
        all_ok = all_ok and out["ok"]
        print(json.dumps(out), flush=True)
    sys.exit(0 if all_ok else 1)


if __name__ == "__main__":
    import logging

    logging.disable(logging.WARNING)  # the 2020a reader logs every deprecated intersection successor
    main(sys.argv[1])
