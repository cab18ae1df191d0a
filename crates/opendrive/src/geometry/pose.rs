//! Poses along a curve.

/// Position, heading and curvature of a curve point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CurvePose {
    pub x: f64,
    pub y: f64,
    /// Tangent direction, radians, counter-clockwise from +x.
    pub hdg: f64,
    /// Signed curvature (1/m), positive turning left.
    pub curvature: f64,
}
