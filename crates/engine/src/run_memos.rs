//! One run's memos. The per-step memos of `roads` (reference poses, lane borders, lane shapes,
//! world → lane searches, esmini's junction connections, lane 0's OSI points) and `position_cache` (routes, trajectory paths) are keyed by the
//! addresses of the network and scenario a run borrows, and live in thread-local slots so
//! that the hot paths reach them without a handle. A run owns its own set and swaps it into
//! the slots of the thread stepping it for the duration of a step (`RunMemos::enter`): two
//! runs stepped in turn on one thread (closed-loop simulations side by side), or one run
//! stepped from different threads, never see each other's entries, and an address a later
//! network reuses never finds a stale one.

use crate::position_cache;
use crate::roads::{junction_connections, lane_shape, locate, pose_memo, track_pos};

/// The memo entries of one run; `None` while they are held in the thread's slots for all of
/// a run's frames ([`RunMemos::take`]).
pub(crate) struct RunMemos(Option<Stores>);

/// The entries themselves.
struct Stores {
    poses: pose_memo::Store,
    shapes: lane_shape::Store,
    located: locate::Store,
    positions: position_cache::Store,
    connections: junction_connections::Store,
    lane0_points: track_pos::Store,
}

impl RunMemos {
    /// No entries yet (a run starts).
    pub(crate) fn new() -> RunMemos {
        RunMemos(Some(Stores {
            poses: pose_memo::Store::new(),
            shapes: lane_shape::Store::new(),
            located: locate::Store::new(),
            positions: position_cache::Store::new(),
            connections: junction_connections::Store::new(),
            lane0_points: track_pos::Store::new(),
        }))
    }

    /// This run's entries in the thread's slots until the guard drops (then the slots hold
    /// what they held before). Nothing to do while the entries are taken: whoever took them
    /// holds them in the slots already.
    pub(crate) fn enter(&mut self) -> Entered<'_> {
        let mut stores = self.0.as_mut();
        if let Some(s) = &mut stores {
            s.swap();
        }
        Entered(stores)
    }

    /// The entries, leaving `self` without them, so that the taker can enter them once for
    /// many frames (each [`RunMemos::enter`] of `self` then leaves the slots as they are).
    pub(crate) fn take(&mut self) -> RunMemos {
        RunMemos(self.0.take())
    }
}

impl Stores {
    fn swap(&mut self) {
        self.poses.swap_with_thread();
        self.shapes.swap_with_thread();
        self.located.swap_with_thread();
        self.positions.swap_with_thread();
        self.connections.swap_with_thread();
        self.lane0_points.swap_with_thread();
    }
}

/// While alive, the thread's memo slots hold one run's entries.
pub(crate) struct Entered<'m>(Option<&'m mut Stores>);

impl Drop for Entered<'_> {
    fn drop(&mut self) {
        if let Some(s) = &mut self.0 {
            s.swap();
        }
    }
}
