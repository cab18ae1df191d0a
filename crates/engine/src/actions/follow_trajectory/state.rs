//! What a running FollowTrajectoryAction remembers: the path, where the entity is on it, its
//! timing.

use trajectory::{Path, TimeMapping};

#[derive(Debug, Clone)]
pub(crate) struct FollowTrajectoryRt {
    pub path: Path,
    /// Arc length of the entity along the path.
    pub s: f64,
    /// Timing, None when the trajectory's time stamps are ignored.
    pub timing: Option<TimeMapping>,
    /// esmini's running trajectory time (before the offset is added).
    pub time: f64,
    /// esmini's simulation clock at the step in progress: the sum of the steps so far, whose
    /// rounding an absolute time reference reads (esmini's simTime).
    pub clock: f64,
    /// A timed polyline's vertices as esmini times them: (s, t, speed, acceleration to the
    /// next), by the following mode (`polyline_timing`).
    pub vertices: Option<Vec<(f64, f64, f64, f64)>>,
    /// −1 when the entity faces against the path (it started reversing), else 1; fixed at
    /// the start (esmini's `initialHeadingSign_`).
    pub heading_sign: f64,
    /// Started reversing along vertices that all give headings: the entity faces as they say,
    /// never turned by π (esmini's explicit_h_active_).
    pub faces_vertex_headings: bool,
    /// Some vertex gives its height (a z or dz): the entity pitches with the path rather than
    /// with the road (`attitude.rs`).
    pub elevated: bool,
    /// A clothoid or clothoid spline: a trajectory time outside its stamps' range puts the
    /// entity at the path's end (esmini's ClothoidShape and ClothoidSplineShape::Evaluate).
    pub end_outside_times: bool,
    /// A single Clothoid shape with its (startTime, stopTime): esmini's ClothoidShape::Evaluate
    /// maps a time in range to s = length · (t − 2·start) / (stop − start) (the start time
    /// taken off twice), kept unclamped for the speed while the pose is clamped to the path.
    pub clothoid_times: Option<(f64, f64)>,
    /// The s and heading of the pose last evaluated on a path that is not a polyline: there
    /// the heading is the path's own (esmini's GetHTrue after that evaluation), which the next
    /// timed step's headingDirection reads back instead of evaluating the path again.
    pub true_heading_at: Option<(f64, f64)>,
}
