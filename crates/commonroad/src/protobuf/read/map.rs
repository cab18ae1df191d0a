//! The map file: location, lanelets (bounds by id, stop lines, neighbours, types, users,
//! references), traffic signs (the country's table back to national ids), traffic lights
//! (position, direction; their cycles are in the dynamic file), intersections and environment
//! obstacles.

use std::collections::BTreeMap;

use super::super::messages::{commonroad_common as pb, commonroad_map as mp};
use super::super::sign_names::SIGN_NAMES;
use super::super::signs::sign_country;
use super::values::{enum_from, occupancy, point};
use super::Bad;
use crate::geometry::Point;
use crate::header::{GeoLocation, GeoTransformation};
use crate::ids::{IncomingId, IntersectionId, LaneletId, ObstacleId, TrafficLightId, TrafficSignId};
use crate::intersection::{Incoming, Intersection};
use crate::lanelet::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletType, LineMarking, RoadUser, StopLine};
use crate::obstacle::{EnvironmentObstacle, EnvironmentObstacleType};
use crate::scenario::LaneletNetwork;
use crate::traffic::{CycleElement, TrafficLight, TrafficLightDirection, TrafficSign, TrafficSignElement};

pub(super) fn location(l: &mp::Location) -> GeoLocation {
    GeoLocation {
        geo_name_id: i64::from(l.geo_name_id),
        gps_latitude: l.gps_latitude,
        gps_longitude: l.gps_longitude,
        geo_transformation: l.geo_transformation.as_ref().map(|g| GeoTransformation {
            geo_reference: g.geo_reference.clone().unwrap_or_default(),
            x_translation: g.x_translation.unwrap_or(0.0),
            y_translation: g.y_translation.unwrap_or(0.0),
            z_rotation: g.z_rotation.unwrap_or(0.0),
            scaling: g.scaling.unwrap_or(1.0),
        }),
    }
}

fn id<T>(raw: u64, new: fn(u64) -> Option<T>, ctx: &dyn Fn() -> String) -> Result<T, Bad> {
    new(raw).ok_or_else(|| Bad::new(ctx(), "id 0 (ids are positive)"))
}

fn ids<T>(raw: &[u32], new: fn(u64) -> Option<T>, ctx: &dyn Fn() -> String) -> Result<Vec<T>, Bad> {
    raw.iter().map(|r| id(u64::from(*r), new, ctx)).collect()
}

fn marking(raw: Option<i32>, ctx: &dyn Fn() -> String) -> Result<Option<LineMarking>, Bad> {
    let Some(raw) = raw else { return Ok(None) };
    let name = mp::line_marking_enum::LineMarking::try_from(raw).ok().map(|m| m.as_str_name());
    let m = enum_from("line marking", name, LineMarking::ALL, LineMarking::as_str, ctx)?;
    // `unknown` is the model's None (the writer writes None as unknown)
    Ok(Some(m).filter(|m| *m != LineMarking::Unknown))
}

