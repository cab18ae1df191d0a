//! Which side of the reference line a lane id lies on as esmini counts it (its SIGN: the centre
//! lane, 0, on the positive side), and the lane difference Position::Delta reports from it.

/// esmini's SIGN of lane id `id`: −1 right of the reference line, +1 otherwise (lane 0 too).
pub(crate) fn side(id: i32) -> i32 {
    if id < 0 {
        -1
    } else {
        1
    }
}

/// Position::Delta's lane difference from lane `from` to lane `to`: `to − from`, one less in
/// size across the reference line (the centre lane is not counted).
pub(crate) fn lane_delta(from: i32, to: i32) -> i32 {
    let d = to - from;
    if side(from) != side(to) {
        (d.abs() - 1) * side(d)
    } else {
        d
    }
}
