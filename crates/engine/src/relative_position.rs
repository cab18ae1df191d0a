//! RelativeRoadPosition and RelativeLanePosition as esmini 3.6 resolves them
//! (Position::EvaluateRelation): a copy of the reference entity's position is moved `ds` along
//! the road network — across lane sections, roads and junctions, not clamped to its road —
//! the way Position::MoveAlongS moves it (road s, not distance; `ds` along the road's s axis,
//! `dsLane` along the reference lane's driving direction; at a junction the route's arm, or
//! the arm turning least from the lane's driving direction, a tie drawn from the run's seeded
//! generator when a teleport resolves the position, as esmini's MoveToConnectingRoad). The route is the entity's own
//! when an action puts it there, else the reference entity's. The result is on the road the
//! copy reached: a lane position keeps the reference entity's lane id plus `dLane` (not the id
//! of the lane the copy followed onto that road), a road position the copy's t plus `dt`.

use crate::entities::Entity;
use crate::esmini_random::EsminiRandom;
use crate::positions::{face_along_road, place, relative_heading, road_placement, step_lane, Placement, PositionError};
use crate::roads::lane_geometry::{lane_borders, lane_center_t};
use crate::roads::lane_position::LanePos;
use opendrive::{drives_along_s, RoadNetwork, TrafficRule};
use openscenario::Orientation;

/// How a RelativeLanePosition measures its distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Along {
    /// `ds`: along the road's s axis.
    Road(f64),
    /// `dsLane`: along the reference lane's driving direction.
    Lane(f64),
}

impl Along {
    /// From the attributes as written (`ds` wins, as in esmini's reader).
    pub(crate) fn of(ds: Option<f64>, ds_lane: Option<f64>) -> Along {
        match (ds, ds_lane) {
            (Some(d), _) => Along::Road(d),
            (None, Some(d)) => Along::Lane(d),
            (None, None) => Along::Road(0.0),
        }
    }
}

/// The reference entity's lane position moved `ds` in road s (+: along +s).
fn moved(net: &RoadNetwork, e: &Entity, ds: f64, own_route: Option<&routing::Route>, random: Option<&mut EsminiRandom>) -> Result<LanePos, PositionError> {
    let mut lp = e.lane.ok_or_else(|| format!("entity `{}` is not on a road", e.name))?;
    lp.dir = 1.0;
    let route = own_route.or(e.route.as_deref());
    crate::roads::move_along_road_s(net, &mut lp, ds, route, random);
    Ok(lp)
}

/// esmini's RELATIVE_ROAD: the moved copy's t plus `dt`, heading from the road's direction.
pub(crate) fn relative_road(
    net: &RoadNetwork,
    e: &Entity,
    ds: f64,
    dt: f64,
    orientation: Option<&Orientation>,
    own_route: Option<&routing::Route>,
    random: Option<&mut EsminiRandom>,
) -> Result<Placement, PositionError> {
    let lp = moved(net, e, ds, own_route, random)?;
    let road = net.roads.get(lp.road).ok_or("reference road missing")?;
    let t = lane_center_t(road, lp.lane_id, lp.s).unwrap_or(0.0) + lp.offset;
    let mut p = road_placement(net, lp.road, lp.s, t + dt, orientation)?;
    // The heading is relative to the road's reference direction — along +s without an
    // orientation — whichever side of the road the entity lands on; only an absolute
    // orientation is kept as is.
    face_along_road(net, &mut p, orientation);
    Ok(p)
}

/// esmini's RELATIVE_LANE. With `dsLane` the copy moves along the reference lane's driving
/// direction, and dLane and the offset count to the left of it — unless the reference entity
/// faces along its lane's driving direction on the rule's side of the road (right-hand
/// traffic: a right lane, facing +s), when they count as with `ds` (towards higher lane ids).
// The attributes of esmini's RelativeLanePosition, plus the route and the generator its move
// through a junction may use: grouping them would only rename them.
#[allow(clippy::too_many_arguments)]
pub(crate) fn relative_lane(
    net: &RoadNetwork,
    e: &Entity,
    d_lane: i32,
    along: Along,
    offset: f64,
    orientation: Option<&Orientation>,
    own_route: Option<&routing::Route>,
    random: Option<&mut EsminiRandom>,
) -> Result<Placement, PositionError> {
    let reference = e.lane.ok_or_else(|| format!("entity `{}` is not on a road", e.name))?;
    let ref_road = net.roads.get(reference.road).ok_or("reference road missing")?;
    let (ds, along_lane) = match along {
        Along::Road(d) => (d, false),
        // MoveDirectionMode::LANE_DIRECTION: −sign(lane id) in right-hand traffic, +sign in left.
        Along::Lane(d) => {
            // esmini's SIGN: lane 0 counts as positive.
            let sign = f64::from(crate::roads::lane_side::side(reference.lane_id));
            (d * if ref_road.rule == TrafficRule::LeftHand { sign } else { -sign }, true)
        }
    };
    let lp = moved(net, e, ds, own_route, random)?;
    let (lane_id, offset) = if along_lane {
        let forward = reference.dir > 0.0;
        let as_road = match ref_road.rule {
            TrafficRule::RightHand => forward && reference.lane_id < 0,
            TrafficRule::LeftHand => !forward && reference.lane_id > 0,
        };
        if as_road {
            (step_lane(reference.lane_id, d_lane), offset)
        } else {
            (step_lane(reference.lane_id, -d_lane), -offset)
        }
    } else {
        (step_lane(reference.lane_id, d_lane), offset)
    };
    let road = net.roads.get(lp.road).ok_or("road missing")?;
    let o = relative_heading(orientation);
    if lane_borders(road, road.section_index_at(lp.s), lane_id, lp.s).is_none() {
        // No such lane: esmini's SetLanePos fails and the position keeps where the copy went,
        // its lane id and world point, but SetLanePosMode has already stored the asked offset:
        // the first move goes on from there (the copy's offset is gone).
        let along_s = !along_lane || drives_along_s(road.rule, lp.lane_id);
        let mut p = place(net, lp.road, lp.lane_id, lp.s, lp.offset, along_s, Some(&o))?;
        if let Some(kept) = p.lane.as_mut().filter(|l| l.offset != offset) {
            kept.offset = offset;
            p.world_left = true;
        }
        return Ok(p);
    }
    // Without an absolute heading the entity faces from the road's s direction, turned by π
    // with `dsLane` where the new lane drives against s (esmini's SetHeadingRelative).
    let along_s = !along_lane || drives_along_s(road.rule, lane_id);
    place(net, lp.road, lane_id, lp.s, offset, along_s, Some(&o))
}
