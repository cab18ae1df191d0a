//! One run's memos. The per-step memos of `roads` (reference poses, lane borders, lane shapes,
//! world → lane searches) and `position_cache` (routes, trajectory paths) are keyed by the
//! addresses of the network and scenario a run borrows, and live in thread-local slots so
//! that the hot paths reach them without a handle. A run owns its own set and swaps it into
//! the slots of the thread stepping it for the duration of a step (`RunMemos::enter`): two
//! runs stepped in turn on one thread (closed-loop simulations side by side), or one run
//! stepped from different threads, never see each other's entries, and an address a later
//! network reuses never finds a stale one.

use crate::position_cache;
use crate::roads::{lane_shape, locate, pose_memo};

/// The memo entries of one run.
pub(crate) struct RunMemos {
    poses: pose_memo::Store,
    shapes: lane_shape::Store,
    located: locate::Store,
    positions: position_cache::Store,
}

impl RunMemos {
    /// No entries yet (a run starts).
    pub(crate) fn new() -> RunMemos {
        RunMemos { poses: pose_memo::Store::new(), shapes: lane_shape::Store::new(), located: locate::Store::new(), positions: position_cache::Store::new() }
    }

    /// This run's entries in the thread's slots until the guard drops (then the slots hold
    /// what they held before).
    pub(crate) fn enter(&mut self) -> Entered<'_> {
        self.swap();
        Entered(self)
    }

    fn swap(&mut self) {
        self.poses.swap_with_thread();
        self.shapes.swap_with_thread();
        self.located.swap_with_thread();
        self.positions.swap_with_thread();
    }
}

/// While alive, the thread's memo slots hold one run's entries.
pub(crate) struct Entered<'m>(&'m mut RunMemos);

impl Drop for Entered<'_> {
    fn drop(&mut self) {
        self.0.swap();
    }
}
