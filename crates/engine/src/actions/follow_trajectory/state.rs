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
    /// Following mode `follow` with time stamps: per segment between stamps (s, t, v, a),
    /// constant acceleration with the speed continuous, starting at the first segment's
    /// mean speed (esmini's vertex speeds); `position` mode moves at each segment's mean speed.
    pub accel: Option<Vec<(f64, f64, f64, f64)>>,
    /// −1 when the entity faces against the path (it started reversing), else 1; fixed at
    /// the start (esmini's `initialHeadingSign_`).
    pub heading_sign: f64,
    /// Some vertex gives its height (a z or dz): the entity pitches with the path rather than
    /// with the road (`attitude.rs`).
    pub elevated: bool,
}
