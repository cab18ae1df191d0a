//! What esmini's LoomingController looks at to steer (ControllerLooming::Step): the near
//! point (the lane centre 10 m ahead) and the far point (the tangent point of the lane's inner
//! edge within 80 m, found on the lane's OSI points). The OSI points are esmini's
//! (OpenDrive::SetLaneOSIPoints / CheckAndAddOSIPoint / CheckLaneOSIRequirement): points of
//! the lane centre, a new one wherever the tangent lines at the last point and the candidate
//! meet more than 5 cm off the chord, at most 50 m apart (flat roads).

use crate::roads::LanePos;
use opendrive::{ContactPoint, ElementType, Road, RoadNetwork};
use std::collections::HashMap;

const SMALL_NUMBER: f64 = 1e-6;
/// RoadManager.cpp: OSI_POINT_CALC_STEPSIZE, OSI_TANGENT_LINE_TOLERANCE.
const CALC_STEP: f64 = 1.0;
const TANGENT_TOL: f64 = 0.01;
/// CommonMini.hpp: OSI_MAX_LONGITUDINAL_DISTANCE, OSI_MAX_LATERAL_DEVIATION.
const MAX_SEGMENT: f64 = 50.0;
const MAX_LATERAL_DEVIATION: f64 = 0.05;
const MIN_SEGMENT: f64 = 0.2;

/// One OSI point of a lane centre: s, x, y, road heading.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OsiPoint {
    pub s: f64,
    pub x: f64,
    pub y: f64,
    pub h: f64,
}

/// OSI points by (road, lane section, lane), computed once.
pub(crate) type OsiMemo = HashMap<(usize, usize, i32), Vec<OsiPoint>>;

fn section_end(road: &Road, j: usize) -> f64 {
    road.lane_sections.get(j + 1).map_or(road.length, |n| n.s)
}

fn centre(net: &RoadNetwork, road: usize, lane_id: i32, s: f64) -> Option<OsiPoint> {
    let p = LanePos { road, lane_id, s, offset: 0.0, dir: 1.0 }.pose(net)?;
    Some(OsiPoint { s, x: p.x, y: p.y, h: p.road_heading })
}

/// The three points (s − 1 cm, s, s + 1 cm) whose tangent lines esmini compares.
fn triple(net: &RoadNetwork, road: usize, lane_id: i32, s: f64, s_end: f64) -> Option<[(f64, f64); 3]> {
    let a = centre(net, road, lane_id, (s - TANGENT_TOL).max(0.0))?;
    let b = centre(net, road, lane_id, s)?;
    let c = centre(net, road, lane_id, (s + TANGENT_TOL).min(s_end))?;
    Some([(a.x, a.y), (b.x, b.y), (c.x, c.y)])
}

