//! How fast a lane's centre moves sideways along the road: dt/ds of the centre of a lane, from
//! the slopes of the lane offset and of the widths (or borders) of the lanes between it and
//! the reference line. An entity that follows a widening or narrowing lane drifts sideways,
//! and esmini turns its heading along that drift: the heading of a lane follower is the
//! direction of its path, road heading + atan(dt/ds / (1 − κ·t)).

use opendrive::model::poly::piecewise_slope;
use opendrive::model::poly::record_at;
use opendrive::{Lane, Road};

/// dt/ds of the centre of lane `lane_id` in section `section` at road `s` (0 for the centre
/// lane and for a lane that does not exist).
pub(crate) fn lane_center_slope(road: &Road, section: usize, lane_id: i32, s: f64) -> f64 {
    let Some(sec) = road.lane_sections.get(section) else { return 0.0 };
    let base = piecewise_slope(&road.lane_offsets, s);
    if lane_id == 0 {
        return base;
    }
    let (lanes, sign): (&[Lane], f64) = if lane_id > 0 { (&sec.left, 1.0) } else { (&sec.right, -1.0) };
    let ds = s - sec.s;
    let mut inner = base;
    for lane in lanes {
        let outer = if !lane.widths.is_empty() {
            inner + sign * record_at(&lane.widths, ds).map_or(0.0, |r| r.slope(ds - r.s))
        } else if let Some(b) = record_at(&lane.borders, ds) {
            base + b.slope(ds - b.s)
        } else {
            inner
        };
        if lane.id == lane_id {
            return 0.5 * (inner + outer);
        }
        inner = outer;
    }
    0.0
}

/// The turn of a lane follower's heading away from the road direction: atan of the centre's
/// sideways slope over the lane's own length scale (1 − κ·t).
pub(crate) fn drift_angle(road: &Road, section: usize, lane_id: i32, s: f64, t: f64, curvature: f64) -> f64 {
    let slope = lane_center_slope(road, section, lane_id, s);
    if slope == 0.0 {
        return 0.0;
    }
    (slope / (1.0 - curvature * t).max(0.1)).atan()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lane −1 3 m wide; lane −2 widening from 0 to 4 m over s = 0 … 40 (slope 0.1).
    const ROAD: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="100"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="0" b="0.1" c="0" d="0"/><width sOffset="40" a="4" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;

    #[test]
    fn the_centre_of_a_widening_outer_lane_moves_out_at_half_the_widening_rate() {
        let net = opendrive::parse_str(ROAD, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"));
        let road = &net.roads[0];
        // Lane −1 keeps its width: its centre does not move.
        assert_eq!(lane_center_slope(road, 0, -1, 20.0), 0.0);
        // Lane −2's centre is at −3 − w/2, w' = 0.1: dt/ds = −0.05.
        assert!((lane_center_slope(road, 0, -2, 20.0) + 0.05).abs() < 1e-15);
        assert!((drift_angle(road, 0, -2, 20.0, -4.0, 0.0) - (-0.05f64).atan()).abs() < 1e-15);
        // Past s = 40 the width is constant again.
        assert_eq!(lane_center_slope(road, 0, -2, 60.0), 0.0);
    }
}
