//! Lane borders of a whole lane section at one s, as t values, with lane widths clamped at
//! zero: a width polynomial that dips below zero (or a `<border>` record that crosses its
//! inner neighbour) would otherwise fold the lane over its neighbour and make the lanelet
//! polygon self-intersecting.

use opendrive::{CubicRecord, Road};

/// The border t values of every lane of a section at one s.
/// Index 0 is the centre line (lane offset); then the outer border of each left lane in the
/// section's order (id 1, 2, ... outward); then the outer border of each right lane
/// (id −1, −2, ... outward).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SectionCut {
    pub t: Vec<f64>,
}

/// Position of a lane's two borders in [`SectionCut::t`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct BorderIdx {
    pub inner: usize,
    pub outer: usize,
}

/// Border indices of the lane at position `pos` of the left (`left = true`) or right side.
pub(crate) fn border_idx(n_left: usize, left: bool, pos: usize) -> BorderIdx {
    let first = if left { 1 } else { 1 + n_left };
    let outer = first + pos;
    let inner = if pos == 0 { 0 } else { outer - 1 };
    BorderIdx { inner, outer }
}

fn record_at(records: &[CubicRecord], s: f64) -> Option<&CubicRecord> {
    let i = records.partition_point(|r| r.s <= s);
    records.get(i.saturating_sub(1))
}

/// Border t values of section `sec_idx` of `road` at `s` (clamped, see the module doc).
pub(crate) fn section_cut(road: &Road, sec_idx: usize, s: f64) -> SectionCut {
    let mut t = Vec::new();
    let base = road.lane_offset_at(s);
    t.push(base);
    let Some(sec) = road.lane_sections.get(sec_idx) else { return SectionCut { t } };
    let ds = s - sec.s;
    for (lanes, sign) in [(&sec.left, 1.0), (&sec.right, -1.0)] {
        let mut inner = base;
        for lane in lanes.iter() {
            let outer = if !lane.widths.is_empty() {
                let w = record_at(&lane.widths, ds).map_or(0.0, |r| r.value(ds - r.s));
                inner + sign * w.max(0.0)
            } else if let Some(b) = record_at(&lane.borders, ds) {
                let raw = base + b.value(ds - b.s);
                // never on the inner side of the inner border
                if sign * (raw - inner) < 0.0 {
                    inner
                } else {
                    raw
                }
            } else {
                inner
            };
            t.push(outer);
            inner = outer;
        }
    }
    SectionCut { t }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn border_indices_follow_the_layout() {
        // 2 left lanes, 3 right lanes: t = [centre, L1, L2, R1, R2, R3]
        assert_eq!(border_idx(2, true, 0), BorderIdx { inner: 0, outer: 1 });
        assert_eq!(border_idx(2, true, 1), BorderIdx { inner: 1, outer: 2 });
        assert_eq!(border_idx(2, false, 0), BorderIdx { inner: 0, outer: 3 });
        assert_eq!(border_idx(2, false, 2), BorderIdx { inner: 4, outer: 5 });
    }
}
