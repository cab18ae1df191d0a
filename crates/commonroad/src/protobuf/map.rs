//! The map file (`CommonRoadMap`): location, lanelets with their bounds and stop lines, traffic
//! signs, traffic lights, intersections and environment obstacles — everything of a scenario
//! that does not move — named by its content.
//!
//! In 2024 a bound and a stop line are objects of their own, with ids the readers register
//! beside the obstacles' (`Scenario.add_objects` refuses an id used twice). A map is shared by
//! scenarios whose obstacles are numbered differently, so its own ids come from a range no
//! scenario uses: from [`FIRST_MAP_PART_ID`] on, for each lanelet in order its left and
//! right bound, then the stop lines, then the intersections' crossings.

use prost::Message;
use sha2::{Digest, Sha256};

use super::error::{finite, fits_i32, fits_u32};
use super::messages::{commonroad_common as pb, commonroad_map as map};
use super::meta::file_information;
use super::signs::{element, sign_country};
use super::values::{absolute_shape, enum_value, point};
use crate::geometry::Point;
use crate::header::GeoLocation;
use crate::ids::LaneletId;
use crate::intersection::Intersection;
use crate::lanelet::{DrivingDir, Lanelet, LineMarking};
use crate::obstacle::EnvironmentObstacle;
use crate::scenario::{LaneletNetwork, Scenario};
use crate::traffic::{TrafficLight, TrafficSign};
use crate::Error;

/// The first id of a map's own parts (bounds, stop lines, crossings). The scenario's ids must
/// lie below it: the readers register all of them in one id space.
pub const FIRST_MAP_PART_ID: u64 = 1_000_000_000;

/// The map's file information: it belongs to no scenario in particular (many share it), so it
/// names the tool and no date (commonroad-io reads a missing date as 2022-01-01).
const MAP_AUTHOR: &str = "osc2cr";
const MAP_SOURCE: &str = "lanelet network converted by osc2cr";

/// Hex digits of the content hash in a map's name (64 bits).
const NAME_HEX_DIGITS: usize = 16;

/// An encoded map and its id.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MapFile {
    /// `COUNTRY_<content hash>-1`: what `CommonRoadScenario.map_id` names, and, with `.pb`, the
    /// file name (commonroad-io's writer names a map file by this id).
    pub id: String,
    pub bytes: Vec<u8>,
    /// What the 2024 map cannot say of the model, or says differently.
    pub warnings: Vec<String>,
}

impl MapFile {
    /// `<id>.pb`.
    pub fn file_name(&self) -> String {
        format!("{}.pb", self.id)
    }
}

/// The map of `scenario`: its country, location, lanelet network and environment obstacles.
pub fn encode_map(scenario: &Scenario) -> Result<MapFile, Error> {
    let country = sign_country(scenario.header.benchmark_id.parts().country);
    let mut warnings = Vec::new();
    let message = map_message(country, scenario, &mut warnings)?;
    let (id, bytes) = named(country, message);
    Ok(MapFile { id, bytes, warnings })
}

/// The map named by the hash of its bytes with an empty name: the name is the first 64 bits of
/// SHA-256, in hex. Field 1 (the meta information, which holds the name) is encoded first, so
/// the named bytes are the named field 1 followed by the rest of the unnamed bytes.
fn named(country: &str, mut message: map::CommonRoadMap) -> (String, Vec<u8>) {
    let unnamed = message.encode_to_vec();
    let digest = Sha256::digest(&unnamed);
    let name: String = digest.iter().map(|b| format!("{b:02x}")).collect::<String>()[..NAME_HEX_DIGITS].to_string();
    let unnamed_meta_len = prost::encoding::message::encoded_len(1, &message.map_meta_information);
    message.map_meta_information.map_id.map_name = name.clone();
    let mut bytes = Vec::with_capacity(unnamed.len() + NAME_HEX_DIGITS);
    prost::encoding::message::encode(1, &message.map_meta_information, &mut bytes);
    bytes.extend_from_slice(&unnamed[unnamed_meta_len..]);
    (format!("{country}_{name}-1"), bytes)
}

/// Ids of the map's own parts (bounds, stop lines, crossings), handed out in order.
struct PartIds {
    next: u64,
}

impl PartIds {
    fn take(&mut self, what: &str) -> Result<u64, Error> {
        let id = self.next;
        // bound ids are int32 in the messages
        fits_i32(|| format!("{what} id"), id)?;
        self.next += 1;
        Ok(id)
    }
}