fn project_distance(px: f64, py: f64, (x1, y1): (f64, f64), (x2, y2): (f64, f64)) -> f64 {
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
fn requirement(p0: &[(f64, f64); 3], p1: &[(f64, f64); 3]) -> bool {
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

/// OpenDrive::SetLaneOSIPoints for one lane of one lane section (flat roads: no elevation
/// limit on the segment length).
pub(crate) fn lane_osi_points(net: &RoadNetwork, road_idx: usize, j: usize, lane_id: i32) -> Vec<OsiPoint> {
    let Some(road) = net.roads.get(road_idx) else { return Vec::new() };
    let Some(lsec) = road.lane_sections.get(j) else { return Vec::new() };
    let s_end = section_end(road, j);
    let Some(mut pivot) = centre(net, road_idx, lane_id, lsec.s) else { return Vec::new() };
    let mut points = vec![pivot];
    let Some(mut x0) = triple(net, road_idx, lane_id, lsec.s, s_end) else { return points };
    let mut last_ok = pivot;
    let mut cand = pivot;
    let mut x_last_ok = x0;
    let mut insert = false;
    let mut step = CALC_STEP.min(s_end - lsec.s);
    // A bound on the iterations for hostile input (esmini loops until the section end).
    for _ in 0..1_000_000 {
        let s = (cand.s + step).min(s_end - SMALL_NUMBER / 2.0);
        let (Some(c), Some(x1)) = (centre(net, road_idx, lane_id, s), triple(net, road_idx, lane_id, s, s_end)) else { break };
        cand = c;
        // OpenDrive::CheckAndAddOSIPoint
        let mut req = requirement(&x0, &x1);
        if req && MAX_SEGMENT < cand.s - pivot.s - SMALL_NUMBER {
            req = false;
        }
        if (req && cand.s + SMALL_NUMBER > s_end - SMALL_NUMBER)
            || step.abs() < MIN_SEGMENT + SMALL_NUMBER
            || (req && cand.s - pivot.s > MAX_SEGMENT - SMALL_NUMBER)
        {
            let last_s = points.last().map_or(f64::NEG_INFINITY, |p| p.s);
            let p = if !req && step.abs() < MIN_SEGMENT + SMALL_NUMBER && last_ok.s > last_s + SMALL_NUMBER {
                last_ok
            } else {
                last_ok = cand;
                x_last_ok = x1;
                cand
            };
            points.push(p);
            insert = false;
            if p.s + SMALL_NUMBER > s_end - SMALL_NUMBER {
                break;
            }
            step = CALC_STEP.min(s_end - p.s).min(2.0 * (p.s - pivot.s)).abs();
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

pub(crate) fn angle_pi(a: f64) -> f64 {
    // GetAngleInIntervalMinusPIPlusPI
    let mut b = a % (2.0 * std::f64::consts::PI);
    if b < -std::f64::consts::PI {
        b += 2.0 * std::f64::consts::PI;
    } else if b > std::f64::consts::PI {
        b -= 2.0 * std::f64::consts::PI;
    }
    b
}

/// GetAngleDifference
pub(crate) fn angle_difference(a: f64, b: f64) -> f64 {
    angle_pi(a - b)
}

/// The far tangent point ControllerLooming::Step finds, if any: (x, y, its absolute angle seen
/// from the entity, its distance along the road), and whether the search stopped at a
/// junction, with the distance searched.
pub(crate) struct FarTangent {
    pub point: Option<(f64, f64, f64, f64)>,
    pub intersection: bool,
    pub dist: f64,
}

fn sign(x: f64) -> i32 {
    if x < 0.0 {
        -1
    } else {
        1
    }
}

/// The tangent-point search of ControllerLooming::Step. `me`: the entity's lane position,
/// (x, y), its road heading and whether it faces along the road.
#[allow(clippy::too_many_arguments)] // the inputs of esmini's search, each a different quantity
pub(crate) fn far_tangent(net: &RoadNetwork, memo: &mut OsiMemo, me: LanePos, x: f64, y: f64, h_road: f64, forward: bool, far_dist: f64) -> FarTangent {
    let mut out = FarTangent { point: None, intersection: false, dist: 0.0 };
    let Some(road0) = net.roads.get(me.road) else { return out };
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut counter = [0usize; 2];
    let mut angle_diff_prev = [0.0f64; 2];
    let mut far_prev = [(0.0f64, 0.0f64); 2];
    let mut far_s_prev = [0.0f64; 2];
    let mut far_angle_prev =
        if forward { [angle_pi(h_road + half_pi), angle_pi(h_road - half_pi)] } else { [angle_pi(h_road - half_pi), angle_pi(h_road + half_pi)] };
    let mut road_idx = me.road;
    let mut direction: i32 = if forward { 1 } else { -1 };
    let mut direction_prev = direction;
    let mut prev_links: Option<(Vec<i32>, Vec<i32>)> = None;
    let mut road_counter: i32 = -1;
    let mut dist = 0.0;
    let mut guard = 0;
    while out.point.is_none() && dist < far_dist && guard < 1000 {
        guard += 1;
        if road_counter != -1 {
            let Some(r) = net.roads.get(road_idx) else { break };
            let link = if direction == 1 { r.successor.as_ref() } else { r.predecessor.as_ref() };
            let Some(link) = link else { break };
            if link.element_type == ElementType::Junction {
                out.intersection = true;
                break;
            }
            let Some(next) = net.road_index(&link.element_id) else { break };
            road_idx = next;
            direction_prev = direction;
            let cp = link.contact_point;
            if (direction == 1 && cp == Some(ContactPoint::End)) || (direction == -1 && cp == Some(ContactPoint::Start)) {
                direction *= -1;
            }
        }
        road_counter += 1;
        let Some(road) = net.roads.get(road_idx) else { break };
        let n_sec = road.lane_sections.len();
        let mut dist_lsec = 0.0;
        let mut n = 0;
        while out.point.is_none() && dist + dist_lsec < far_dist && n < n_sec {
            let j = if direction == -1 { n_sec - 1 - n } else { n };
            n += 1;
            let Some(lsec) = road.lane_sections.get(j) else { return out };
            let lsec_len = section_end(road, j) - lsec.s;
            // the lane followed: the entity's, then the link of the previous one
            // (`lane->GetLink`, successor when the search went along +s)
            let next_lane = match &prev_links {
                None => Some(me.lane_id),
                Some((succ, pred)) => {
                    if direction_prev == 1 {
                        succ.first().copied()
                    } else {
                        pred.first().copied()
                    }
                }
            };
            let Some(lid) = next_lane else { return out };
            let Some(lane) = lsec.lane(lid) else { return out };
            prev_links = Some((lane.successors.clone(), lane.predecessors.clone()));
            let pts = memo.entry((road_idx, j, lid)).or_insert_with(|| lane_osi_points(net, road_idx, j, lid)).clone();
            let mut dist_left = -1.0;
            for m in 0..2 {
                let start = if road_counter == 0 { 0 } else { 1 };
                for k in start..pts.len() {
                    let idx = if direction == -1 { pts.len() - 1 - k } else { k };
                    let p = pts[idx];
                    let past = if road_counter == 0 {
                        (direction == 1 && p.s - me.s > far_dist) || (direction == -1 && me.s - p.s > far_dist)
                    } else {
                        (direction == 1 && dist + p.s > far_dist) || (direction == -1 && dist + dist_lsec - p.s > far_dist)
                    };
                    if past {
                        break;
                    }
                    if m == 1
                        && out.point.is_some()
                        && (if road_counter == 0 {
                            (direction == 1 && p.s > me.s + dist_left) || (direction == -1 && p.s < me.s - dist_left)
                        } else {
                            (direction == 1 && p.s > dist_left - dist) || (direction == -1 && lsec_len - p.s > dist_left - dist)
                        })
                    {
                        break;
                    }
                    let ahead = road_counter > 0 || (direction == 1 && p.s > me.s) || (direction == -1 && p.s < me.s);
                    if !ahead {
                        continue;
                    }
                    let width = crate::roads::pose_memo::lane_borders_at(road, me.lane_id, p.s).map_or(0.0, |(a, b)| (b - a).abs());
                    let mut ly = if m == 0 { 1.0 } else { -1.0 } * width / 2.0;
                    if direction != 1 {
                        ly = -ly;
                    }
                    let (sh, ch) = p.h.sin_cos();
                    let (fx, fy) = (p.x - ly * sh, p.y + ly * ch);
                    let mut fs = dist + if direction == 1 { p.s } else { dist_lsec - p.s };
                    if road_counter == 0 {
                        fs -= if direction == 1 { me.s } else { road0.length - me.s };
                    }
                    let fa = angle_pi((fy - y).atan2(fx - x));
                    let ad = angle_difference(fa, far_angle_prev[m]);
                    if counter[m] > 0 && ad.abs() > SMALL_NUMBER && sign(ad) != sign(angle_diff_prev[m]) {
                        out.point = Some((far_prev[m].0, far_prev[m].1, far_angle_prev[m], far_s_prev[m]));
                        if m == 0 {
                            dist_left = far_s_prev[m];
                        }
                        break;
                    }
                    far_prev[m] = (fx, fy);
                    far_s_prev[m] = fs;
                    far_angle_prev[m] = fa;
                    if ad.abs() > SMALL_NUMBER {
                        angle_diff_prev[m] = ad;
                    }
                    counter[m] += 1;
                }
            }
            dist_lsec += lsec_len;
        }
        dist += if road_counter == 0 {
            if direction == 1 {
                road0.length - me.s
            } else {
                me.s
            }
        } else {
            road.length
        };
    }
    out.dist = dist;
    out
}
