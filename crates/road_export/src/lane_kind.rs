//! Lanelet types and road users → OpenDRIVE lane types and road types. CommonRoad types
//! OpenDRIVE has no lane type for are written as the nearest one, with a warning. Bus lanes
//! are driving lanes whose `<access>` allows buses: OpenDRIVE 1.8's lane type `bus` is an
//! error for esmini 3.6, which knows the access rule.

use commonroad::{Lanelet, LaneletType, RoadUser};

/// A lane's type and the road user its `<access>` allows (if restricted).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct LaneKind {
    pub kind: &'static str,
    pub access: Option<&'static str>,
}

/// The lane type of a lanelet, and what was approximated (for a warning).
pub(crate) fn lane_type(l: &Lanelet) -> (LaneKind, Option<String>) {
    let (kind, note) = plain_type(l);
    match kind {
        "bus" => (LaneKind { kind: "driving", access: Some("bus") }, note),
        _ => (LaneKind { kind, access: None }, note),
    }
}

fn plain_type(l: &Lanelet) -> (&'static str, Option<String>) {
    use LaneletType as T;
    let has = |t: T| l.lanelet_types.contains(&t);
    let users: Vec<RoadUser> = l.user_one_way.iter().chain(&l.user_bidirectional).copied().collect();
    let only = |u: RoadUser| !users.is_empty() && users.iter().all(|x| *x == u);
    if has(T::Crosswalk) {
        return ("sidewalk", Some("lanelet type crosswalk has no OpenDRIVE lane type (a crossing is an object there); written as a sidewalk lane".into()));
    }
    if has(T::Sidewalk) || only(RoadUser::Pedestrian) {
        return ("sidewalk", None);
    }
    if has(T::BicycleLane) || only(RoadUser::Bicycle) {
        return ("biking", None);
    }
    if has(T::BusStop) {
        return ("bus", Some("lanelet type busStop has no OpenDRIVE lane type; written as a bus lane".into()));
    }
    if has(T::BusLane) || only(RoadUser::Bus) {
        return ("bus", None);
    }
    if has(T::Shoulder) {
        return ("shoulder", None);
    }
    if has(T::Parking) {
        return ("parking", None);
    }
    if has(T::RestrictedArea) || has(T::Restricted) {
        return ("restricted", None);
    }
    if has(T::Border) {
        return ("border", None);
    }
    if has(T::AccessRamp) {
        return ("onRamp", None);
    }
    if has(T::ExitRamp) {
        return ("offRamp", None);
    }
    let vehicle = |u: &RoadUser| !matches!(u, RoadUser::Pedestrian | RoadUser::Bicycle);
    if l.user_bidirectional.iter().any(vehicle) {
        return ("bidirectional", None);
    }
    if has(T::DriveWay) {
        return ("driving", Some("lanelet type driveWay has no OpenDRIVE lane type; written as a driving lane".into()));
    }
    ("driving", None)
}

/// The road type of lanes with these lanelets (the class most of them name).
pub(crate) fn road_type<'a>(lanelets: impl Iterator<Item = &'a Lanelet>) -> &'static str {
    let (mut motorway, mut town, mut rural) = (0, 0, 0);
    for l in lanelets {
        let has = |t: LaneletType| l.lanelet_types.contains(&t);
        if has(LaneletType::Interstate) || has(LaneletType::Highway) {
            motorway += 1;
        } else if has(LaneletType::Urban) {
            town += 1;
        } else if has(LaneletType::Country) {
            rural += 1;
        }
    }
    let best = motorway.max(town).max(rural);
    if best == 0 {
        "unknown"
    } else if best == motorway {
        "motorway"
    } else if best == town {
        "town"
    } else {
        "rural"
    }
}
