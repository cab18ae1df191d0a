//! The map round trip's measure: a lanelet network against the network a reader made of its
//! export. Each original lanelet is matched to the read-back lanelets that lie along it in
//! the same driving direction (one, or a chain where a reader cut it into lane sections);
//! its bound error is the largest distance from a point of its bounds (sampled every 0.1 m)
//! to the matched lanelets' bounds. Successors, predecessors and adjacency count as kept
//! when some matched pieces carry the same relation. The drivable area added is the area
//! of the read-back lanelets outside every original one (scanlines every 5 cm, exact along
//! each line).

use crate::vec2::{one_sided_distance, samples, SegmentIndex, V2};
use commonroad::{Lanelet, LaneletId, LaneletNetwork};
use std::collections::BTreeMap;

/// How far a read-back lanelet may lie from an original one and still be one of its pieces (m).
const PIECE: f64 = 1.0;
/// Scanline spacing of the area measure (m).
const ROW: f64 = 0.05;
/// Bound sample spacing (m).
const STEP: f64 = 0.1;
/// Bound errors are measured up to this (m); larger ones are reported as this.
pub const ERROR_CAP: f64 = 10.0;

/// One original lanelet's result.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneletResult {
    pub id: u64,
    /// Ids of the matched read-back lanelets.
    pub matched: Vec<u64>,
    /// Largest distance of its bounds from the matched bounds (infinite without a match).
    pub bound_error: f64,
    /// Where on its bounds the error is largest.
    pub worst_at: Option<(f64, f64)>,
    /// Relations not found between the matched lanelets, e.g. `successor 12`.
    pub lost: Vec<String>,
}

/// The comparison of two networks.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    pub lanelets: Vec<LaneletResult>,
    /// Relations of the original (successors, predecessors, adjacencies) and how many were kept.
    pub relations: usize,
    pub relations_kept: usize,
    /// Drivable area of the original and what the read-back network adds outside it (m²).
    pub area: f64,
    pub area_added: f64,
}

impl Comparison {
    /// Largest bound error over all lanelets (0 for an empty network).
    pub fn worst_bound_error(&self) -> f64 {
        self.lanelets.iter().map(|l| l.bound_error).fold(0.0, f64::max)
    }
    /// The added area as a fraction of the original.
    pub fn added_fraction(&self) -> f64 {
        if self.area > 0.0 {
            self.area_added / self.area
        } else {
            0.0
        }
    }
    /// Whether every lanelet is within `tol`, every relation kept and at most `max_added`
    /// (a fraction) of area added.
    pub fn passes(&self, tol: f64, max_added: f64) -> bool {
        self.lanelets.iter().all(|l| l.bound_error <= tol) && self.relations_kept == self.relations && self.added_fraction() <= max_added
    }
    /// The lanelets that fail `tol` or lost a relation, as lines of text.
    pub fn failures(&self, tol: f64) -> Vec<String> {
        self.lanelets
            .iter()
            .filter(|l| l.bound_error > tol || !l.lost.is_empty())
            .map(|l| {
                let err = if l.bound_error.is_finite() { format!("{:.4} m", l.bound_error) } else { "no match".into() };
                let at = l.worst_at.map(|(x, y)| format!(" at ({x:.2}, {y:.2})")).unwrap_or_default();
                format!("lanelet {}: bound error {err}{at}{}", l.id, if l.lost.is_empty() { String::new() } else { format!(", lost {}", l.lost.join(", ")) })
            })
            .collect()
    }
}

struct Shape {
    left: Vec<V2>,
    right: Vec<V2>,
    min: V2,
    max: V2,
}

