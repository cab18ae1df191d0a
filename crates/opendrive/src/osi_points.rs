//! esmini's OSI points: the polyline esmini reports for a lane centre, a lane boundary or a
//! road-mark line (`OpenDrive::SetLaneOSIPoints`, `SetLaneBoundaryPoints`,
//! `CheckAndAddOSIPoint`, `CheckLaneOSIRequirement` in esmini 3.6.0's RoadManager.cpp). Walking
//! along s in steps of 1 m, a point is added where the tangent lines at the last point and the
//! candidate meet more than 5 cm off the chord, or where the segment would grow past 50 m; a
//! failing step is halved until it is shorter than 20 cm. The curve is any `s → (x, y)`: the
//! caller says which line of which lane it samples. `osi_points` is the flat-road rule;
//! `road_osi_points` adds esmini's shorter segments where the road's elevation curves and its
//! cut at a discontinuity of the elevation (`GetMaxSegmentLen`; superelevation is not modelled).

use crate::model::road::Road;

const SMALL_NUMBER: f64 = 1e-6;
/// RoadManager.cpp: OSI_POINT_CALC_STEPSIZE, OSI_TANGENT_LINE_TOLERANCE.
const CALC_STEP: f64 = 1.0;
const TANGENT_TOL: f64 = 0.01;
/// CommonMini.hpp: OSI_MAX_LONGITUDINAL_DISTANCE, OSI_MAX_LATERAL_DEVIATION.
const MAX_SEGMENT: f64 = 50.0;
const MAX_LATERAL_DEVIATION: f64 = 0.05;
const MIN_SEGMENT: f64 = 0.2;
/// A bound on the iterations for hostile input (esmini loops until the section end).
const MAX_ITERATIONS: usize = 1_000_000;

type Xy = (f64, f64);

/// The three points (s − 1 cm, s, s + 1 cm) whose tangent lines esmini compares.
fn triple(f: &impl Fn(f64) -> Option<Xy>, s: f64, s_end: f64) -> Option<[Xy; 3]> {
    Some([f((s - TANGENT_TOL).max(0.0))?, f(s)?, f((s + TANGENT_TOL).min(s_end))?])
}

fn project_distance(px: f64, py: f64, (x1, y1): Xy, (x2, y2): Xy) -> f64 {
    let (dx, dy) = (x2 - x1, y2 - y1);
    let len2 = dx * dx + dy * dy;
    if len2 < 1e-300 {
        return (px - x1).hypot(py - y1);
    }
    let t = ((px - x1) * dx + (py - y1) * dy) / len2;
    let (qx, qy) = (x1 + t * dx, y1 + t * dy);
    (px - qx).hypot(py - qy)
}

/// OpenDrive::CheckLaneOSIRequirement.
fn requirement(p0: &[Xy; 3], p1: &[Xy; 3]) -> bool {
    let (ax, ay) = (p0[2].0 - p0[0].0, p0[2].1 - p0[0].1);
    let (bx, by) = (p1[2].0 - p1[0].0, p1[2].1 - p1[0].1);
    let angle = (ax * by - ay * bx).atan2(ax * bx + ay * by).abs();
    if angle > 0.5 {
        return false;
    }
    // GetIntersectionOfTwoLineSegments (lines through the tolerance points)
    let (ax1, ay1, ax2, ay2) = (p0[0].0, p0[0].1, p0[2].0, p0[2].1);
    let (bx1, by1, bx2, by2) = (p1[0].0, p1[0].1, p1[2].0, p1[2].1);
    let den = (ax1 - ax2) * (by1 - by2) - (ay1 - ay2) * (bx1 - bx2);
    if den.abs() < SMALL_NUMBER {
        return project_distance(bx1, by1, p0[0], p0[2]) < 0.1;
    }
    let t = ((ax1 - bx1) * (by1 - by2) - (ay1 - by1) * (bx1 - bx2)) / den;
    let (ix, iy) = (ax1 + t * (ax2 - ax1), ay1 + t * (ay2 - ay1));
    let error = project_distance(ix, iy, p0[1], p1[1]);
    error < MAX_LATERAL_DEVIATION || error.is_nan()
}

/// The s values of esmini's OSI points of the curve `f` between `s_start` and `s_end` (a lane
/// section) on a flat road, the first at `s_start`. Empty if `f` has no point at `s_start`.
pub fn osi_points(s_start: f64, s_end: f64, f: impl Fn(f64) -> Option<Xy>) -> Vec<f64> {
    osi_points_limited(s_start, s_end, f, |_, _| Some(MAX_SEGMENT))
}

