//! esmini's choice of the reference-line segment a world point is placed on
//! (`Position::XYZ2TrackPos`, RoadManager.cpp), for one road. esmini walks the OSI points of
//! lane 0 and weighs each segment by the point's distance from it beyond the road's width,
//! adds |z_input − z of the segment| when that exceeds 2 m (a WorldPosition without z asks
//! at z = 0) and 3 m when the point lies outside the sector between the segment's end normals;
//! the s then comes from the segment's closest vertex and its neighbour on the point's side:
//! on a straight piece the unsigned distance from the first vertex (a point behind it is
//! mirrored), on a curved one the angle between the normals. Where the road climbs more than
//! 2 m, the z penalty can pick a segment far from the exact projection (a road going up and
//! down again: the descending half), which this reproduces.

use crate::angles::angle_difference;
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
use opendrive::model::road::Road;
use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::FRAC_PI_2;
use std::sync::Arc;

/// XYZ2TrackPos: the penalty of a segment whose sector does not hold the point.
const OUTSIDE_PENALTY: f64 = 3.0;

/// One OSI point of lane 0 (PointStruct): s, position, elevation and heading; `geometry_h` is
/// the heading as esmini's PointStruct holds it (see `geometry_heading`).
#[derive(Clone, Copy)]
struct Vertex {
    s: f64,
    x: f64,
    y: f64,
    z: f64,
    h: f64,
    geometry_h: f64,
}

fn lane0(road: &Road, s: f64) -> Vertex {
    let (x, y, h) = road.lane0_at(s);
    Vertex { s, x, y, z: road.elevation_at(s), h, geometry_h: geometry_heading(road, s, h) }
}

/// The heading esmini's Geometry::EvaluateDS gives at `s` (`h` ours there): the geometry's start
/// heading taken into [0, 2π) (Geometry::GetHdg) plus the turn along it. It matters where
/// XYZ2TrackPos compares two vertices' headings to call a segment straight: a straight road
/// whose pieces point a hair either side of 0 (hdg 8e-10, then −8e-10 read as 2π − 8e-10) is
/// taken for a curve there, and its normals, being parallel, give no intersection.
fn geometry_heading(road: &Road, s: f64, h: f64) -> f64 {
    match road.geometries.get(road.geometry_index_at(s.clamp(0.0, road.length))) {
        Some(g) => h - g.hdg + crate::angles::wrap_2pi(g.hdg),
        None => h,
    }
}

/// Lane 0's OSI points over the road's lane sections (`Road::lane0_osi_s`, the duplicate
/// first point of each following section left out: OpenDrive::SetLaneOSIPoints) and what the
/// segment scan derives from each, computed once per road and run: a fresh placement
/// (`locate::fresh_point`) weighs every road near the point, and a jump's placement or a point
/// on a road whose laneOffset varies (`locate::on_chosen_segment`) asks again for the road it
/// found.
fn scan_of(road: &Road) -> Arc<Scan> {
    let key: VertexKey = (road as *const Road as usize, road.geometries.as_ptr() as usize, road.length.to_bits());
    if let Some(v) = VERTICES.with(|m| m.borrow().get(&key).cloned()) {
        return v;
    }
    let v = Arc::new(Scan::new(road));
    VERTICES.with(|m| m.borrow_mut().insert(key, v.clone()));
    v
}

/// The segment scan's view of lane 0's OSI points, per vertex: where the scan puts it (the
/// road's own end pose for the last), its elevation, its normal (the bisector of the segments
/// meeting there; the road's own at the ends), the cosine and sine of its heading and the
/// road's width right and left at its s. The same arithmetic as the scan did per segment.
struct Scan {
    pts: Vec<Vertex>,
    pos: Vec<(f64, f64)>,
    z: Vec<f64>,
    norm: Vec<(f64, f64)>,
    dir: Vec<(f64, f64)>,
    width: Vec<[f64; 2]>,
    /// Each segment's line (from vertex i to i + 1; the last vertex alone: none), as
    /// DistanceFromPointToLine2D takes it: the difference of its ends and its length.
    seg_line: Vec<Line>,
    /// Each vertex's normal line (the vertex to the vertex plus the normal), likewise.
    norm_line: Vec<Line>,
}

