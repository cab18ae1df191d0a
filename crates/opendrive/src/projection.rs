//! World → road: nearest (road, lane, s, t) of a point, via the spatial index and a Newton
//! projection onto the exact reference line.

use crate::geometry::CurvePose;
use crate::model::road::Road;
use crate::network::RoadNetwork;
use crate::road_geometry::LaneBorders;

/// Where a world point lies on the road network.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LanePosition {
    /// Index into [`RoadNetwork::roads`].
    pub road: usize,
    /// Lane section index at `s`.
    pub section: usize,
    pub lane_id: i32,
    pub s: f64,
    /// Lateral coordinate from the reference line (+ left).
    pub t: f64,
    /// t − t of the lane centre.
    pub offset: f64,
    /// 0 when the point is on a lane of this road, else its distance from the road's area.
    pub distance: f64,
    /// Heading of the reference line at s.
    pub heading: f64,
}

impl LanePosition {
    /// Whether the point lies on a lane of the road.
    pub fn is_on_road(&self) -> bool {
        self.distance == 0.0
    }
}

/// Along-track residual below which a projection counts as falling inside the road's s range.
const END_TOLERANCE: f64 = 1e-6;

/// Project (x, y) onto the reference line of `road` starting from `s_guess`.
/// Returns (s, t, along-track residual; non-zero only past the road's ends).
pub fn project_onto_road(road: &Road, x: f64, y: f64, s_guess: f64) -> (f64, f64, f64) {
    let (s, t, along, _) = project_with_heading(road, x, y, s_guess);
    (s, t, along)
}

/// [`project_onto_road`] and the reference heading at the s found.
fn project_with_heading(road: &Road, x: f64, y: f64, s_guess: f64) -> (f64, f64, f64, f64) {
    let mut s = s_guess.clamp(0.0, road.length);
    // The last pose evaluated, with the s it was evaluated at and its heading's sin/cos: when
    // the iteration ends on that very s (same bits), the final pose is that one, not recomputed.
    let mut last: Option<(u64, CurvePose, f64, f64)> = None;
    for _ in 0..40 {
        let p = road.reference_pose(s);
        let (sin, cos) = p.hdg.sin_cos();
        last = Some((s.to_bits(), p, sin, cos));
        let (dx, dy) = (x - p.x, y - p.y);
        let along = dx * cos + dy * sin;
        let lat = -dx * sin + dy * cos;
        // Newton on d(along)/ds = -(1 - κ t); damped when the point is near the centre of curvature.
        let denom = (1.0 - p.curvature * lat).max(0.2);
        let next = (s + along / denom).clamp(0.0, road.length);
        let done = (next - s).abs() < 1e-11;
        s = next;
        if done {
            break;
        }
    }
    let (p, sin, cos) = match last {
        Some((bits, p, sin, cos)) if bits == s.to_bits() => (p, sin, cos),
        _ => {
            let p = road.reference_pose(s);
            let (sin, cos) = p.hdg.sin_cos();
            (p, sin, cos)
        }
    };
    let (dx, dy) = (x - p.x, y - p.y);
    (s, -dx * sin + dy * cos, dx * cos + dy * sin, p.hdg)
}

/// Lane of `road` at (s, t): the lane whose borders contain t, or the outermost lane on
/// that side with the lateral distance beyond it. Zero-width lanes are never chosen when
/// another lane contains t.
fn lane_at(road: &Road, section: usize, s: f64, t: f64) -> Option<(i32, LaneBorders, f64)> {
    let first_left = t > road.lane_offset_at(s);
    // Scanned lazily, without collecting the borders: this runs for every located point.
    let first = scan_side(road, section, first_left, s, t);
    if let Some((id, b)) = first.containing {
        return Some((id, b, 0.0));
    }
    let second = scan_side(road, section, !first_left, s, t);
    if let Some((id, b)) = second.containing {
        return Some((id, b, 0.0));
    }
    // Outside: outermost non-degenerate lane on the side of t.
    let side = if first.outermost_wide.is_some() { first } else { second };
    let (id, b) = side.outermost_wide.or(side.outermost)?;
    let dist = (t - b.outer).abs().min((t - b.inner).abs());
    Some((id, b, dist))
}

/// What one side's lanes say about t (innermost first, stopping at the first containing lane).
#[derive(Clone, Copy)]
struct SideScan {
    containing: Option<(i32, LaneBorders)>,
    outermost_wide: Option<(i32, LaneBorders)>,
    outermost: Option<(i32, LaneBorders)>,
}

fn scan_side(road: &Road, section: usize, left: bool, s: f64, t: f64) -> SideScan {
    let mut out = SideScan { containing: None, outermost_wide: None, outermost: None };
    for (id, b) in road.side_border_iter(section, left, s) {
        out.outermost = Some((id, b));
        if b.width() > 0.0 {
            if b.contains(t) {
                out.containing = Some((id, b));
                break;
            }
            out.outermost_wide = Some((id, b));
        }
    }
    out
}