fn lanelet(l: &mp::Lanelet, bounds: &BTreeMap<i32, &mp::Bound>, stop_lines: &BTreeMap<u32, &mp::StopLine>) -> Result<Lanelet, Bad> {
    let ctx = || format!("lanelet {}", l.lanelet_id);
    let lanelet_id = id(u64::from(l.lanelet_id), LaneletId::new, &ctx)?;
    let bound = |which: i32, reverse: Option<bool>| -> Result<(Vec<Point>, Option<LineMarking>), Bad> {
        let b = bounds.get(&which).ok_or_else(|| Bad::new(ctx(), format!("bound {which} is not in the map")))?;
        let mut points = b.points.iter().map(|p| point(p, &ctx)).collect::<Result<Vec<_>, _>>()?;
        if reverse == Some(true) {
            points.reverse();
        }
        Ok((points, marking(b.line_marking, &ctx)?))
    };
    let (left, left_marking) = bound(l.left_bound, l.left_bound_reverse)?;
    let (right, right_marking) = bound(l.right_bound, l.right_bound_reverse)?;
    let lb = LaneletBounds::new(left, right).map_err(|e| Bad::new(ctx(), e.to_string()))?;
    let mut out = Lanelet::new(lanelet_id, lb, LaneletType::Unknown);
    out.left_marking = left_marking;
    out.right_marking = right_marking;
    out.predecessors = ids(&l.predecessors, LaneletId::new, &ctx)?;
    out.successors = ids(&l.successors, LaneletId::new, &ctx)?;
    let adjacent = |raw: Option<u32>, opposite: Option<bool>| -> Result<Option<Adjacent>, Bad> {
        raw.map(|r| {
            let driving_dir = if opposite == Some(true) { DrivingDir::Opposite } else { DrivingDir::Same };
            Ok(Adjacent { lanelet: id(u64::from(r), LaneletId::new, &ctx)?, driving_dir })
        })
        .transpose()
    };
    out.adjacent_left = adjacent(l.adjacent_left, l.adjacent_left_opposite_dir)?;
    out.adjacent_right = adjacent(l.adjacent_right, l.adjacent_right_opposite_dir)?;
    if let Some(sl) = l.stop_line {
        let s = stop_lines.get(&sl).ok_or_else(|| Bad::new(ctx(), format!("stop line {sl} is not in the map")))?;
        let line_marking = marking(Some(s.line_marking), &ctx)?.unwrap_or(LineMarking::Unknown);
        out.stop_line = Some(StopLine {
            points: Some([point(&s.start_point, &ctx)?, point(&s.end_point, &ctx)?]),
            line_marking,
            traffic_sign_refs: Vec::new(),
            traffic_light_refs: Vec::new(),
        });
    }
    out.lanelet_types = l
        .lanelet_types
        .iter()
        .map(|t| {
            let name = mp::lanelet_type_enum::LaneletType::try_from(*t).ok().map(|v| v.as_str_name());
            enum_from("lanelet type", name, LaneletType::ALL, LaneletType::as_str, &ctx)
        })
        .collect::<Result<_, _>>()?;
    let users = |raw: &[i32]| -> Result<Vec<RoadUser>, Bad> {
        raw.iter()
            .map(|u| {
                let name = mp::road_user_enum::RoadUser::try_from(*u).ok().map(|v| v.as_str_name());
                enum_from("road user", name, RoadUser::ALL, RoadUser::as_str, &ctx)
            })
            .collect()
    };
    out.user_one_way = users(&l.user_one_way)?;
    out.user_bidirectional = users(&l.user_bidirectional)?;
    out.traffic_sign_refs = ids(&l.traffic_sign_refs, TrafficSignId::new, &ctx)?;
    out.traffic_light_refs = ids(&l.traffic_light_refs, TrafficLightId::new, &ctx)?;
    Ok(out)
}

/// The 2020a id of a 2024 sign member for `country`: the writer's table read backwards, an id
/// the 2020a XSD knows first; `MAX_SPEED` is `274` where the country's own id is not in the XSD
/// (the 2020a readers read 274 as the speed limit of any country, and the writer writes it so).
fn national_id(country: &str, member: &str) -> Option<&'static str> {
    let table = SIGN_NAMES.iter().find(|(c, _)| *c == country)?.1;
    let mut ids = table.iter().filter(|(_, name)| *name == member).map(|(id, _)| *id);
    let first = ids.clone().next();
    ids.find(|id| crate::is_xsd_traffic_sign_id(id)).or((member == "MAX_SPEED").then_some("274")).or(first)
}

fn traffic_sign(s: &mp::TrafficSign, country: &str, warnings: &mut Vec<String>) -> Result<TrafficSign, Bad> {
    let ctx = || format!("trafficSign {}", s.traffic_sign_id);
    let mut elements = Vec::new();
    for e in &s.traffic_sign_elements {
        let member = pb::traffic_sign_id_enum::TrafficSignId::try_from(e.element_id).ok().map(|v| v.as_str_name());
        match member.and_then(|m| national_id(country, m)) {
            Some(national) => elements.push(TrafficSignElement { sign_id: national.to_string(), additional_values: e.additional_values.clone() }),
            None => warnings.push(format!("{}: sign {} has no id in the {country} table; left out", ctx(), member.unwrap_or("(unknown value)"))),
        }
    }
    Ok(TrafficSign {
        id: id(u64::from(s.traffic_sign_id), TrafficSignId::new, &ctx)?,
        elements,
        position: Some(point(&s.position, &ctx)?),
        is_virtual: s.r#virtual.unwrap_or(false),
    })
}

