"""Compares two OSI trace files (GroundTruth per message, 4-byte little-endian length before
each) field by field with the osi3 Python bindings: osc2cr's against esmini's for the same
scenario. Prints one JSON object: per field the largest difference, counts, and what differs.

    python compare_osi.py OURS.osi ESMINI.osi
"""
import json
import math
import sys

from osi_trace import read


def vec(v):
    return (v.x, v.y, v.z)


def dist(a, b):
    return math.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))


def polyline_distance(p, line):
    """Distance of point p to the polyline `line` (x, y, z points)."""
    best = math.inf
    for a, b in zip(line, line[1:]):
        d = [b[k] - a[k] for k in range(3)]
        ll = sum(x * x for x in d)
        t = 0.0 if ll == 0 else max(0.0, min(1.0, sum((p[k] - a[k]) * d[k] for k in range(3)) / ll))
        best = min(best, dist(p, [a[k] + t * d[k] for k in range(3)]))
    if len(line) == 1:
        best = dist(p, line[0])
    return best


def main():
    ours, theirs = read(sys.argv[1]), read(sys.argv[2])
    r = {"messages": [len(ours), len(theirs)], "frames_compared": 0, "timestamp_max": 0.0,
         "position_max": 0.0, "velocity_max": 0.0, "acceleration_max": 0.0, "yaw_max": 0.0,
         "id_mismatch": [], "type_mismatch": [], "dimension_mismatch": [], "lane_id_mismatch": 0,
         "host_vehicle_id": [ours[0].host_vehicle_id.value if ours else None,
                             theirs[0].host_vehicle_id.value if theirs else None],
         "version": [], "lanes": {}, "boundaries": {}, "stationary": [len(ours[0].stationary_object) if ours else 0,
                                                               len(theirs[0].stationary_object) if theirs else 0]}
    if ours and theirs:
        r["version"] = [[g.version.version_major, g.version.version_minor, g.version.version_patch] for g in (ours[0], theirs[0])]
    worst = {}
    for k, (a, b) in enumerate(zip(ours, theirs)):
        r["frames_compared"] += 1
        ta = a.timestamp.seconds + a.timestamp.nanos * 1e-9
        tb = b.timestamp.seconds + b.timestamp.nanos * 1e-9
        r["timestamp_max"] = max(r["timestamp_max"], abs(ta - tb))
        ids_a = [o.id.value for o in a.moving_object]
        ids_b = [o.id.value for o in b.moving_object]
        if ids_a != ids_b and len(r["id_mismatch"]) < 5:
            r["id_mismatch"].append([k, ids_a, ids_b])
        for oa, ob in zip(a.moving_object, b.moving_object):
            if oa.type != ob.type or oa.vehicle_classification.type != ob.vehicle_classification.type:
                if len(r["type_mismatch"]) < 5:
                    r["type_mismatch"].append([k, oa.id.value, oa.type, ob.type])
            da = (oa.base.dimension.length, oa.base.dimension.width, oa.base.dimension.height)
            db = (ob.base.dimension.length, ob.base.dimension.width, ob.base.dimension.height)
            if dist(da, db) > 1e-6 and len(r["dimension_mismatch"]) < 5:
                r["dimension_mismatch"].append([k, oa.id.value, da, db])
            for field, key in (("position", "position_max"), ("velocity", "velocity_max"), ("acceleration", "acceleration_max")):
                d = dist(vec(getattr(oa.base, field)), vec(getattr(ob.base, field)))
                if d > r[key]:
                    r[key] = d
                    worst[key] = [k, ta, oa.id.value]
            dy = abs(math.remainder(oa.base.orientation.yaw - ob.base.orientation.yaw, 2 * math.pi))
            if dy > r["yaw_max"]:
                r["yaw_max"] = dy
                worst["yaw_max"] = [k, ta, oa.id.value]
            if [x.value for x in oa.assigned_lane_id] != [x.value for x in ob.assigned_lane_id]:
                r["lane_id_mismatch"] += 1
    r["worst_at"] = worst
    if ours and theirs:
        la = {l.id.value: l for l in ours[0].lane}
        lb = {l.id.value: l for l in theirs[0].lane}
        both = sorted(set(la) & set(lb))
        cl_max, attr_mismatch = 0.0, []
        for i in both:
            ca = [vec(p) for p in la[i].classification.centerline]
            cb = [vec(p) for p in lb[i].classification.centerline]
            for p in ca:
                cl_max = max(cl_max, polyline_distance(p, cb))
            for p in cb:
                cl_max = max(cl_max, polyline_distance(p, ca))
            for f in ("type", "subtype", "centerline_is_driving_direction"):
                if getattr(la[i].classification, f) != getattr(lb[i].classification, f):
                    attr_mismatch.append([i, f])
            for f in ("left_adjacent_lane_id", "right_adjacent_lane_id", "left_lane_boundary_id", "right_lane_boundary_id"):
                if [x.value for x in getattr(la[i].classification, f)] != [x.value for x in getattr(lb[i].classification, f)]:
                    attr_mismatch.append([i, f])
        r["lanes"] = {"ours": len(la), "esmini": len(lb), "both": len(both), "centerline_max": cl_max,
                      "only_ours": sorted(set(la) - set(lb))[:10], "only_esmini": sorted(set(lb) - set(la))[:10],
                      "attribute_mismatch": attr_mismatch[:20]}
        ba = {x.id.value: x for x in ours[0].lane_boundary}
        bb = {x.id.value: x for x in theirs[0].lane_boundary}
        both = sorted(set(ba) & set(bb))
        # dashed lines: esmini gives the dashes' ends, osc2cr the whole line (compared one way)
        line_max, dashed_max, type_mismatch = 0.0, 0.0, []
        for i in both:
            pa = [vec(p.position) for p in ba[i].boundary_line]
            pb = [vec(p.position) for p in bb[i].boundary_line]
            dashed = bb[i].classification.type == 4
            m = max([polyline_distance(p, pa) for p in pb] + [0.0])
            if not dashed:
                m = max([m] + [polyline_distance(p, pb) for p in pa])
                line_max = max(line_max, m)
            else:
                dashed_max = max(dashed_max, m)
            if ba[i].classification.type != bb[i].classification.type:
                type_mismatch.append([i, ba[i].classification.type, bb[i].classification.type])
        r["boundaries"] = {"ours": len(ba), "esmini": len(bb), "both": len(both), "line_max": line_max,
                           "dashed_points_max": dashed_max, "type_mismatch": type_mismatch[:10],
                           "only_ours": sorted(set(ba) - set(bb))[:10], "only_esmini": sorted(set(bb) - set(ba))[:10]}
    print(json.dumps(r))


if __name__ == "__main__":
    main()