/// The lane position of a point at (s, horizontal t) of `road`, `along` its along-track
/// residual (non-zero only past the road's ends).
fn lane_position(road: usize, r: &Road, s: f64, t: f64, along: f64, heading: f64, surface_t: &dyn Fn(&Road, f64, f64) -> f64) -> Option<LanePosition> {
    let t = surface_t(r, s, t);
    let section = r.section_index_at(s);
    let (lane_id, borders, lateral) = lane_at(r, section, s, t)?;
    let off_end = if along.abs() > END_TOLERANCE { along.abs() } else { 0.0 };
    let distance = if off_end > 0.0 || lateral > 0.0 { off_end.hypot(lateral) } else { 0.0 };
    Some(LanePosition { road, section, lane_id, s, t, offset: t - borders.center(), distance, heading })
}

impl RoadNetwork {
    /// Locate (x, y) on road `road` starting the projection at `s_guess`.
    pub fn locate_on_road(&self, road: usize, x: f64, y: f64, s_guess: f64) -> Option<LanePosition> {
        self.locate_on_road_by(road, x, y, s_guess, &|_, _, t| t)
    }

    /// [`Self::locate_on_road`] with the horizontal lateral distance from the reference line
    /// turned into the road's t by `surface_t(road, s, horizontal t)` before the lane is chosen
    /// (a simulator that lays t along a banked road's tilted surface divides by cos(roll)).
    pub fn locate_on_road_by(&self, road: usize, x: f64, y: f64, s_guess: f64, surface_t: &dyn Fn(&Road, f64, f64) -> f64) -> Option<LanePosition> {
        let r = self.roads.get(road)?;
        let (s, t, along, heading) = project_with_heading(r, x, y, s_guess);
        lane_position(road, r, s, t, along, heading, surface_t)
    }

    /// (x, y) placed on road `road` at the given `s` (found by another rule than the exact
    /// projection): t is the signed distance from the reference line's tangent at s, and the
    /// point counts as within the road's s range.
    pub fn locate_at_s_by(&self, road: usize, x: f64, y: f64, s: f64, surface_t: &dyn Fn(&Road, f64, f64) -> f64) -> Option<LanePosition> {
        let r = self.roads.get(road)?;
        let s = s.clamp(0.0, r.length);
        let p = r.reference_pose(s);
        let (sin, cos) = p.hdg.sin_cos();
        let (dx, dy) = (x - p.x, y - p.y);
        lane_position(road, r, s, -dx * sin + dy * cos, 0.0, p.hdg, surface_t)
    }

    /// Best s guess per road from the candidate segments: (road, s, squared distance).
    fn road_candidates(&self, x: f64, y: f64, seg_ids: &[u32], out: &mut Vec<(usize, f64, f64)>) {
        for &i in seg_ids {
            let Some(sg) = self.index.segments.get(i as usize) else { continue };
            let (u, d2) = sg.project(x, y);
            let s = sg.s0 + u * (sg.s1 - sg.s0);
            match out.iter_mut().find(|c| c.0 == sg.road) {
                Some(c) if d2 < c.2 => *c = (sg.road, s, d2),
                Some(_) => {}
                None => out.push((sg.road, s, d2)),
            }
        }
    }

    /// The roads near (x, y) that [`Self::world_to_lane`] weighs, by index: those with a piece
    /// of reference line in the nearest ring of index cells that has any, or the ring after.
    pub fn roads_near(&self, x: f64, y: f64) -> Vec<usize> {
        let mut ids = Vec::new();
        self.near_segments(x, y, &mut ids);
        let mut roads: Vec<usize> = ids.iter().filter_map(|&i| self.index.segments.get(i as usize).map(|sg| sg.road)).collect();
        roads.sort_unstable();
        roads.dedup();
        roads
    }

    /// The index segments of the nearest ring of cells holding any, and of the ring after (a
    /// nearer segment may sit in a neighbouring cell).
    fn near_segments(&self, x: f64, y: f64, ids: &mut Vec<u32>) {
        let mut ring = self.index.first_ring(x, y);
        let mut found_at = None;
        loop {
            let more = self.index.ring(x, y, ring, ids);
            if found_at.is_none() && !ids.is_empty() {
                found_at = Some(ring);
            }
            if found_at.is_some_and(|f| ring > f) || !more {
                break;
            }
            ring += 1;
        }
    }

