//! What esmini's LoomingController looks at to steer (ControllerLooming::Step): the near
//! point (the lane centre 10 m ahead) and the far point (the tangent point of the lane's inner
//! edge within 80 m, found on the lane's OSI points). The OSI points are esmini's
//! (OpenDrive::SetLaneOSIPoints / CheckAndAddOSIPoint / CheckLaneOSIRequirement): points of
//! the lane centre, a new one wherever the tangent lines at the last point and the candidate
//! meet more than 5 cm off the chord, at most 50 m apart, closer where the elevation curves
//! and cut where it breaks (`opendrive::road_osi_points`; superelevation is not modelled).

use crate::angles::{angle_difference, angle_pi};
use crate::roads::LanePos;
use opendrive::{ContactPoint, ElementType, Road, RoadNetwork};
use std::collections::HashMap;

use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;

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

/// OpenDrive::SetLaneOSIPoints for one lane of one lane section (`opendrive::road_osi_points`).
pub(crate) fn lane_osi_points(net: &RoadNetwork, road_idx: usize, j: usize, lane_id: i32) -> Vec<OsiPoint> {
    let Some(road) = net.roads.get(road_idx) else { return Vec::new() };
    let Some(lsec) = road.lane_sections.get(j) else { return Vec::new() };
    let s_end = section_end(road, j);
    let xy = |s: f64| centre(net, road_idx, lane_id, s).map(|p| (p.x, p.y));
    opendrive::road_osi_points(road, lsec.s, s_end, xy).into_iter().filter_map(|s| centre(net, road_idx, lane_id, s)).collect()
}

/// Where esmini's position, attached to the road by Position::XYZ2TrackPos, is at or past the
/// end of its road: XYZ2TrackPos takes the s of the closest OSI point of the reference line
/// when the point lies beyond the last one (the "same point" case), and the last OSI point of
/// a lane section lies `SMALL_NUMBER / 2` short of its end (OpenDrive::SetLaneOSIPoints). So
/// the far-tangent search, which looks only at OSI points strictly ahead of the entity's s,
/// skips a lane's last point there. (A position stopped at the end by Position::MoveAlongS
/// has the road's length as its s.)
pub(crate) fn at_last_osi_point(net: &RoadNetwork, lp: LanePos) -> LanePos {
    let last = net.roads.get(lp.road).map_or(f64::INFINITY, |r| r.length - SMALL_NUMBER / 2.0);
    if lp.s > last {
        LanePos { s: last, ..lp }
    } else {
        lp
    }
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

/// Where the looming driver stands: its lane position, (x, y), its road heading and whether it
/// faces along the road.
pub(crate) struct Viewpoint {
    pub(crate) lane: LanePos,
    pub(crate) x: f64,
    pub(crate) y: f64,
    pub(crate) h_road: f64,
    pub(crate) forward: bool,
}

/// The tangent-point search of ControllerLooming::Step, up to `far_dist` ahead of `view`.
pub(crate) fn far_tangent(net: &RoadNetwork, memo: &mut OsiMemo, view: Viewpoint, far_dist: f64) -> FarTangent {
    let Viewpoint { lane: me, x, y, h_road, forward } = view;
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
                    let width = crate::roads::pose_memo::lane_borders_at(road, me.lane_id, p.s).map_or(0.0, |b| b.width());
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