/// esmini's `GetMaxSegmentLen` for a curve on `road` from `pivot` to `cand` (s values): 50 m
/// shortened where the elevation curves; `None` at a discontinuity of the elevation (the
/// segment is then cut at its shortest).
pub fn road_segment_limit(road: &Road, pivot: f64, cand: f64) -> Option<f64> {
    let h = 1e-4;
    let slope = |s: f64| road.elevation_slope_at(s.clamp(0.0, road.length));
    let curvature = (slope(cand + h) - slope(cand - h)) / (2.0 * h);
    let limit = MIN_SEGMENT.max(MAX_SEGMENT.min(MAX_SEGMENT / (1.0 + 1.75e3 * curvature.abs())));
    let z = |s: f64| road.elevation_at(s.clamp(0.0, road.length));
    if (slope(cand) - slope(pivot)).abs() > 0.1 - SMALL_NUMBER || ((z(cand) - z(pivot)) - slope(pivot) * (cand - pivot)).abs() > 0.1 - SMALL_NUMBER {
        return None;
    }
    Some(limit)
}

/// esmini's OSI points of a curve on `road` (`osi_points` with `road_segment_limit`).
pub fn road_osi_points(road: &Road, s_start: f64, s_end: f64, f: impl Fn(f64) -> Option<Xy>) -> Vec<f64> {
    osi_points_limited(s_start, s_end, f, |p, c| road_segment_limit(road, p, c))
}

/// The OSI points with `limit(pivot, candidate)` the longest segment allowed (`None`: a
/// discontinuity, the shortest).
fn osi_points_limited(s_start: f64, s_end: f64, f: impl Fn(f64) -> Option<Xy>, limit: impl Fn(f64, f64) -> Option<f64>) -> Vec<f64> {
    if f(s_start).is_none() {
        return Vec::new();
    }
    let mut pivot = s_start;
    let mut points = vec![pivot];
    let Some(mut x0) = triple(&f, s_start, s_end) else { return points };
    let mut last_ok = pivot;
    let mut cand = pivot;
    let mut x_last_ok = x0;
    let mut insert = false;
    let mut step = CALC_STEP.min(s_end - s_start);
    for _ in 0..MAX_ITERATIONS {
        let s = (cand + step).min(s_end - SMALL_NUMBER / 2.0);
        let (Some(_), Some(x1)) = (f(s), triple(&f, s, s_end)) else { break };
        cand = s;
        // OpenDrive::CheckAndAddOSIPoint
        let mut req = requirement(&x0, &x1);
        let mut max_segment = MAX_SEGMENT;
        if req {
            match limit(pivot, cand) {
                Some(m) => max_segment = m,
                None => {
                    max_segment = MIN_SEGMENT;
                    req = false;
                }
            }
            if max_segment < cand - pivot - SMALL_NUMBER {
                req = false;
            }
        }
        if (req && cand + SMALL_NUMBER > s_end - SMALL_NUMBER) || step.abs() < MIN_SEGMENT + SMALL_NUMBER || (req && cand - pivot > max_segment - SMALL_NUMBER)
        {
            let last_s = points.last().copied().unwrap_or(f64::NEG_INFINITY);
            let p = if !req && step.abs() < MIN_SEGMENT + SMALL_NUMBER && last_ok > last_s + SMALL_NUMBER {
                last_ok
            } else {
                last_ok = cand;
                x_last_ok = x1;
                cand
            };
            points.push(p);
            insert = false;
            if p + SMALL_NUMBER > s_end - SMALL_NUMBER {
                break;
            }
            step = CALC_STEP.min(s_end - p).min(2.0 * (p - pivot)).abs();
            pivot = last_ok;
            x0 = x_last_ok;
            cand = pivot;
        } else if !req {
            insert = true;
            step = -step.abs() / 2.0;
        } else {
            step = if insert { step.abs() / 2.0 } else { CALC_STEP };
            last_ok = cand;
            x_last_ok = x1;
        }
    }
    points
}

impl Road {
    /// Where lane 0 (the reference line moved by the lane offset) is at `s`, and the
    /// reference line's heading there: (x, y, hdg).
    pub fn lane0_at(&self, s: f64) -> (f64, f64, f64) {
        let p = self.reference_pose(s);
        let t = self.lane_offset_at(s);
        let (sin, cos) = p.hdg.sin_cos();
        (p.x - t * sin, p.y + t * cos, p.hdg)
    }

    /// The s of lane 0's OSI points over the road's lane sections, the duplicate first point
    /// of each following section left out (esmini's OpenDrive::SetLaneOSIPoints for lane 0,
    /// which follows the lane offset); computed once per road and kept.
    pub fn lane0_osi_s(&self) -> &[f64] {
        self.lane0_osi.get_or_init(|| {
            let xy = |s: f64| {
                let (x, y, _) = self.lane0_at(s);
                Some((x, y))
            };
            let n = self.lane_sections.len();
            let mut out = Vec::new();
            for j in 0..n {
                let Some((a, b)) = self.section_range(j) else { continue };
                let mut pts = road_osi_points(self, a, b, xy);
                if j + 1 < n && pts.len() > 1 {
                    pts.pop();
                }
                out.extend(pts);
            }
            out
        })
    }
}