fn shape(l: &Lanelet) -> Shape {
    let left: Vec<V2> = l.bounds.left().iter().map(V2::of).collect();
    let right: Vec<V2> = l.bounds.right().iter().map(V2::of).collect();
    let (mut min, mut max) = (V2::new(f64::INFINITY, f64::INFINITY), V2::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
    for p in left.iter().chain(&right) {
        min = V2::new(min.x.min(p.x), min.y.min(p.y));
        max = V2::new(max.x.max(p.x), max.y.max(p.y));
    }
    Shape { left, right, min, max }
}

fn overlaps(a: &Shape, b: &Shape, margin: f64) -> bool {
    a.min.x <= b.max.x + margin && b.min.x <= a.max.x + margin && a.min.y <= b.max.y + margin && b.min.y <= a.max.y + margin
}

/// Whether `piece` runs the same way as `line` where it lies: its middle segment against
/// the nearest segment of `line` (closed loops have no start-to-end direction).
fn same_way(piece: &[V2], line: &[V2]) -> bool {
    let k = piece.len() / 2;
    let (Some(&a), Some(&b)) = (piece.get(k.saturating_sub(1)), piece.get(k.max(1))) else { return false };
    let mid = a.lerp(b, 0.5);
    let nearest = line.windows(2).min_by(|x, y| crate::vec2::to_segment(mid, x[0], x[1]).0.total_cmp(&crate::vec2::to_segment(mid, y[0], y[1]).0));
    nearest.is_some_and(|w| w[1].sub(w[0]).dot(b.sub(a)) > 0.0)
}

/// Compares `original` with `back` (what a reader made of the export).
pub fn compare(original: &LaneletNetwork, back: &LaneletNetwork) -> Comparison {
    let orig: Vec<Shape> = original.lanelets.iter().map(shape).collect();
    let read: Vec<Shape> = back.lanelets.iter().map(shape).collect();
    // pieces of each original lanelet (indices into back)
    let mut pieces: Vec<Vec<usize>> = Vec::with_capacity(orig.len());
    for o in &orig {
        let mut m = Vec::new();
        for (j, b) in read.iter().enumerate() {
            if !overlaps(o, b, PIECE) {
                continue;
            }
            if one_sided_distance(&b.left, &o.left, 1.0, 2.0 * PIECE) <= PIECE
                && one_sided_distance(&b.right, &o.right, 1.0, 2.0 * PIECE) <= PIECE
                && (same_way(&b.left, &o.left) || same_way(&b.right, &o.right))
            {
                m.push(j);
            }
        }
        pieces.push(m);
    }
    let back_pos: BTreeMap<u64, usize> = back.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let orig_pos: BTreeMap<u64, usize> = original.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let mut results = Vec::with_capacity(orig.len());
    let (mut relations, mut kept) = (0, 0);
    for (i, (l, o)) in original.lanelets.iter().zip(&orig).enumerate() {
        let m = &pieces[i];
        let mut worst_at: Option<V2> = None;
        let err = if m.is_empty() {
            f64::INFINITY
        } else {
            let side = |pts: &[V2], pick: fn(&Shape) -> &Vec<V2>| {
                let index = SegmentIndex::new(m.iter().filter_map(|&j| read.get(j)).map(|b| pick(b).as_slice()), 2.0);
                samples(pts, STEP).into_iter().map(|p| (index.distance(p, ERROR_CAP), p)).fold((0.0, None), |a, (d, p)| if d > a.0 { (d, Some(p)) } else { a })
            };
            let (l, r) = (side(&o.left, |s| &s.left), side(&o.right, |s| &s.right));
            worst_at = if l.0 >= r.0 { l.1 } else { r.1 };
            l.0.max(r.0)
        };
        // relations
        let pieces_of = |id: u64| orig_pos.get(&id).and_then(|&k| pieces.get(k)).cloned().unwrap_or_default();
        let has = |target: u64, rel: &dyn Fn(&Lanelet) -> Vec<u64>| {
            let theirs = pieces_of(target);
            m.iter().filter_map(|&j| back.lanelets.get(j)).any(|b| rel(b).iter().any(|x| back_pos.get(x).is_some_and(|k| theirs.contains(k))))
        };
        let mut lost = Vec::new();
        type Links = fn(&Lanelet) -> &Vec<LaneletId>;
        let links: [(&str, Links); 2] = [("successor", |b| &b.successors), ("predecessor", |b| &b.predecessors)];
        for (name, list) in links {
            for s in list(l) {
                relations += 1;
                if has(s.get(), &|b| list(b).iter().map(|x| x.get()).collect()) {
                    kept += 1;
                } else {
                    lost.push(format!("{name} {}", s.get()));
                }
            }
        }
        for (name, adj) in [("adjacent left", l.adjacent_left), ("adjacent right", l.adjacent_right)] {
            let Some(a) = adj else { continue };
            relations += 1;
            let left = name == "adjacent left";
            let rel = move |b: &Lanelet| {
                let x = if left { b.adjacent_left } else { b.adjacent_right };
                x.filter(|x| x.driving_dir == a.driving_dir).map(|x| vec![x.lanelet.get()]).unwrap_or_default()
            };
            if has(a.lanelet.get(), &rel) {
                kept += 1;
            } else {
                lost.push(format!("{name} {}", a.lanelet.get()));
            }
        }
        let matched = m.iter().filter_map(|&j| back.lanelets.get(j)).map(|b| b.id.get()).collect();
        results.push(LaneletResult { id: l.id.get(), matched, bound_error: err, worst_at: worst_at.map(|p| (p.x, p.y)), lost });
    }
    let (area, area_added) = areas(&orig, &read);
    Comparison { lanelets: results, relations, relations_kept: kept, area, area_added }
}

/// Per scanline, the x intervals covered by the shapes (even–odd rule per shape), merged.
fn rows(shapes: &[Shape], y0: f64, n_rows: usize) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new(); n_rows];
    for sh in shapes {
        let ring: Vec<V2> = sh.left.iter().chain(sh.right.iter().rev()).copied().collect();
        let mut hits: Vec<(usize, f64)> = Vec::new();
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            let (lo, hi) = if a.y <= b.y { (a, b) } else { (b, a) };
            if hi.y <= lo.y {
                continue;
            }
            let first = ((lo.y - y0) / ROW - 0.5).ceil().max(0.0) as usize;
            let mut r = first;
            while r < n_rows {
                let y = y0 + (r as f64 + 0.5) * ROW;
                if y >= hi.y {
                    break;
                }
                if y >= lo.y {
                    hits.push((r, lo.x + (hi.x - lo.x) * (y - lo.y) / (hi.y - lo.y)));
                }
                r += 1;
            }
        }
        hits.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
        for pair in hits.chunk_by(|a, b| a.0 == b.0) {
            for c in pair.chunks(2) {
                if let [a, b] = c {
                    if let Some(row) = out.get_mut(a.0) {
                        row.push((a.1, b.1));
                    }
                }
            }
        }
    }
    for row in &mut out {
        row.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut merged: Vec<(f64, f64)> = Vec::with_capacity(row.len());
        for &(a, b) in row.iter() {
            match merged.last_mut() {
                Some(last) if a <= last.1 => last.1 = last.1.max(b),
                _ => merged.push((a, b)),
            }
        }
        *row = merged;
    }
    out
}

/// Length of `a` minus `b` (both merged interval lists).
fn minus_len(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let mut total = 0.0;
    for &(x0, x1) in a {
        let mut covered = 0.0;
        for &(y0, y1) in b {
            let (lo, hi) = (x0.max(y0), x1.min(y1));
            if hi > lo {
                covered += hi - lo;
            }
        }
        total += (x1 - x0) - covered;
    }
    total
}

fn areas(orig: &[Shape], read: &[Shape]) -> (f64, f64) {
    let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in orig.iter().chain(read) {
        y0 = y0.min(s.min.y);
        y1 = y1.max(s.max.y);
    }
    if y1.is_nan() || y0.is_nan() || y1 <= y0 {
        return (0.0, 0.0);
    }
    let n_rows = (((y1 - y0) / ROW).ceil() as usize).min(2_000_000);
    let (ro, rb) = (rows(orig, y0, n_rows), rows(read, y0, n_rows));
    let area: f64 = ro.iter().flatten().map(|(a, b)| b - a).sum::<f64>() * ROW;
    let added: f64 = rb.iter().zip(&ro).map(|(b, o)| minus_len(b, o)).sum::<f64>() * ROW;
    (area, added)
}
