//! Superelevation (road banking) as esmini applies it to lane positions: a point t across a
//! road rolled by angle r lies t·cos r out horizontally and t·sin r up, and as the roll changes
//! along s the horizontal offset changes, turning the path's heading.

use opendrive::model::poly::record_at;
use opendrive::Road;

/// Roll angle (rad) and its rate d(roll)/ds at `s`; (0, 0) on a road without superelevation.
pub(crate) fn roll_at(road: &Road, s: f64) -> (f64, f64) {
    match record_at(&road.superelevation, s) {
        Some(r) => (r.value(s - r.s), r.slope(s - r.s)),
        None => (0.0, 0.0),
    }
}

/// For a point `t` across the road at `s` on a road of reference curvature `curvature`: the
/// horizontal offset, the height above the reference line, and the heading added to the
/// reference heading by the changing roll.
pub(crate) fn banked(road: &Road, s: f64, t: f64, curvature: f64) -> (f64, f64, f64) {
    if road.superelevation.is_empty() {
        return (t, 0.0, 0.0);
    }
    let (roll, rate) = roll_at(road, s);
    let (sin, cos) = roll.sin_cos();
    let th = t * cos;
    let dth = -t * sin * rate;
    let turn = if dth == 0.0 { 0.0 } else { dth.atan2(1.0 - curvature * th) };
    (th, t * sin, turn)
}

/// The inverse of [`banked`]'s lateral part, as esmini's `Position::XYZ2TrackPos` does it: a
/// world point's horizontal distance `th` from the reference line at `s` is divided by
/// cos(roll) ("compensate for banking"), so its t is measured along the tilted surface.
pub(crate) fn surface_t(road: &Road, s: f64, th: f64) -> f64 {
    if road.superelevation.is_empty() {
        return th;
    }
    let cos = roll_at(road, s).0.cos();
    // A road rolled to the vertical has no horizontal extent: keep the distance as it is.
    if cos.abs() < 1e-9 {
        th
    } else {
        th / cos
    }
}