fn map_message(country: &str, scenario: &Scenario, warnings: &mut Vec<String>) -> Result<map::CommonRoadMap, Error> {
    let net = &scenario.network;
    check_ids_below_parts(net, &scenario.environment_obstacles)?;
    let mut parts = PartIds { next: FIRST_MAP_PART_ID };
    let mut lanelets = Vec::with_capacity(net.lanelets.len());
    let mut boundaries = Vec::with_capacity(2 * net.lanelets.len());
    for l in &net.lanelets {
        let ctx = || format!("lanelet {}", l.id);
        let left = parts.take("bound")?;
        let right = parts.take("bound")?;
        boundaries.push(bound(left, l.bounds.left(), l.left_marking, &|| format!("{} left bound", ctx()))?);
        boundaries.push(bound(right, l.bounds.right(), l.right_marking, &|| format!("{} right bound", ctx()))?);
        lanelets.push(lanelet(l, left, right)?);
    }
    let mut stop_lines = Vec::new();
    for (l, msg) in net.lanelets.iter().zip(lanelets.iter_mut()) {
        if let Some(sl) = &l.stop_line {
            let id = parts.take("stop line")?;
            let ctx = || format!("lanelet {} stop line", l.id);
            let [start, end] = match &sl.points {
                Some([a, b]) => [*a, *b],
                // the readers' reading of a stop line without points: the lanelet's end
                None => [last(l.bounds.left()), last(l.bounds.right())],
            };
            stop_lines.push(map::StopLine {
                stop_line_id: fits_u32(ctx, id)?,
                start_point: point(&start, &ctx)?,
                end_point: point(&end, &ctx)?,
                line_marking: line_marking(Some(sl.line_marking))?,
            });
            msg.stop_line = Some(fits_u32(ctx, id)?);
            let lost_signs: Vec<String> = sl.traffic_sign_refs.iter().filter(|r| !l.traffic_sign_refs.contains(r)).map(ToString::to_string).collect();
            let lost_lights: Vec<String> = sl.traffic_light_refs.iter().filter(|r| !l.traffic_light_refs.contains(r)).map(ToString::to_string).collect();
            if !lost_signs.is_empty() || !lost_lights.is_empty() {
                warnings.push(format!(
                    "{}: the 2024 StopLine refers to no sign or light and the lanelet does not refer to \
                     sign(s) [{}] / light(s) [{}] itself: that reference of the stop line is not written",
                    ctx(),
                    lost_signs.join(", "),
                    lost_lights.join(", ")
                ));
            }
        }
    }
    let traffic_signs = net.traffic_signs.iter().map(|s| traffic_sign(s, country, net, warnings)).collect::<Result<Vec<_>, _>>()?;
    let traffic_lights = net.traffic_lights.iter().map(|t| traffic_light(t, net, warnings)).collect::<Result<Vec<_>, _>>()?;
    let intersections = net.intersections.iter().map(|i| intersection(i, &mut parts, warnings)).collect::<Result<Vec<_>, _>>()?;
    let environment_obstacles = scenario.environment_obstacles.iter().map(environment_obstacle).collect::<Result<Vec<_>, _>>()?;
    Ok(map::CommonRoadMap {
        map_meta_information: map::MapInformation {
            map_id: pb::MapId { country_id: country.to_string(), map_name: String::new(), map_id: 1 },
            file_information: file_information(None, MAP_AUTHOR, "", MAP_SOURCE),
        },
        location: location(&scenario.location)?,
        lanelets,
        stop_lines,
        boundaries,
        areas: Vec::new(),
        traffic_signs,
        traffic_lights,
        intersections,
        environment_obstacles,
    })
}

/// Every id of the map below the range of its parts' ids.
fn check_ids_below_parts(net: &LaneletNetwork, environment: &[EnvironmentObstacle]) -> Result<(), Error> {
    let env_max = environment.iter().map(|o| o.id.get()).max().unwrap_or(0);
    let max = net.max_id().max(env_max);
    if max >= FIRST_MAP_PART_ID {
        return Err(Error::IdInMapPartRange { context: "the lanelet network".into(), id: max, first: FIRST_MAP_PART_ID });
    }
    Ok(())
}

fn last(points: &[Point]) -> Point {
    points.last().copied().unwrap_or(Point::new(0.0, 0.0))
}

fn line_marking(m: Option<LineMarking>) -> Result<i32, Error> {
    // no marking in the model is "unknown" (what the 2020a readers make of a missing one);
    // the 2024 field must be set, its default would read as "dashed"
    let xsd = m.map_or("unknown", LineMarking::as_str);
    enum_value("line marking", xsd, map::line_marking_enum::LineMarking::from_str_name)
}

fn bound(id: u64, points: &[Point], marking: Option<LineMarking>, ctx: &dyn Fn() -> String) -> Result<map::Bound, Error> {
    Ok(map::Bound {
        boundary_id: fits_i32(ctx, id)?,
        points: points.iter().map(|p| point(p, ctx)).collect::<Result<_, _>>()?,
        line_marking: Some(line_marking(marking)?),
    })
}

