//! Line markings → road marks. A road mark sits on a lane's outer border (the centre lane's on
//! the centre line); double lines are named left to right looking along +s, so the marking of
//! a lanelet driving against s is mirrored.

use crate::model::Mark;
use commonroad::LineMarking;

/// The road mark of a marking; `None` for unknown (no road mark is written). The flag says
/// OpenDRIVE has no exact equivalent.
pub(crate) fn road_mark(m: LineMarking, against_s: bool) -> (Option<Mark>, bool) {
    use LineMarking as L;
    let mk = |kind: &'static str| Some(Mark { kind, weight: None });
    let bold = |kind: &'static str| Some(Mark { kind, weight: Some("bold") });
    match m {
        L::Dashed => (mk("broken"), false),
        L::Solid => (mk("solid"), false),
        L::SolidSolid => (mk("solid solid"), false),
        L::DashedDashed => (mk("broken broken"), false),
        L::SolidDashed if against_s => (mk("broken solid"), false),
        L::SolidDashed => (mk("solid broken"), false),
        L::DashedSolid if against_s => (mk("solid broken"), false),
        L::DashedSolid => (mk("broken solid"), false),
        L::Curb => (mk("curb"), false),
        L::LoweredCurb => (mk("curb"), true),
        L::BroadDashed => (bold("broken"), false),
        L::BroadSolid => (bold("solid"), false),
        L::NoMarking => (mk("none"), false),
        L::Unknown => (None, false),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn double_lines_mirror_against_s() {
        assert_eq!(road_mark(LineMarking::SolidDashed, false).0.map(|m| m.kind), Some("solid broken"));
        assert_eq!(road_mark(LineMarking::SolidDashed, true).0.map(|m| m.kind), Some("broken solid"));
        assert_eq!(road_mark(LineMarking::BroadSolid, false).0.and_then(|m| m.weight), Some("bold"));
        assert!(road_mark(LineMarking::LoweredCurb, false).1);
        assert!(road_mark(LineMarking::Unknown, false).0.is_none());
    }
}