/// A line through a point as DistanceFromPointToLine2D measures from it: the difference of
/// its two defining points and their distance, computed once.
#[derive(Clone, Copy)]
struct Line {
    dx: f64,
    dy: f64,
    len: f64,
}

impl Line {
    fn through((ax, ay): (f64, f64), (bx, by): (f64, f64)) -> Line {
        let (dx, dy) = (bx - ax, by - ay);
        Line { dx, dy, len: dx.hypot(dy) }
    }

    /// DistanceFromPointToLine2D from (px, py) to this line through `a` (the distance to `a`
    /// itself for a degenerate line).
    fn distance(&self, px: f64, py: f64, (ax, ay): (f64, f64)) -> f64 {
        if self.len < 1e-300 {
            return (px - ax).hypot(py - ay);
        }
        ((px - ax) * self.dy - (py - ay) * self.dx).abs() / self.len
    }
}

impl Scan {
    fn new(road: &Road) -> Scan {
        let pts: Vec<Vertex> = road.lane0_osi_s().iter().map(|&s| lane0(road, s)).collect();
        let n = pts.len();
        let end = lane0(road, road.length);
        let pos: Vec<(f64, f64)> = (0..n).map(|i| if i + 1 == n { (end.x, end.y) } else { (pts[i].x, pts[i].y) }).collect();
        let z = (0..n).map(|i| if i + 1 == n { end.z } else { pts[i].z }).collect();
        let heading = |i: usize| if i + 1 < n { (pos[i + 1].1 - pos[i].1).atan2(pos[i + 1].0 - pos[i].0) } else { end.h };
        let norm: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                if i == 0 {
                    normal(pts[0].h)
                } else if i + 1 == n {
                    normal(end.h)
                } else {
                    normal(heading(i - 1) + 0.5 * angle_difference(heading(i), heading(i - 1)))
                }
            })
            .collect();
        let dir = pts.iter().map(|p| (p.h.cos(), p.h.sin())).collect();
        let width = pts.iter().map(|p| [width(road, p.s, false), width(road, p.s, true)]).collect();
        let seg_line = (0..n).map(|i| Line::through(pos[i], pos[(i + 1).min(n - 1)])).collect();
        let norm_line = (0..n).map(|i: usize| Line::through(pos[i], (pos[i].0 + norm[i].0, pos[i].1 + norm[i].1))).collect();
        Scan { pts, pos, z, norm, dir, width, seg_line, norm_line }
    }
}

/// (road address, geometry address, length bits): a road of the network a run borrows.
type VertexKey = (usize, usize, u64);
type VertexMemo = HashMap<VertexKey, Arc<Scan>>;

thread_local! {
    static VERTICES: RefCell<VertexMemo> = RefCell::new(HashMap::new());
}

/// One run's lane-0 OSI points (`crate::run_memos`: addresses are only stable while a
/// network is borrowed).
pub(crate) struct Store(VertexMemo);

impl Store {
    /// No entries.
    pub(crate) fn new() -> Store {
        Store(HashMap::new())
    }

    /// Exchange these entries with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        VERTICES.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.0));
    }
}

/// The road's width on the side of `sign` at s (Road::GetWidth with every lane type but
/// none): the outer border's distance from lane 0 of the outermost lane not of type none.
pub(crate) fn width(road: &Road, s: f64, left: bool) -> f64 {
    let section = road.section_index_at(s);
    let centre = road.lane_offset_at(s);
    let Some(sec) = road.lane_sections.get(section) else { return 0.0 };
    let lanes = if left { &sec.left } else { &sec.right };
    // side_border_iter goes outwards over the same lanes, in the same order.
    road.side_border_iter(section, left, s)
        .zip(lanes)
        .filter(|(_, lane)| lane.kind != opendrive::LaneType::None)
        .last()
        .map_or(0.0, |((_, b), _)| (b.outer - centre).abs())
}

