//! Line markings of lanelet bounds from OpenDRIVE road marks. The marking of a border is the
//! road mark of the lane whose outer border it is (the centre lane's for the centre line).

use commonroad::LineMarking;
use opendrive::{Lane, RoadMark, RoadMarkType};

/// CommonRoad marking of an OpenDRIVE road mark type; `None` = unknown (not written).
/// Double lines are named left-to-right looking along +s; `against_s` swaps them for a
/// lanelet whose driving direction is −s.
pub fn marking(kind: RoadMarkType, against_s: bool) -> Option<LineMarking> {
    use RoadMarkType as R;
    Some(match kind {
        R::Solid => LineMarking::Solid,
        R::Broken => LineMarking::Dashed,
        R::SolidSolid => LineMarking::SolidSolid,
        R::BrokenBroken => LineMarking::DashedDashed,
        R::SolidBroken if against_s => LineMarking::DashedSolid,
        R::SolidBroken => LineMarking::SolidDashed,
        R::BrokenSolid if against_s => LineMarking::SolidDashed,
        R::BrokenSolid => LineMarking::DashedSolid,
        R::Curb => LineMarking::Curb,
        R::None => LineMarking::NoMarking,
        R::BottsDots | R::Grass | R::Custom | R::Edge | R::Other => return None,
    })
}

/// The road mark covering the longest part of a section of length `len` (marks are ordered
/// by their sOffset; each holds until the next).
pub fn dominant_mark(marks: &[RoadMark], len: f64) -> Option<&RoadMark> {
    let mut best: Option<(&RoadMark, f64)> = None;
    for (i, m) in marks.iter().enumerate() {
        let end = marks.get(i + 1).map_or(len, |n| n.s_offset).min(len);
        let cover = end - m.s_offset.max(0.0);
        if best.is_none_or(|(_, c)| cover > c) {
            best = Some((m, cover));
        }
    }
    best.map(|(m, _)| m)
}

/// Marking of the outer border of `lane` (of the centre line for the centre lane).
pub fn border_marking(lane: Option<&Lane>, section_len: f64, against_s: bool) -> Option<LineMarking> {
    lane.and_then(|l| dominant_mark(&l.road_marks, section_len)).and_then(|m| marking(m.kind, against_s))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mark(s: f64, kind: RoadMarkType) -> RoadMark {
        RoadMark {
            s_offset: s,
            kind,
            type_raw: String::new(),
            weight: None,
            color: None,
            material: None,
            width: None,
            height: None,
            lane_change: None,
            lines: 0,
        }
    }

    #[test]
    fn mapping_of_mark_types() {
        assert_eq!(marking(RoadMarkType::Broken, false), Some(LineMarking::Dashed));
        assert_eq!(marking(RoadMarkType::SolidSolid, true), Some(LineMarking::SolidSolid));
        assert_eq!(marking(RoadMarkType::SolidBroken, false), Some(LineMarking::SolidDashed));
        assert_eq!(marking(RoadMarkType::SolidBroken, true), Some(LineMarking::DashedSolid));
        assert_eq!(marking(RoadMarkType::None, false), Some(LineMarking::NoMarking));
        assert_eq!(marking(RoadMarkType::BottsDots, false), None);
    }

    #[test]
    fn dominant_mark_is_the_longest() {
        // solid on [0, 10), broken on [10, 100)
        let marks = [mark(0.0, RoadMarkType::Solid), mark(10.0, RoadMarkType::Broken)];
        assert_eq!(dominant_mark(&marks, 100.0).map(|m| m.kind), Some(RoadMarkType::Broken));
        assert_eq!(dominant_mark(&marks, 15.0).map(|m| m.kind), Some(RoadMarkType::Solid));
        assert!(dominant_mark(&[], 5.0).is_none());
    }
}
