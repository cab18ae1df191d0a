"""An OSI trace against the CommonRoad 2020a file of the same run: every message opens with the
osi3 bindings, one per engine frame (timestamps 0, dt, 2 dt, ...), and at every CommonRoad time
step each dynamic obstacle's state (box centre, orientation, speed) is a moving object's of the
message at that time. Obstacles are matched to OSI objects by their position at time 0. Prints
one JSON object with the largest differences.

    python osi_vs_commonroad.py TRACE.osi SCENARIO.xml ENGINE_STEP
"""
import json
import math
import sys
import xml.etree.ElementTree as ET

from osi_trace import read


def states(obstacle):
    out = {}
    for s in [obstacle.find("initialState")] + list(obstacle.iter("state")):
        t = int(s.find("time/exact").text)
        p = s.find("position/point")
        out[t] = (float(p.find("x").text), float(p.find("y").text), float(s.find("orientation/exact").text),
                  float(s.find("velocity/exact").text))
    return out


def main():
    msgs = read(sys.argv[1])
    root = ET.parse(sys.argv[2]).getroot()
    step = float(sys.argv[3])
    dt = float(root.get("timeStepSize"))
    ratio = round(dt / step)
    r = {"messages": len(msgs), "timestamp_max": 0.0, "obstacles": 0, "states": 0, "position_max": 0.0,
         "orientation_max": 0.0, "speed_max": 0.0, "unmatched": []}
    for k, g in enumerate(msgs):
        t = g.timestamp.seconds + g.timestamp.nanos * 1e-9
        r["timestamp_max"] = max(r["timestamp_max"], abs(t - k * step))
    for ob in root.iter("dynamicObstacle"):
        st = states(ob)
        t0 = min(st)
        x0, y0 = st[t0][0], st[t0][1]
        first = msgs[t0 * ratio].moving_object
        best = min(first, key=lambda o: math.hypot(o.base.position.x - x0, o.base.position.y - y0))
        if math.hypot(best.base.position.x - x0, best.base.position.y - y0) > 1e-3:
            r["unmatched"].append(ob.get("id"))
            continue
        r["obstacles"] += 1
        for t, (x, y, h, v) in st.items():
            objs = [o for o in msgs[t * ratio].moving_object if o.id.value == best.id.value]
            if not objs:
                r["unmatched"].append([ob.get("id"), t])
                continue
            b = objs[0].base
            r["states"] += 1
            r["position_max"] = max(r["position_max"], math.hypot(b.position.x - x, b.position.y - y))
            r["orientation_max"] = max(r["orientation_max"], abs(math.remainder(b.orientation.yaw - h, 2 * math.pi)))
            r["speed_max"] = max(r["speed_max"], abs(math.hypot(b.velocity.x, b.velocity.y) - abs(v)))
    print(json.dumps(r))


if __name__ == "__main__":
    main()