/// IsPointWithinSectorBetweenTwoLines: whether p lies between the normal lines at a and b,
/// and its normalised place between them (negative or a distance when outside).
/// `la` and `lb` are the normal lines at a and b ([`Line::through`] a and a + na).
fn sector(p: (f64, f64), a: (f64, f64), na: (f64, f64), la: Line, b: (f64, f64), nb: (f64, f64), lb: Line) -> (bool, f64) {
    let cross = |(ux, uy): (f64, f64), (vx, vy): (f64, f64)| ux * vy - uy * vx;
    let d0 = cross((p.0 - a.0, p.1 - a.1), na);
    let d1 = cross((p.0 - b.0, p.1 - b.1), nb);
    let dist0 = la.distance(p.0, p.1, a);
    let dist1 = lb.distance(p.0, p.1, b);
    let s_norm = dist0 / SMALL_NUMBER.max(dist0 + dist1);
    if d0 > 0.0 && d1 < 0.0 {
        (true, s_norm)
    } else if d0 < 0.0 && d1 > 0.0 {
        (true, -s_norm)
    } else if dist0 < dist1 {
        (false, -dist0)
    } else {
        (false, dist1)
    }
}

fn normal(h: f64) -> (f64, f64) {
    let (sin, cos) = (h + FRAC_PI_2).sin_cos();
    (cos, sin)
}

/// Where XYZ2TrackPos puts (x, y) at height `z_input` on `road` alone: the s. `None` for a
/// road without OSI points.
pub(crate) fn segment_s(road: &Road, x: f64, y: f64, z_input: f64) -> Option<f64> {
    segment_choice(road, x, y, z_input).map(|(s, _)| s)
}

/// [`segment_s`] and the weighed distance of the segment chosen, by which XYZ2TrackPos
/// compares roads (the smallest wins, the first road in the file at a tie).
pub(crate) fn segment_choice(road: &Road, x: f64, y: f64, z_input: f64) -> Option<(f64, f64)> {
    let scan = scan_of(road);
    let pts = &scan.pts;
    let n = pts.len();
    if n < 2 {
        return None;
    }
    let mut best = f64::INFINITY;
    let mut chosen: Option<usize> = None;
    // The segments, and the last vertex alone (the scan's extra round).
    for (a, b) in (0..n - 1).map(|i| (i, i + 1)).chain(std::iter::once((n - 1, n - 1))) {
        let (pa, pb) = (scan.pos[a], scan.pos[b]);
        let (cos_h, sin_h) = scan.dir[a];
        let cp = cos_h * (y - pa.1) - sin_h * (x - pa.0);
        let w = scan.width[a][usize::from(cp > 0.0)];
        let (inside, s_norm) = sector((x, y), pa, scan.norm[a], scan.norm_line[a], pb, scan.norm[b], scan.norm_line[b]);
        let inside = inside && s_norm >= 0.0;
        // A segment outside weighs at least 3 m more than the larger of its two distances: one
        // that cannot get below the best so far is passed over (the same choice, cheaper).
        if !inside && best <= OUTSIDE_PENALTY {
            continue;
        }
        let mut dist = (scan.seg_line[a].distance(x, y, pa) - w).max(0.0);
        let zs = if inside { (1.0 - s_norm) * scan.z[a] + s_norm * scan.z[b] } else { scan.z[b] };
        let penalty = opendrive::projection::height_penalty(z_input - zs);
        if !inside {
            if (dist.max(s_norm.abs()) + penalty) + OUTSIDE_PENALTY >= best {
                continue;
            }
            dist = dist.hypot(s_norm);
        }
        let mut weighted = dist + penalty;
        if !inside {
            weighted += OUTSIDE_PENALTY;
        }
        if weighted < best {
            best = weighted;
            let d2 = |(px, py): (f64, f64)| (x - px).powi(2) + (y - py).powi(2);
            let k = if d2(pa) < d2(pb) { a } else { b };
            chosen = Some(k);
        }
    }
    let k = chosen?;
    Some((s_from_vertex(road, &scan, k, x, y), best))
}

