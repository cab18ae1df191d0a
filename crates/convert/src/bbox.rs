//! From an OpenSCENARIO reference point to the centre of the entity's bounding box: CommonRoad
//! obstacle shapes are centred on the state position, OpenSCENARIO positions are the entity's
//! reference point (a vehicle's rear axle), and the box centre is given relative to it.

/// The world position of the box centre for an entity at reference point `(x, y)` with heading
/// `h`, whose box centre lies at `(cx, cy)` in the entity frame (x forward, y left).
pub fn box_center(x: f64, y: f64, h: f64, cx: f64, cy: f64) -> (f64, f64) {
    let (s, c) = h.sin_cos();
    (x + c * cx - s * cy, y + s * cx + c * cy)
}

/// The inverse of [`box_center`]: the reference point of an entity whose box centre is at
/// `(x, y)` with heading `h` (a CommonRoad position back to an OpenSCENARIO one).
pub fn reference_point(x: f64, y: f64, h: f64, cx: f64, cy: f64) -> (f64, f64) {
    let (s, c) = h.sin_cos();
    (x - (c * cx - s * cy), y - (s * cx + c * cy))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn offset_is_rotated_by_the_heading() {
        // heading east: centre 1.4 m ahead
        let (x, y) = box_center(10.0, 5.0, 0.0, 1.4, 0.0);
        assert!((x - 11.4).abs() < 1e-12 && (y - 5.0).abs() < 1e-12);
        // heading north: 1.4 m ahead is +y, 0.5 m left is −x
        let (x, y) = box_center(10.0, 5.0, FRAC_PI_2, 1.4, 0.5);
        assert!((x - 9.5).abs() < 1e-12, "{x}");
        assert!((y - 6.4).abs() < 1e-12, "{y}");
        // heading 45°: the offset (1, 0) moves by (√½, √½)
        let (x, y) = box_center(0.0, 0.0, FRAC_PI_2 / 2.0, 1.0, 0.0);
        assert!((x - 0.5f64.sqrt()).abs() < 1e-12 && (y - 0.5f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn reference_point_undoes_box_center() {
        for (h, cx, cy) in [(0.3, 1.4, 0.0), (-2.9, 2.1, -0.4), (FRAC_PI_2, 0.0, 0.7)] {
            let (x, y) = box_center(12.5, -3.0, h, cx, cy);
            let (rx, ry) = reference_point(x, y, h, cx, cy);
            assert!((rx - 12.5).abs() < 1e-12 && (ry + 3.0).abs() < 1e-12, "{h} {cx} {cy}: {rx} {ry}");
        }
    }
}