fn ids(v: &[LaneletId], ctx: &dyn Fn() -> String) -> Result<Vec<u32>, Error> {
    v.iter().map(|r| fits_u32(ctx, r.get())).collect()
}

fn lanelet(l: &Lanelet, left: u64, right: u64) -> Result<map::Lanelet, Error> {
    let ctx = || format!("lanelet {}", l.id);
    let opposite = |d: DrivingDir| d == DrivingDir::Opposite;
    Ok(map::Lanelet {
        lanelet_id: fits_u32(ctx, l.id.get())?,
        left_bound: fits_i32(ctx, left)?,
        right_bound: fits_i32(ctx, right)?,
        left_bound_reverse: None,
        right_bound_reverse: None,
        predecessors: ids(&l.predecessors, &ctx)?,
        successors: ids(&l.successors, &ctx)?,
        adjacent_left: l.adjacent_left.map(|a| fits_u32(ctx, a.lanelet.get())).transpose()?,
        adjacent_right: l.adjacent_right.map(|a| fits_u32(ctx, a.lanelet.get())).transpose()?,
        adjacent_left_opposite_dir: l.adjacent_left.map(|a| opposite(a.driving_dir)),
        adjacent_right_opposite_dir: l.adjacent_right.map(|a| opposite(a.driving_dir)),
        stop_line: None,
        lanelet_types: l
            .lanelet_types
            .iter()
            .map(|t| enum_value("lanelet type", t.as_str(), map::lanelet_type_enum::LaneletType::from_str_name))
            .collect::<Result<_, _>>()?,
        user_one_way: l
            .user_one_way
            .iter()
            .map(|u| enum_value("road user", u.as_str(), map::road_user_enum::RoadUser::from_str_name))
            .collect::<Result<_, _>>()?,
        user_bidirectional: l
            .user_bidirectional
            .iter()
            .map(|u| enum_value("road user", u.as_str(), map::road_user_enum::RoadUser::from_str_name))
            .collect::<Result<_, _>>()?,
        traffic_sign_refs: l.traffic_sign_refs.iter().map(|r| fits_u32(ctx, r.get())).collect::<Result<_, _>>()?,
        traffic_light_refs: l.traffic_light_refs.iter().map(|r| fits_u32(ctx, r.get())).collect::<Result<_, _>>()?,
        adjacent_areas: Vec::new(),
    })
}

/// Where a sign or light without a position stands: the end of the right bound of the first
/// lanelet that refers to it, moved to the rightmost lane of the same direction (where the
/// 2020a readers place a light in right-hand traffic).
fn fallback_position(net: &LaneletNetwork, refers: impl Fn(&Lanelet) -> bool) -> Option<Point> {
    let mut l = net.lanelets.iter().find(|l| refers(l))?;
    let mut hops = 0;
    while let Some(a) = l.adjacent_right.filter(|a| a.driving_dir == DrivingDir::Same) {
        match net.lanelets.iter().find(|x| x.id == a.lanelet) {
            Some(next) if hops < net.lanelets.len() => {
                l = next;
                hops += 1;
            }
            _ => break,
        }
    }
    Some(last(l.bounds.right()))
}

fn placed(what: &str, given: Option<Point>, net: &LaneletNetwork, refers: impl Fn(&Lanelet) -> bool, warnings: &mut Vec<String>) -> Point {
    if let Some(p) = given {
        return p;
    }
    match fallback_position(net, refers) {
        Some(p) => {
            warnings.push(format!(
                "{what} has no position; the 2024 format requires one: it is placed at ({:.3}, {:.3}), the end of \
                 the right bound of the first lanelet referring to it (where the 2020a readers place it)",
                p.x, p.y
            ));
            p
        }
        None => {
            warnings.push(format!("{what} has no position and no lanelet refers to it; the 2024 format requires one: (0, 0) is written"));
            Point::new(0.0, 0.0)
        }
    }
}

fn traffic_sign(s: &TrafficSign, country: &str, net: &LaneletNetwork, warnings: &mut Vec<String>) -> Result<map::TrafficSign, Error> {
    let ctx = || format!("trafficSign {}", s.id);
    let position = placed(&ctx(), s.position, net, |l| l.traffic_sign_refs.contains(&s.id), warnings);
    Ok(map::TrafficSign {
        traffic_sign_id: fits_u32(ctx, s.id.get())?,
        traffic_sign_elements: s.elements.iter().map(|e| element(e, country, &ctx, warnings)).collect::<Result<_, _>>()?,
        position: point(&position, &ctx)?,
        r#virtual: Some(s.is_virtual),
    })
}

