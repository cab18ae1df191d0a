//! A trajectory vertex given as a WorldPosition without h at its road's very end takes the
//! absolute heading 0, as a point past the road's end does: esmini's last OSI point lies at
//! L - SMALL_NUMBER/2, and a point beyond it, the end itself included, is off the road's
//! reference direction. The engine counted only points strictly past L. Found by a helper on
//! s75075_00549.
//!
//! Fixture `nurbs_control_point_at_road_end.xosc` on crossing.xodr: Ego follows a NURBS whose
//! last control point, without h, is the west arm's end (-320, 5.25). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_last_control_point_faces_zero() {
    assert_fixture_matches_esmini(
        "nurbs_control_point_at_road_end.xosc",
        4.0,
        &[("Ego", 0.12, -281.096056, 5.156723, 2.978596), ("Ego", 1.0, -289.877833, 4.599127, 2.147907), ("Ego", 3.0, -309.871442, 4.588162, 0.580922)],
    );
}
