//! FollowTrajectoryAction's TimeReference: simulation time ↔ trajectory time.
//!
//! esmini evaluates a timed trajectory at `scale · elapsed + offset` where `elapsed` is the
//! time since the action started (relative domain) or the simulation time (absolute
//! domain); this module implements that mapping and its inverse. Whether timing is used
//! at all (TimeReference `None`) is the engine's decision.

/// The `domainAbsoluteRelative` of a Timing element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimeDomain {
    Absolute,
    Relative,
}

/// A Timing element: domain, scale, offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeMapping {
    pub domain: TimeDomain,
    pub scale: f64,
    pub offset: f64,
}

impl TimeMapping {
    /// Trajectory time to evaluate at simulation time `sim_time` for an action started at
    /// `action_start`.
    pub fn trajectory_time(&self, sim_time: f64, action_start: f64) -> f64 {
        let elapsed = match self.domain {
            TimeDomain::Absolute => sim_time,
            TimeDomain::Relative => sim_time - action_start,
        };
        self.scale * elapsed + self.offset
    }

    /// Simulation time at which trajectory time `traj_time` is reached (`None` if the scale
    /// is zero or not finite: time then stands still on the trajectory).
    pub fn simulation_time(&self, traj_time: f64, action_start: f64) -> Option<f64> {
        if self.scale == 0.0 || !self.scale.is_finite() {
            return None;
        }
        let elapsed = (traj_time - self.offset) / self.scale;
        Some(match self.domain {
            TimeDomain::Absolute => elapsed,
            TimeDomain::Relative => elapsed + action_start,
        })
    }
}