fn traffic_light(t: &TrafficLight, net: &LaneletNetwork, warnings: &mut Vec<String>) -> Result<map::TrafficLight, Error> {
    use pb::traffic_light_state_enum::TrafficLightState;
    let ctx = || format!("trafficLight {}", t.id);
    let position = placed(&ctx(), t.position, net, |l| l.traffic_light_refs.contains(&t.id), warnings);
    Ok(map::TrafficLight {
        traffic_light_id: fits_u32(ctx, t.id.get())?,
        position: point(&position, &ctx)?,
        // the colours of its cycle, in cycle order: commonroad-io reads a 2020a light's `color` so
        // (the cycle itself is in the dynamic file)
        color: t.cycle.iter().map(|c| enum_value("traffic light color", c.color.as_str(), TrafficLightState::from_str_name)).collect::<Result<_, _>>()?,
        direction: t
            .direction
            .map(|d| enum_value("traffic light direction", d.as_str(), map::traffic_light_direction_enum::TrafficLightDirection::from_str_name))
            .transpose()?,
    })
}

fn intersection(i: &Intersection, parts: &mut PartIds, warnings: &mut Vec<String>) -> Result<map::Intersection, Error> {
    let ctx = || format!("intersection {}", i.id);
    let left_of: Vec<String> = i.incomings.iter().filter_map(|inc| inc.is_left_of.map(|l| format!("{} isLeftOf {l}", inc.id))).collect();
    if !left_of.is_empty() {
        warnings.push(format!(
            "{}: the 2024 IncomingGroup has no isLeftOf (commonroad-io 2026.1 reads none from 2020a either): \
             not written for incoming {}",
            ctx(),
            left_of.join(", ")
        ));
    }
    let incomings = i
        .incomings
        .iter()
        .map(|inc| {
            Ok(map::IncomingGroup {
                incoming_group_id: fits_u32(ctx, inc.id.get())?,
                incoming_lanelets: ids(&inc.incoming_lanelets, &ctx)?,
                outgoing_group_id: None,
                outgoing_right: ids(&inc.successors_right, &ctx)?,
                outgoing_straight: ids(&inc.successors_straight, &ctx)?,
                outgoing_left: ids(&inc.successors_left, &ctx)?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let crossings = i
        .crossings
        .iter()
        .map(|c| {
            Ok(map::CrossingGroup {
                crossing_group_id: fits_u32(ctx, parts.take("crossing")?)?,
                crossing_lanelets: ids(c, &ctx)?,
                incoming_group_id: None,
                outgoing_group_id: None,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(map::Intersection { intersection_id: fits_u32(ctx, i.id.get())?, incomings, outgoings: Vec::new(), crossings })
}

fn environment_obstacle(o: &EnvironmentObstacle) -> Result<map::EnvironmentObstacle, Error> {
    let ctx = || format!("environmentObstacle {}", o.id);
    Ok(map::EnvironmentObstacle {
        environment_obstacle_id: fits_u32(ctx, o.id.get())?,
        obstacle_type: enum_value(
            "environment obstacle type",
            o.obstacle_type.as_str(),
            map::environment_obstacle_type_enum::EnvironmentObstacleType::from_str_name,
        )?,
        obstacle_shape: absolute_shape(&o.shape, &ctx)?,
    })
}

fn location(l: &GeoLocation) -> Result<map::Location, Error> {
    let geo_name_id = i32::try_from(l.geo_name_id).map_err(|_| Error::OutOfRange {
        context: "location geoNameId".into(),
        value: l.geo_name_id.unsigned_abs(),
        max: i32::MAX as u64,
    })?;
    let geo_transformation = match &l.geo_transformation {
        Some(g) => Some(map::GeoTransformation {
            geo_reference: Some(g.geo_reference.clone()),
            x_translation: Some(finite(|| "geoTransformation xTranslation".into(), g.x_translation)?),
            y_translation: Some(finite(|| "geoTransformation yTranslation".into(), g.y_translation)?),
            z_rotation: Some(finite(|| "geoTransformation zRotation".into(), g.z_rotation)?),
            scaling: Some(finite(|| "geoTransformation scaling".into(), g.scaling)?),
        }),
        None => None,
    };
    Ok(map::Location {
        geo_name_id,
        gps_latitude: finite(|| "location gpsLatitude".into(), l.gps_latitude)?,
        gps_longitude: finite(|| "location gpsLongitude".into(), l.gps_longitude)?,
        geo_transformation,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn naming_rewrites_only_the_first_field() {
        let mut m = map::CommonRoadMap::default();
        m.map_meta_information.map_id.country_id = "ZAM".into();
        m.location.gps_latitude = 999.0;
        m.lanelets.push(map::Lanelet { lanelet_id: 7, ..Default::default() });
        let (id, bytes) = named("ZAM", m.clone());
        let name = id.trim_start_matches("ZAM_").trim_end_matches("-1").to_string();
        assert_eq!(name.len(), NAME_HEX_DIGITS);
        m.map_meta_information.map_id.map_name = name;
        assert_eq!(bytes, m.encode_to_vec(), "the named bytes are the whole message encoded");
    }
}
