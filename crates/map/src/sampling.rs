//! Adaptive s stations of a lane section: every border of every lane is sampled at the same
//! stations (so both bounds of a lanelet, and the bounds neighbours share, have equal point
//! counts and identical points), refined until every border polyline is within the tolerance
//! of the exact border at the checked parameters (quarter, half, three-quarter of each
//! segment). Geometry, lane-offset and width/border record starts are always stations, so no
//! kink of the exact curve falls inside a segment.

use crate::borders::{section_cut, SectionCut};
use opendrive::Road;

/// Segments shorter than this are not split further (m).
const MIN_SEGMENT: f64 = 0.01;
/// Recursion limit of the refinement.
const MAX_DEPTH: u32 = 24;
/// Stations per lane section at most (hostile geometry must not exhaust memory or time);
/// past it segments are no longer split.
/// The corpus' largest section needs a few hundred; a fuzzed cubic width of 5·s³ m asked for
/// 100,000 (56 MB of XML for six lanelets, 0.6 s), so the cap is 20,000 and reaching it warns.
pub const MAX_STATIONS: usize = 20_000;

/// A 2-D point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct P2 {
    pub x: f64,
    pub y: f64,
}

/// One station: s, the border t values and their world points (same indexing as
/// [`SectionCut::t`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Station {
    pub s: f64,
    pub cut: SectionCut,
    pub points: Vec<P2>,
}

/// The station at `s` of section `sec_idx`.
pub(crate) fn station(road: &Road, sec_idx: usize, s: f64) -> Station {
    let cut = section_cut(road, sec_idx, s);
    let p = road.reference_pose(s);
    let (sin, cos) = p.hdg.sin_cos();
    let points = cut.t.iter().map(|&t| P2 { x: p.x - t * sin, y: p.y + t * cos }).collect();
    Station { s, cut, points }
}

/// Seed stations: section ends and every record start inside the section.
fn seeds(road: &Road, sec_idx: usize, s0: f64, s1: f64) -> Vec<f64> {
    let mut v = vec![s0, s1];
    let inside = |s: f64| s > s0 && s < s1;
    v.extend(road.geometries.iter().map(|g| g.s).filter(|&s| inside(s)));
    v.extend(road.lane_offsets.iter().map(|r| r.s).filter(|&s| inside(s)));
    if let Some(sec) = road.lane_sections.get(sec_idx) {
        for lane in sec.left.iter().chain(&sec.right) {
            for r in lane.widths.iter().chain(&lane.borders) {
                let s = sec.s + r.s;
                if inside(s) {
                    v.push(s);
                }
            }
        }
    }
    v.sort_by(f64::total_cmp);
    // merge stations closer than the minimum segment
    let mut out: Vec<f64> = Vec::with_capacity(v.len());
    for s in v {
        match out.last() {
            Some(&last) if s - last < MIN_SEGMENT => {}
            _ => out.push(s),
        }
    }
    if let (Some(last), Some(&end)) = (out.last_mut(), Some(&s1)) {
        *last = end;
    }
    out
}

