//! What a NaturalDriver remembers: its IDM and MOBIL parameters, its mode and its lane changes.

use crate::actions::lane_change::state::LaneChangeRt;

/// The driver's parameters (esmini's defaults when a property is missing).
#[derive(Debug, Clone)]
pub(crate) struct NdParams {
    pub desired_distance: f64,
    pub desired_speed: f64,
    pub lane_change_duration: f64,
    pub lookahead: f64,
    /// Comfortable deceleration, negative.
    pub max_dec: f64,
    pub max_acc: f64,
    pub lane_change_delay: f64,
    pub thw: f64,
    pub max_imposed_braking: f64,
    pub politeness: f64,
    pub lane_change_acc_gain: f64,
    /// The lane id the driver wants to be in.
    pub route: i32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Mode {
    Drive,
    ChangeLane,
}

/// A NaturalDriver's state during a run.
#[derive(Debug, Clone)]
pub(crate) struct NaturalDriverRt {
    pub active: bool,
    /// esmini's mode: override unless the `mode` property says additive (the driver moves the
    /// entity either way; the mode decides whether a teleport is ignored).
    pub(in crate::controllers) override_mode: bool,
    pub p: NdParams,
    pub(super) current_speed: f64,
    pub(super) mode: Mode,
    /// A lane change was injected and its cool-down runs.
    pub lane_change_injected: bool,
    pub(super) cooldown: f64,
    pub target_lane: i32,
    /// Injected lane change waiting for the next frame to start (target lane, action name).
    pub(super) pending: Option<(i32, String)>,
    /// The injected lane change in progress and its name.
    pub(super) lane_change: Option<(LaneChangeRt, String)>,
    /// Injections so far (esmini numbers injected actions across the run).
    pub injections: u32,
    /// Yaw off the lane that the driver's own lane change gave the entity this frame (kept by
    /// the driver's move); `None` when none of its own stepped: the move keeps the heading the
    /// entity holds relative to the road.
    pub(super) action_yaw: Option<f64>,
}

impl NaturalDriverRt {
    /// Whether its injected lane change waits to start.
    pub(crate) fn lane_change_pending(&self) -> bool {
        self.pending.is_some()
    }

    /// Whether its injected lane change is started or running.
    pub(crate) fn changes_lane(&self) -> bool {
        self.pending.is_some() || self.lane_change.is_some()
    }
}

/// ScenarioEngine's object_distance_map_: when each ordered pair of entities is due again (its
/// next_update_, on esmini's accumulated clock), a square table by entity index; NaN where the
/// pair has no entry.
#[derive(Debug, Clone, Default)]
pub(crate) struct DistanceCache {
    n: usize,
    next_update: Vec<f64>,
}

impl DistanceCache {
    /// The entry of pair (a, b), if it has one.
    pub(crate) fn get(&self, a: usize, b: usize) -> Option<f64> {
        if a >= self.n || b >= self.n {
            return None;
        }
        self.next_update.get(a * self.n + b).copied().filter(|t| !t.is_nan())
    }

    /// Set the entry of pair (a, b), growing the table to hold it.
    pub(crate) fn set(&mut self, a: usize, b: usize, next: f64) {
        let need = a.max(b) + 1;
        if need > self.n {
            let mut grown = vec![f64::NAN; need * need];
            for i in 0..self.n {
                grown[i * need..i * need + self.n].copy_from_slice(&self.next_update[i * self.n..(i + 1) * self.n]);
            }
            self.n = need;
            self.next_update = grown;
        }
        self.next_update[a * self.n + b] = next;
    }

    /// Drop the entry of pair (a, b).
    pub(crate) fn remove(&mut self, a: usize, b: usize) {
        if a < self.n && b < self.n {
            self.next_update[a * self.n + b] = f64::NAN;
        }
    }
}
