//! Lanelets, traffic signs, traffic lights and intersections.

use std::num::NonZeroU64;

use roxmltree::Node;

use super::cursor::{child, children, Cursor};
use crate::geometry::Point;
use crate::ids::{IncomingId, IntersectionId, LaneletId, TrafficLightId, TrafficSignId};
use crate::intersection::{Incoming, Intersection};
use crate::lanelet::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletType, LineMarking, RoadUser, StopLine};
use crate::traffic::{CycleElement, TrafficLight, TrafficLightColor, TrafficLightDirection, TrafficSign, TrafficSignElement};
use crate::Error;

fn bound(cx: &Cursor, node: Node) -> Result<(Vec<Point>, Option<LineMarking>), Error> {
    let points = children(node, "point").map(|p| cx.point(p)).collect::<Result<Vec<_>, _>>()?;
    let marking = child(node, "lineMarking").map(|m| cx.enum_text(m, LineMarking::ALL, LineMarking::as_str)).transpose()?;
    // The writer leaves out `unknown` (the readers' default), so reading it back as None
    // makes a written file read back as the model it came from.
    Ok((points, marking.filter(|m| *m != LineMarking::Unknown)))
}

fn adjacent(cx: &Cursor, node: Node, name: &str) -> Result<Option<Adjacent>, Error> {
    let Some(a) = child(node, name) else {
        return Ok(None);
    };
    let lanelet = cx.typed(a, "ref", LaneletId::new)?;
    let dir = a.attribute("drivingDir").unwrap_or("");
    let driving_dir =
        DrivingDir::ALL.iter().copied().find(|d| d.as_str() == dir).ok_or_else(|| cx.err(a, format!("drivingDir {dir:?}: expected same or opposite")))?;
    Ok(Some(Adjacent { lanelet, driving_dir }))
}

fn stop_line(cx: &Cursor, node: Node) -> Result<StopLine, Error> {
    let pts = children(node, "point").map(|p| cx.point(p)).collect::<Result<Vec<_>, _>>()?;
    let points = match pts.as_slice() {
        [] => None,
        [a, b] => Some([*a, *b]),
        _ => return Err(cx.err(node, "<stopLine>: expected 0 or 2 points")),
    };
    let line_marking = match child(node, "lineMarking") {
        Some(m) => cx.enum_text(m, LineMarking::ALL, LineMarking::as_str)?,
        None => LineMarking::Solid,
    };
    Ok(StopLine {
        points,
        line_marking,
        traffic_sign_refs: cx.refs(node, "trafficSignRef", TrafficSignId::new)?,
        traffic_light_refs: cx.refs(node, "trafficLightRef", TrafficLightId::new)?,
    })
}

pub(crate) fn lanelet(cx: &mut Cursor, node: Node) -> Result<Lanelet, Error> {
    let id = cx.typed(node, "id", LaneletId::new)?;
    let (left, left_marking) = bound(cx, cx.req(node, "leftBound")?)?;
    let (right, right_marking) = bound(cx, cx.req(node, "rightBound")?)?;
    let bounds = LaneletBounds::new(left, right).map_err(|e| cx.err(node, format!("lanelet {id}: {e}")))?;
    let types = children(node, "laneletType").map(|t| cx.enum_text(t, LaneletType::ALL, LaneletType::as_str)).collect::<Result<Vec<_>, _>>()?;
    let mut l = Lanelet::new(id, bounds, LaneletType::Unknown);
    l.lanelet_types = types;
    l.left_marking = left_marking;
    l.right_marking = right_marking;
    l.predecessors = cx.refs(node, "predecessor", LaneletId::new)?;
    l.successors = cx.refs(node, "successor", LaneletId::new)?;
    l.adjacent_left = adjacent(cx, node, "adjacentLeft")?;
    l.adjacent_right = adjacent(cx, node, "adjacentRight")?;
    l.stop_line = child(node, "stopLine").map(|s| stop_line(cx, s)).transpose()?;
    let users = |name| -> Result<Vec<RoadUser>, Error> { children(node, name).map(|u| cx.enum_text(u, RoadUser::ALL, RoadUser::as_str)).collect() };
    l.user_one_way = users("userOneWay")?;
    l.user_bidirectional = users("userBidirectional")?;
    l.traffic_sign_refs = cx.refs(node, "trafficSignRef", TrafficSignId::new)?;
    l.traffic_light_refs = cx.refs(node, "trafficLightRef", TrafficLightId::new)?;
    Ok(l)
}

