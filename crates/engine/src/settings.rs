//! How a run is driven: the fixed step and the time cap.

/// Engine settings (defaults are the paper's: 0.01 s step, 60 s cap).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Fixed engine step, s.
    pub step: f64,
    /// Simulated time after which the run stops even if the storyboard is still running, s.
    pub max_time: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings { step: 0.01, max_time: 60.0 }
    }
}

/// What steers one run besides its settings: esmini's random seed and a wall-clock limit.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunControl {
    /// Seed of esmini's random generator (esmini's `--seed`; the reference traces use 0). It
    /// decides what esmini leaves to chance, e.g. which of two equally turning junction arms an
    /// entity takes.
    pub seed: u32,
    /// Stop with [`crate::Error::Deadline`] once this instant has passed (a batch's per-scenario
    /// time limit). Checked every few hundred steps, so a run overshoots it by well under 1 ms.
    pub deadline: Option<std::time::Instant>,
}

/// Most steps one run may take (hostile settings: a tiny step with a huge cap).
pub(crate) const MAX_STEPS: usize = 10_000_000;

impl Settings {
    pub(crate) fn check(&self) -> Result<(), crate::Error> {
        if !(self.step.is_finite() && self.step > 0.0) {
            return Err(crate::Error::Settings(format!("step must be a positive number of seconds, got {}", self.step)));
        }
        if !(self.max_time.is_finite() && self.max_time >= 0.0) {
            return Err(crate::Error::Settings(format!("max time must be a non-negative number of seconds, got {}", self.max_time)));
        }
        if self.max_time / self.step > MAX_STEPS as f64 {
            return Err(crate::Error::Settings(format!("max time / step = {:.0} steps, more than the {} accepted", self.max_time / self.step, MAX_STEPS)));
        }
        Ok(())
    }
}
