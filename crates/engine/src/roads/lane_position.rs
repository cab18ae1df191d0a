//! A position attached to a lane: road, lane, s, lateral offset from the lane centre, and
//! which way along s the entity faces.

use super::lane_geometry::lane_center_t;
use opendrive::RoadNetwork;

/// An entity's place on the road network.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LanePos {
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
pub struct LanePose {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub road_heading: f64,
    pub curvature: f64,
    pub t: f64,
}

impl LanePos {
    /// World pose; `None` if the road or lane is missing.
    pub fn pose(&self, net: &RoadNetwork) -> Option<LanePose> {
        let road = net.roads.get(self.road)?;
        let s = self.s.clamp(0.0, road.length);
        let t = lane_center_t(road, self.lane_id, s).unwrap_or(0.0) + self.offset;
        let p = road.reference_pose(s);
        let (sin, cos) = p.hdg.sin_cos();
        Some(LanePose {
            x: p.x - t * sin,
            y: p.y + t * cos,
            z: road.elevation_at(s),
            road_heading: p.hdg,
            curvature: p.curvature,
            t,
        })
    }

    /// Heading of the driving direction the entity faces (reference heading, turned by π when
    /// it faces -s).
    pub fn facing_heading(&self, pose: &LanePose) -> f64 {
        if self.dir < 0.0 {
            pose.road_heading + std::f64::consts::PI
        } else {
            pose.road_heading
        }
    }
}
