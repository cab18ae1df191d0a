//! What the per-step lane rules may skip: a lane whose centre runs parallel to the reference
//! line throughout its section (constant lane offset, constant widths of it and of every lane
//! inside it) never drifts sideways (`lane_slope`), and a lane of constant positive width never
//! narrows to nothing (`zero_width`). Most corpus lanes are such lanes, and asking once per
//! (road, section, lane) instead of evaluating slopes and borders every step keeps the engine's
//! per-step cost low. Memoised like `pose_memo`, one set of entries per run.

use opendrive::model::poly::CubicRecord;
use opendrive::Road;
use std::cell::RefCell;

/// Facts about one lane of one section.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct LaneShape {
    /// The lane's centre keeps its distance to the reference line throughout the section.
    pub parallel: bool,
    /// The lane's width is constant and positive throughout the section.
    pub never_zero_width: bool,
}

const SLOTS: usize = 256;

/// (road address, section, lane id).
type Key = (usize, usize, i32);

thread_local! {
    static MEMO: RefCell<Vec<Option<(Key, LaneShape)>>> = RefCell::new(vec![None; SLOTS]);
}

fn constant(records: &[CubicRecord]) -> bool {
    records.iter().all(|r| r.b == 0.0 && r.c == 0.0 && r.d == 0.0)
}

/// The facts of lane `lane_id` in section `section` of `road` (a lane that does not exist is
/// neither parallel nor safe from zero width, so nothing is skipped for it).
pub(crate) fn lane_shape(road: &Road, section: usize, lane_id: i32) -> LaneShape {
    let k: Key = (road as *const Road as usize, section, lane_id);
    let h = ((k.0 as u64) ^ (k.1 as u64).rotate_left(23) ^ u64::from(lane_id as u32).rotate_left(41)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    let i = (h >> 56) as usize % SLOTS;
    if let Some(v) = MEMO.with(|m| m.borrow().get(i).copied().flatten().filter(|e| e.0 == k).map(|e| e.1)) {
        return v;
    }
    let v = compute(road, section, lane_id);
    MEMO.with(|m| {
        if let Some(e) = m.borrow_mut().get_mut(i) {
            *e = Some((k, v));
        }
    });
    v
}

fn compute(road: &Road, section: usize, lane_id: i32) -> LaneShape {
    let nothing = LaneShape { parallel: false, never_zero_width: false };
    let Some(sec) = road.lane_sections.get(section) else { return nothing };
    let offset_constant = constant(&road.lane_offsets);
    if lane_id == 0 {
        return LaneShape { parallel: offset_constant, never_zero_width: false };
    }
    let lanes = if lane_id > 0 { &sec.left } else { &sec.right };
    let mut inside_constant = offset_constant;
    for lane in lanes {
        // widths rule; a lane given by borders is not analysed
        let own_constant = !lane.widths.is_empty() && constant(&lane.widths);
        if lane.id == lane_id {
            // well above the zero-width test's 1e-10, so rounding in the borders cannot matter
            let positive = lane.widths.iter().all(|r| r.a > 1e-6);
            return LaneShape { parallel: inside_constant && own_constant, never_zero_width: own_constant && positive };
        }
        inside_constant &= own_constant;
    }
    nothing
}

/// One run's entries (`crate::run_memos`).
pub(crate) struct Store(Vec<Option<(Key, LaneShape)>>);

impl Store {
    /// No entries.
    pub(crate) fn new() -> Store {
        Store(vec![None; SLOTS])
    }

    /// Exchange these entries with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        MEMO.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.0));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lane −1 constant 3 m; lane −2 widening then constant; lane −3 constant outside it.
    const ROAD: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="100"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<left><lane id="1" type="driving"><width sOffset="0" a="0" b="0" c="0" d="0"/></lane></left>
<right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="0" b="0.1" c="0" d="0"/><width sOffset="40" a="4" b="0" c="0" d="0"/></lane>
<lane id="-3" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;

    fn road() -> Road {
        let net = opendrive::parse_str(ROAD, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"));
        net.roads.into_iter().next().unwrap_or_else(|| panic!("one road"))
    }

    #[test]
    fn facts_per_lane() {
        Store::new().swap_with_thread();
        let r = road();
        let s = |id| lane_shape(&r, 0, id);
        assert_eq!(s(-1), LaneShape { parallel: true, never_zero_width: true });
        // widening: its centre drifts and it starts at width 0
        assert_eq!(s(-2), LaneShape { parallel: false, never_zero_width: false });
        // constant itself, but outside a widening lane: it drifts
        assert_eq!(s(-3), LaneShape { parallel: false, never_zero_width: true });
        // constant zero width: parallel, but zero wide
        assert_eq!(s(1), LaneShape { parallel: true, never_zero_width: false });
        assert_eq!(s(-9), LaneShape { parallel: false, never_zero_width: false });
        // asked again: the memo gives the same
        assert_eq!(s(-3), LaneShape { parallel: false, never_zero_width: true });
    }
}