fn dist_to_segment(p: P2, a: P2, b: P2) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let len2 = dx * dx + dy * dy;
    let u = if len2 > 0.0 { (((p.x - a.x) * dx + (p.y - a.y) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let (cx, cy) = (a.x + u * dx, a.y + u * dy);
    ((p.x - cx).powi(2) + (p.y - cy).powi(2)).sqrt()
}

fn deviation(a: &Station, b: &Station, m: &Station) -> f64 {
    m.points.iter().zip(a.points.iter().zip(&b.points)).map(|(&p, (&pa, &pb))| dist_to_segment(p, pa, pb)).fold(0.0, f64::max)
}

struct Refiner<'a> {
    road: &'a Road,
    sec: usize,
    tol: f64,
}

/// Pieces to cut a segment into when its deviation is `ratio` times the tolerance. The
/// chord deviation of a smooth curve grows with the square of the segment length, so
/// ⌈√ratio / 0.9⌉ equal pieces should each land at ~80 % of the tolerance, where bisection
/// alone ends anywhere between 25 % and 100 % of it. Every piece is checked again, so a
/// wrong guess costs points, never accuracy. Over the 35 corpus maps at 5 mm: 167,508 bound
/// points instead of bisection's 197,592 (−15 %); a factor of 1.0 gave 209,016 (pieces just
/// over the tolerance get halved again), 0.8 gave 180,866.
fn pieces(ratio: f64) -> usize {
    // capped by MAX_STATIONS in `refine`; the clamp only keeps the cast sane
    (ratio.sqrt() / 0.9).ceil().clamp(2.0, 1e6) as usize
}

impl Refiner<'_> {
    fn at(&self, s: f64) -> Station {
        station(self.road, self.sec, s)
    }

    /// Appends the stations after `a` up to and including `b`; `m` is the station halfway.
    fn refine(&self, a: &Station, b: Station, m: Station, depth: u32, out: &mut Vec<Station>) {
        if depth < MAX_DEPTH && b.s - a.s > MIN_SEGMENT && out.len() < MAX_STATIONS {
            let q1 = self.at(a.s + 0.25 * (b.s - a.s));
            let q3 = self.at(a.s + 0.75 * (b.s - a.s));
            let dev = deviation(a, &b, &m).max(deviation(a, &b, &q1)).max(deviation(a, &b, &q3));
            if dev > self.tol {
                let n = pieces(dev / self.tol).min(((b.s - a.s) / MIN_SEGMENT).floor() as usize);
                if n <= 2 {
                    // halves: the quarter stations are their midpoints
                    self.refine(a, m, q1, depth + 1, out);
                    // the first half always ends by pushing its end, the midpoint
                    let Some(mid) = out.last().cloned() else { return };
                    self.refine(&mid, b, q3, depth + 1, out);
                } else {
                    let (s0, h) = (a.s, (b.s - a.s) / n as f64);
                    for i in 0..n {
                        if out.len() >= MAX_STATIONS {
                            // budget spent: close the segment without the remaining pieces
                            out.push(b);
                            return;
                        }
                        let start = out.last().cloned().unwrap_or_else(|| a.clone());
                        let end = if i + 1 == n { b.clone() } else { self.at(s0 + (i + 1) as f64 * h) };
                        let mid = self.at(0.5 * (start.s + end.s));
                        self.refine(&start, end, mid, depth + 1, out);
                    }
                }
                return;
            }
        }
        out.push(b);
    }
}

/// Stations of section `sec_idx` over `[s0, s1]`; empty for a section of (near) zero length.
pub(crate) fn sample_section(road: &Road, sec_idx: usize, tol: f64) -> Vec<Station> {
    let Some((s0, s1)) = road.section_range(sec_idx) else { return Vec::new() };
    // also catches NaN lengths
    if (s1 - s0).partial_cmp(&1e-6) != Some(std::cmp::Ordering::Greater) {
        return Vec::new();
    }
    let seeds = seeds(road, sec_idx, s0, s1);
    let r = Refiner { road, sec: sec_idx, tol: tol.max(1e-6) };
    let mut out = Vec::new();
    let Some(&first) = seeds.first() else { return out };
    out.push(station(road, sec_idx, first));
    for w in seeds.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (Some(sa), sb) = (out.last().cloned(), station(road, sec_idx, b)) else { continue };
        let m = station(road, sec_idx, 0.5 * (a + b));
        r.refine(&sa, sb, m, 0, &mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_to_segment() {
        let (a, b) = (P2 { x: 0.0, y: 0.0 }, P2 { x: 10.0, y: 0.0 });
        assert_eq!(dist_to_segment(P2 { x: 5.0, y: 2.0 }, a, b), 2.0);
        assert_eq!(dist_to_segment(P2 { x: 13.0, y: 4.0 }, a, b), 5.0);
        assert_eq!(dist_to_segment(P2 { x: 1.0, y: 1.0 }, a, a), 2f64.sqrt());
    }
}