fn traffic_light(t: &mp::TrafficLight) -> Result<TrafficLight, Bad> {
    let ctx = || format!("trafficLight {}", t.traffic_light_id);
    let direction = t
        .direction
        .map(|d| {
            let name = mp::traffic_light_direction_enum::TrafficLightDirection::try_from(d).ok().map(|v| v.as_str_name());
            enum_from("traffic light direction", name, TrafficLightDirection::ALL, TrafficLightDirection::as_str, &ctx)
        })
        .transpose()?;
    // the cycle is the dynamic file's; until it is read, the map's colours, a step each
    let cycle = t
        .color
        .iter()
        .map(|c| {
            let name = pb::traffic_light_state_enum::TrafficLightState::try_from(*c).ok().map(|v| v.as_str_name());
            let color = enum_from("traffic light color", name, crate::traffic::TrafficLightColor::ALL, crate::traffic::TrafficLightColor::as_str, &ctx)?;
            Ok(CycleElement { duration: std::num::NonZeroU64::MIN, color })
        })
        .collect::<Result<Vec<_>, Bad>>()?;
    Ok(TrafficLight {
        id: id(u64::from(t.traffic_light_id), TrafficLightId::new, &ctx)?,
        cycle,
        time_offset: 0,
        position: Some(point(&t.position, &ctx)?),
        direction,
        active: None,
    })
}

fn intersection(i: &mp::Intersection) -> Result<Intersection, Bad> {
    let ctx = || format!("intersection {}", i.intersection_id);
    let incomings = i
        .incomings
        .iter()
        .map(|g| {
            Ok(Incoming {
                id: id(u64::from(g.incoming_group_id), IncomingId::new, &ctx)?,
                incoming_lanelets: ids(&g.incoming_lanelets, LaneletId::new, &ctx)?,
                successors_right: ids(&g.outgoing_right, LaneletId::new, &ctx)?,
                successors_straight: ids(&g.outgoing_straight, LaneletId::new, &ctx)?,
                successors_left: ids(&g.outgoing_left, LaneletId::new, &ctx)?,
                is_left_of: None,
            })
        })
        .collect::<Result<_, Bad>>()?;
    let crossings = i.crossings.iter().map(|c| ids(&c.crossing_lanelets, LaneletId::new, &ctx)).collect::<Result<_, _>>()?;
    Ok(Intersection { id: id(u64::from(i.intersection_id), IntersectionId::new, &ctx)?, incomings, crossings })
}

/// The lanelet network of the map (light cycles still the map's colours: see `dynamic`).
pub(super) fn network(m: &mp::CommonRoadMap, warnings: &mut Vec<String>) -> Result<LaneletNetwork, Bad> {
    let bounds: BTreeMap<i32, &mp::Bound> = m.boundaries.iter().map(|b| (b.boundary_id, b)).collect();
    let stop_lines: BTreeMap<u32, &mp::StopLine> = m.stop_lines.iter().map(|s| (s.stop_line_id, s)).collect();
    if !m.areas.is_empty() {
        warnings.push(format!("the map's {} area(s) are not part of the 2020a model; left out", m.areas.len()));
    }
    let country = sign_country(&m.map_meta_information.map_id.country_id);
    Ok(LaneletNetwork {
        lanelets: m.lanelets.iter().map(|l| lanelet(l, &bounds, &stop_lines)).collect::<Result<_, _>>()?,
        traffic_signs: m.traffic_signs.iter().map(|s| traffic_sign(s, country, warnings)).collect::<Result<_, _>>()?,
        traffic_lights: m.traffic_lights.iter().map(traffic_light).collect::<Result<_, _>>()?,
        intersections: m.intersections.iter().map(intersection).collect::<Result<_, _>>()?,
    })
}

pub(super) fn environment_obstacles(m: &mp::CommonRoadMap, warnings: &mut Vec<String>) -> Result<Vec<EnvironmentObstacle>, Bad> {
    m.environment_obstacles
        .iter()
        .map(|o| {
            let ctx = || format!("environmentObstacle {}", o.environment_obstacle_id);
            let name = mp::environment_obstacle_type_enum::EnvironmentObstacleType::try_from(o.obstacle_type).ok().map(|v| v.as_str_name());
            Ok(EnvironmentObstacle {
                id: id(u64::from(o.environment_obstacle_id), ObstacleId::new, &ctx)?,
                obstacle_type: enum_from("environment obstacle type", name, EnvironmentObstacleType::ALL, EnvironmentObstacleType::as_str, &ctx)?,
                shape: occupancy(&o.obstacle_shape, warnings, &ctx)?,
            })
        })
        .collect()
}