    /// Every lane (of any type) that contains (x, y), one per road, sorted by road index.
    pub fn lanes_containing(&self, x: f64, y: f64) -> Vec<LanePosition> {
        let mut ids = Vec::new();
        self.index.ring(x, y, 0, &mut ids);
        let mut cands = Vec::new();
        self.road_candidates(x, y, &ids, &mut cands);
        let mut out: Vec<LanePosition> = cands.iter().filter_map(|&(r, s, _)| self.locate_on_road(r, x, y, s)).filter(|p| p.is_on_road()).collect();
        out.sort_by_key(|p| p.road);
        out
    }

    /// Nearest lane of (x, y). A point on several roads (junctions) prefers `hint` (the road
    /// the caller was on), then, with a hint, the lane whose centre is nearest; without one
    /// (a position nobody was at: esmini's fresh Position has no current road) the road that
    /// comes first in the network (Position::XYZ2TrackPos walks the roads in order and
    /// replaces a road the point lies on only by one it is strictly nearer to). An off-road
    /// point gets the road whose lanes are nearest. `None` only for a network without roads.
    pub fn world_to_lane(&self, x: f64, y: f64, hint: Option<usize>) -> Option<LanePosition> {
        self.world_to_lane_by(x, y, hint, &|_, _, t| t)
    }

    /// [`Self::world_to_lane`] with lateral distances turned into t by `surface_t` (see
    /// [`Self::locate_on_road_by`]).
    pub fn world_to_lane_by(&self, x: f64, y: f64, hint: Option<usize>, surface_t: &dyn Fn(&Road, f64, f64) -> f64) -> Option<LanePosition> {
        self.world_to_lane_at_height(x, y, None, hint, surface_t)
    }

    /// [`Self::world_to_lane_by`] for a point asked at height `z` (esmini's
    /// Position::XYZ2TrackPos): a road whose reference line lies more than 2 m above or below
    /// `z` where the point projects counts that height difference as distance, so of two
    /// roads the point lies on (a bridge over a road) the one at the asked height wins. `None`:
    /// heights are not weighed.
    pub fn world_to_lane_at_height(
        &self,
        x: f64,
        y: f64,
        z: Option<f64>,
        hint: Option<usize>,
        surface_t: &dyn Fn(&Road, f64, f64) -> f64,
    ) -> Option<LanePosition> {
        self.world_to_lane_ranked(x, y, z, hint, surface_t, None)
    }

    /// [`Self::world_to_lane_at_height`] where roads containing the point alike are ranked by
    /// `rank` (lower first, then the network's order) after the hinted road, in place of the
    /// nearest lane centre (esmini's XYZ2TrackPos with a current road: a road directly
    /// connected to it replaces an equally close one, any other road only a farther one).
    pub fn world_to_lane_ranked(
        &self,
        x: f64,
        y: f64,
        z: Option<f64>,
        hint: Option<usize>,
        surface_t: &dyn Fn(&Road, f64, f64) -> f64,
        rank: Option<&dyn Fn(usize) -> u8>,
    ) -> Option<LanePosition> {
        let mut ids = Vec::new();
        self.near_segments(x, y, &mut ids);
        let mut cands = Vec::new();
        self.road_candidates(x, y, &ids, &mut cands);
        let mut best: Option<(LanePosition, f64)> = None;
        for &(r, s, _) in &cands {
            let Some(p) = self.locate_on_road_by(r, x, y, s, surface_t) else { continue };
            // XYZ2TrackPos adds a height difference above 2 m to a segment's distance.
            let weighed = p.distance + z.map_or(0.0, |z| self.roads.get(r).map_or(0.0, |road| height_penalty(z - road.elevation_at(p.s))));
            let better = match &best {
                None => true,
                Some((b, wb)) => {
                    // Among roads that contain the point alike: the hinted road first, then
                    // the caller's rank (esmini: roads directly connected to the current road),
                    // then the file's order; a caller with a hint and no rank still takes the
                    // nearest lane centre.
                    let centre = |q: &LanePosition| match rank {
                        Some(r) => f64::from(r(q.road)),
                        None if hint.is_some() => q.offset.abs(),
                        None => 0.0,
                    };
                    let key = |q: &LanePosition| (if Some(q.road) == hint { 0 } else { 1 }, centre(q), q.road);
                    let (kp, kb) = (key(&p), key(b));
                    if weighed == 0.0 && *wb == 0.0 {
                        kp < kb
                    } else {
                        weighed < *wb || (weighed == *wb && kp.2 < kb.2)
                    }
                }
            };
            if better {
                best = Some((p, weighed));
            }
        }
        best.map(|(p, _)| p)
    }
}

/// XYZ2TrackPos's weight of a height difference `dz` between the asked point and a road's
/// reference line: counted only beyond 2 m ("to avoid noise in co-planar distance
/// calculations"). The engine's segment choice (`track_pos`) weighs its segments by it too.
pub fn height_penalty(dz: f64) -> f64 {
    if dz.abs() > 2.0 {
        dz.abs()
    } else {
        0.0
    }
}