fn bool_text(cx: &Cursor, node: Node) -> Result<bool, Error> {
    match cx.text(node) {
        "true" | "1" => Ok(true),
        "false" | "0" => Ok(false),
        t => Err(cx.err(node, format!("expected true or false, found {t:?}"))),
    }
}

pub(crate) fn traffic_sign(cx: &mut Cursor, node: Node) -> Result<TrafficSign, Error> {
    let id = cx.typed(node, "id", TrafficSignId::new)?;
    let elements = children(node, "trafficSignElement")
        .map(|e| {
            Ok(TrafficSignElement {
                sign_id: cx.text(cx.req(e, "trafficSignID")?).to_string(),
                additional_values: children(e, "additionalValue").map(|v| cx.text(v).to_string()).collect(),
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let position = child(node, "position").map(|_| cx.position_point(node)).transpose()?;
    let is_virtual = child(node, "virtual").map(|v| bool_text(cx, v)).transpose()?.unwrap_or(false);
    Ok(TrafficSign { id, elements, position, is_virtual })
}

pub(crate) fn traffic_light(cx: &mut Cursor, node: Node) -> Result<TrafficLight, Error> {
    let id = cx.typed(node, "id", TrafficLightId::new)?;
    let cycle_node = cx.req(node, "cycle")?;
    let cycle = children(cycle_node, "cycleElement")
        .map(|c| {
            let d = cx.req(c, "duration")?;
            let duration = NonZeroU64::new(cx.u64(d)?).ok_or_else(|| cx.err(d, "<duration>: expected a positive integer"))?;
            let color = cx.enum_text(cx.req(c, "color")?, TrafficLightColor::ALL, TrafficLightColor::as_str)?;
            Ok(CycleElement { duration, color })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let time_offset = child(cycle_node, "timeOffset").map(|t| cx.u64(t)).transpose()?.unwrap_or(0);
    let position = child(node, "position").map(|_| cx.position_point(node)).transpose()?;
    let direction = child(node, "direction").map(|d| cx.enum_text(d, TrafficLightDirection::ALL, TrafficLightDirection::as_str)).transpose()?;
    let active = child(node, "active").map(|a| bool_text(cx, a)).transpose()?;
    Ok(TrafficLight { id, cycle, time_offset, position, direction, active })
}

pub(crate) fn intersection(cx: &mut Cursor, node: Node) -> Result<Intersection, Error> {
    let id = cx.typed(node, "id", IntersectionId::new)?;
    let incomings = children(node, "incoming")
        .map(|inc| {
            Ok(Incoming {
                id: cx.typed(inc, "id", IncomingId::new)?,
                incoming_lanelets: cx.refs(inc, "incomingLanelet", LaneletId::new)?,
                successors_right: cx.refs(inc, "successorsRight", LaneletId::new)?,
                successors_straight: cx.refs(inc, "successorsStraight", LaneletId::new)?,
                successors_left: cx.refs(inc, "successorsLeft", LaneletId::new)?,
                is_left_of: child(inc, "isLeftOf").map(|n| cx.typed(n, "ref", IncomingId::new)).transpose()?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let crossings = children(node, "crossing").map(|c| cx.refs(c, "crossingLanelet", LaneletId::new)).collect::<Result<Vec<_>, _>>()?;
    Ok(Intersection { id, incomings, crossings })
}
