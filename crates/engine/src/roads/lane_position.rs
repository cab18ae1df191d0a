//! A position attached to a lane: road, lane, s, lateral offset from the lane centre, and
//! which way along s the entity faces.

use opendrive::RoadNetwork;

/// An entity's place on the road network.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LanePos {
    /// Index into `RoadNetwork::roads`.
    pub road: usize,
    pub lane_id: i32,
    pub s: f64,
    /// Lateral offset from the lane centre, + to the left of the reference line.
    pub offset: f64,
    /// +1 when the entity faces along +s, -1 against.
    pub dir: f64,
}

/// World pose of a lane position: x, y, z, reference-line heading, curvature of the reference line,
/// and t (lateral coordinate from the reference line).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LanePose {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub road_heading: f64,
    pub curvature: f64,
    pub t: f64,
    /// t of the inner and outer border of the position's own lane (`None`: no such lane).
    pub lane: Option<(f64, f64)>,
}

impl LanePos {
    /// The reference line's heading at the position's s (esmini's GetHRoad, set from the
    /// geometry alone: no turn from a changing superelevation, which `LanePose::road_heading`
    /// has); `None` if the road is missing.
    pub(crate) fn reference_heading(&self, net: &RoadNetwork) -> Option<f64> {
        let road = net.roads.get(self.road)?;
        Some(super::pose_memo::reference_pose(road, self.s.clamp(0.0, road.length)).hdg)
    }

    /// World pose; `None` if the road or lane is missing.
    pub(crate) fn pose(&self, net: &RoadNetwork) -> Option<LanePose> {
        let road = net.roads.get(self.road)?;
        let s = self.s.clamp(0.0, road.length);
        let lane = super::pose_memo::lane_borders_at(road, self.lane_id, s);
        let t = lane.map_or(0.0, |b| b.center) + self.offset;
        let p = super::pose_memo::reference_pose(road, s);
        let (sin, cos) = p.hdg.sin_cos();
        // On a banked road t lies along the tilted surface (see banking.rs).
        let (mut th, mut dz, turn, mut along) = super::banking::banked(road, s, t, p.curvature);
        // a raised lane (kerb, sidewalk) lifts the point along the road's normal
        if let Some((d_th, d_z, d_along)) = lane.and_then(|b| super::lane_height::lift(road, s, self.lane_id, self.offset, b)) {
            th += d_th;
            dz += d_z;
            along += d_along;
        }
        Some(LanePose {
            x: p.x - th * sin + along * cos,
            y: p.y + th * cos + along * sin,
            z: road.elevation_at(s) + dz,
            road_heading: p.hdg + turn,
            curvature: p.curvature,
            t,
            lane: lane.map(|b| (b.inner, b.outer)),
        })
    }

    /// Heading of the driving direction the entity faces (reference heading, turned by π when
    /// it faces -s).
    pub(crate) fn facing_heading(&self, pose: &LanePose) -> f64 {
        if self.dir < 0.0 {
            pose.road_heading + std::f64::consts::PI
        } else {
            pose.road_heading
        }
    }
}
