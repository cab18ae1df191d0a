//! Memo of road reference-line poses. The engine asks for the pose at the same (road, s) more
//! than once per step (an entity placed at s one step is moved from s the next), and a pose
//! on a paramPoly3 costs an arc-length inversion. The memo is a pure function cache keyed by
//! the road's identity and the exact bits of s, so results are bit-identical to the direct
//! call (the borders of an entity's lane likewise); each run keeps its own entries (`run_memos.rs`: addresses are only stable while a network is borrowed).

use opendrive::{CurvePose, Road};
use std::cell::RefCell;

const SLOTS: usize = 256;

/// (road address, geometry address, length bits, s bits).
type Key = (usize, usize, u64, u64);

thread_local! {
    static MEMO: RefCell<Vec<Option<(Key, CurvePose)>>> = RefCell::new(vec![None; SLOTS]);
}

fn key(road: &Road, s: f64) -> Key {
    (road as *const Road as usize, road.geometries.as_ptr() as usize, road.length.to_bits(), s.to_bits())
}

fn slot(k: &Key) -> usize {
    // Fibonacci hashing of the mixed key: cheap and spreads nearby s values.
    let h = (k.0 as u64 ^ k.3.rotate_left(17) ^ k.2.rotate_left(41)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    (h >> 56) as usize % SLOTS
}

/// `road.reference_pose(s)`, from the memo when it was asked before. The hit is inlined into
/// its callers (millions per run), the miss is not.
#[inline]
pub(crate) fn reference_pose(road: &Road, s: f64) -> CurvePose {
    let k = key(road, s);
    let i = slot(&k);
    if let Some(p) = MEMO.with(|m| m.borrow().get(i).copied().flatten().filter(|e| e.0 == k).map(|e| e.1)) {
        return p;
    }
    reference_pose_missed(road, s, k, i)
}

#[inline(never)]
fn reference_pose_missed(road: &Road, s: f64, k: Key, i: usize) -> CurvePose {
    let p = road.reference_pose(s);
    MEMO.with(|m| {
        if let Some(e) = m.borrow_mut().get_mut(i) {
            *e = Some((k, p));
        }
    });
    p
}

/// One run's entries of both memos (`crate::run_memos`).
pub(crate) struct Store {
    poses: Vec<Option<(Key, CurvePose)>>,
    lanes: Vec<LaneEntry>,
}

impl Store {
    /// No entries.
    pub(crate) fn new() -> Store {
        Store { poses: vec![None; SLOTS], lanes: vec![None; SLOTS] }
    }

    /// Exchange these entries with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        MEMO.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.poses));
        LANES.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.lanes));
    }
}

/// Forget the thread's entries (tests).
#[cfg(test)]
pub(crate) fn clear() {
    Store::new().swap_with_thread();
}

type LaneKey = (usize, i32, u64);
type LaneEntry = Option<(LaneKey, Option<opendrive::LaneBorders>)>;

thread_local! {
    static LANES: RefCell<Vec<LaneEntry>> = RefCell::new(vec![None; SLOTS]);
}

/// Borders (inner, outer) of lane `lane_id` at `s` (section looked up), from the memo when it
/// was asked before: an entity's lane is asked at the s where it was placed when it moves on.
pub(crate) fn lane_borders_at(road: &Road, lane_id: i32, s: f64) -> Option<opendrive::LaneBorders> {
    let k: LaneKey = (road as *const Road as usize, lane_id, s.to_bits());
    let h = (k.0 as u64 ^ k.2.rotate_left(17) ^ u64::from(lane_id as u32).rotate_left(29)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    let i = (h >> 56) as usize % SLOTS;
    if let Some(b) = LANES.with(|m| m.borrow().get(i).copied().flatten().filter(|e| e.0 == k).map(|e| e.1)) {
        return b;
    }
    let b = super::lane_geometry::lane_borders(road, road.section_index_at(s), lane_id, s);
    LANES.with(|m| {
        if let Some(e) = m.borrow_mut().get_mut(i) {
            *e = Some((k, b));
        }
    });
    b
}
