//! Input poses (resolved vertex positions) and evaluated path points.

/// A world pose as the engine resolves an OpenSCENARIO position.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub heading: f64,
}

impl Pose {
    pub fn new(x: f64, y: f64, z: f64, heading: f64) -> Pose {
        Pose { x, y, z, heading }
    }
    pub(crate) fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite() && self.heading.is_finite()
    }
}

/// A point of a path at arc length `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathPoint {
    pub s: f64,
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Heading in [0, 2π).
    pub heading: f64,
    /// dheading/ds (1/m, + to the left).
    pub curvature: f64,
}

impl PathPoint {
    /// The point `t` metres to the left of this one (TrajectoryPosition's lateral offset).
    pub fn offset(&self, t: f64) -> (f64, f64) {
        let (sin, cos) = self.heading.sin_cos();
        (self.x - t * sin, self.y + t * cos)
    }
}