/// [`segment_s`] for a point on the road whose exact projection is at `s_near`, without the
/// scan: XYZ2TrackPos's first round on the current road (a point within 5 m of where the
/// position was, among the ten OSI points around it) finds that point inside the segment
/// holding `s_near`.
pub(crate) fn segment_s_near(road: &Road, x: f64, y: f64, s_near: f64) -> Option<f64> {
    let scan = scan_of(road);
    let n = scan.pts.len();
    if n < 2 {
        return None;
    }
    // The point lies inside the segment holding its exact s, the one the scan weighs nearest
    // (the others are outside it and weigh 3 m more); its closer vertex decides.
    let i = scan.pts.partition_point(|p| p.s <= s_near).saturating_sub(1).min(n - 2);
    let d2 = |(px, py): (f64, f64)| (x - px).powi(2) + (y - py).powi(2);
    let k = if d2(scan.pos[i]) < d2(scan.pos[i + 1]) { i } else { i + 1 };
    Some(s_from_vertex(road, &scan, k, x, y))
}

/// The s XYZ2TrackPos interpolates for (x, y) from vertex `k`, the closest of the segment it
/// chose, and its neighbour on the point's side (by angle between their normals, or along their
/// line where the vertices' headings agree).
fn s_from_vertex(road: &Road, scan: &Scan, k: usize, x: f64, y: f64) -> f64 {
    let pts = &scan.pts;
    let n = pts.len();
    // The s from the closest vertex and its neighbour on the point's side.
    let c = pts[k];
    let (nx, ny) = normal(c.h);
    let cross = nx * (y - c.y) - ny * (x - c.x);
    let (first, second) = if cross < 0.0 { (k, (k + 1).min(n - 1)) } else { (k.saturating_sub(1), k) };
    let (f, g) = (pts[first], pts[second]);
    if first == second {
        f.s
    } else {
        let s_norm = if (f.geometry_h - g.geometry_h).abs() < 1e-5 {
            // ProjectPointOnLine2D, then the unsigned distance from the first vertex. On a
            // road both rolled and sloped the closest vertex's normal, projected on the ground,
            // is not square to the line: the point is first moved back along the heading by
            // the shift Track2XYZ gives a point that far across (`banking::banked`).
            let (bx, by) = {
                let (sin_h, cos_h) = c.h.sin_cos();
                let across = -(x - f.x) * sin_h + (y - f.y) * cos_h;
                let along = super::banking::along_shift(road, c.s, across);
                (x - along * cos_h, y - along * sin_h)
            };
            let (dx, dy) = (g.x - f.x, g.y - f.y);
            let len2 = dx * dx + dy * dy;
            let u = ((bx - f.x) * dx + (by - f.y) * dy) / len2;
            (u * dx).hypot(u * dy) / len2.sqrt()
        } else {
            let (n0, n1) = (normal(f.h), normal(g.h));
            // GetIntersectionOfTwoLineSegments of the two normal lines.
            let den = n0.0 * n1.1 - n0.1 * n1.0;
            if den.abs() < SMALL_NUMBER {
                // Parallel normals: GetIntersectionOfTwoLineSegments refuses and leaves the
                // intersection unset; esmini 3.6.0 then puts the point at the first vertex
                // (measured: every point along such a segment gets its first vertex's s).
                return f.s;
            }
            let tt = ((g.x - f.x) * n1.1 - (g.y - f.y) * n1.0) / den;
            let (ix, iy) = (f.x + tt * n0.0, f.y + tt * n0.1);
            let unit = |(ux, uy): (f64, f64)| {
                let l = ux.hypot(uy);
                (ux / l, uy / l)
            };
            let (m0, m1) = (unit((f.x - ix, f.y - iy)), unit((g.x - ix, g.y - iy)));
            let between = (m0.0 * m1.0 + m0.1 * m1.1).clamp(-1.0, 1.0).acos();
            let l = unit((ix - x, iy - y));
            let to_pos = (-m0.0 * l.0 - m0.1 * l.1).clamp(-1.0, 1.0).acos();
            if between.abs() < SMALL_NUMBER {
                0.0
            } else {
                to_pos / between
            }
        };
        // Coincident points or parallel normals (hostile input): the first vertex.
        let s_norm = if s_norm.is_finite() { s_norm } else { 0.0 };
        ((1.0 - s_norm) * f.s + s_norm * g.s).clamp(0.0, road.length)
    }
}
