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
/// horizontal offset across the reference line, the height above it, the heading added to the
/// reference heading by the changing roll, and the shift along the reference heading. esmini
/// (Position::Track2XYZ) turns (0, t, 0) by the road's rotation, heading · pitch · roll
/// (CreateRotationMatrix3d), the pitch being −atan of the elevation's slope: on a road both
/// rolled and sloped the point also moves t·sin(roll)·sin(pitch) along the heading and rises
/// t·sin(roll)·cos(pitch).
pub(crate) fn banked(road: &Road, s: f64, t: f64, curvature: f64) -> (f64, f64, f64, f64) {
    if road.superelevation.is_empty() {
        return (t, 0.0, 0.0, 0.0);
    }
    let (roll, rate) = roll_at(road, s);
    let (sin, cos) = roll.sin_cos();
    let (sin_p, cos_p) = (-road.elevation_slope_at(s).atan()).sin_cos();
    let th = t * cos;
    let dth = -t * sin * rate;
    let turn = if dth == 0.0 { 0.0 } else { dth.atan2(1.0 - curvature * th) };
    (th, t * sin * cos_p, turn, t * sin * sin_p)
}

/// The shift along the heading of a point `across` m horizontally from the reference line at
/// `s` ([`banked`]'s last part, from the horizontal distance): what esmini's
/// Position::XYZ2TrackPos takes off a world point on a road both rolled and sloped (more than
/// SMALL_NUMBER each) before it projects it on a straight piece of the reference line.
pub(crate) fn along_shift(road: &Road, s: f64, across: f64) -> f64 {
    if road.superelevation.is_empty() {
        return 0.0;
    }
    let roll = roll_at(road, s).0;
    let pitch = -road.elevation_slope_at(s).atan();
    if roll.abs() <= crate::dynamics::ESMINI_SMALL_NUMBER || pitch.abs() <= crate::dynamics::ESMINI_SMALL_NUMBER {
        return 0.0;
    }
    across * roll.tan() * pitch.sin()
}

/// cos(AVOID_ZERO(0)) = cos(1e-6) = 1 − 5e-13: `Position::XYZ2TrackPos` divides the lateral
/// distance of a world point by cos(AVOID_ZERO(roll)), so on a road without banking too a point
/// given in the world lands a few 1e-13 m further from the reference line than it is; moved
/// along its lane it keeps that t, so an entity placed by a WorldPosition on a lane centre
/// drives on a hair outside it. Only a tie notices (a follower exactly in line with its lead
/// decides which way to turn by the sign of that hair).
const FLAT_ROAD_COS: f64 = 0.999_999_999_999_5;

/// The inverse of [`banked`]'s lateral part, as esmini's `Position::XYZ2TrackPos` does it: a
/// world point's horizontal distance `th` from the reference line at `s` is divided by
/// cos(roll) ("compensate for banking"), so its t is measured along the tilted surface.
pub(crate) fn surface_t(road: &Road, s: f64, th: f64) -> f64 {
    if road.superelevation.is_empty() {
        // The roll is 0, which esmini's AVOID_ZERO turns into SMALL_NUMBER: the distance
        // grows by 1/cos(1e-6), about 5e-13 of itself (see `FLAT_ROAD_COS`).
        return th / FLAT_ROAD_COS;
    }
    let cos = crate::dynamics::esmini_avoid_zero(roll_at(road, s).0).cos();
    // A road rolled to the vertical has no horizontal extent: keep the distance as it is.
    if cos.abs() < 1e-9 {
        th
    } else {
        th / cos
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_roads_cosine_is_that_of_esminis_small_number() {
        assert_eq!(FLAT_ROAD_COS, crate::dynamics::ESMINI_SMALL_NUMBER.cos());
        assert_eq!(crate::dynamics::esmini_avoid_zero(0.0), crate::dynamics::ESMINI_SMALL_NUMBER);
        assert_eq!(crate::dynamics::esmini_avoid_zero(-1e-9), -crate::dynamics::ESMINI_SMALL_NUMBER);
        assert_eq!(crate::dynamics::esmini_avoid_zero(0.2), 0.2);
    }
}
