//! The generator's tools: a seeded random source, reference paths integrated from a
//! curvature profile, roads of lanes drawn along a path (lane widths varying along it, pieces
//! cut on slanted or bowed cross-sections, points spaced irregularly with noise), lanelets
//! between two cross-sections along cubic Hermite curves, and the validity check every
//! generated network passes (what `cr_check.py` would accept).

use commonroad::*;

/// A plane point.
pub(crate) type P = (f64, f64);

/// splitmix64: the same seed gives the same networks on every machine (no dependency).
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed ^ 0x9e37_79b9_7f4a_7c15)
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in [a, b).
    pub(crate) fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in a..=b.
    pub(crate) fn int(&mut self, a: usize, b: usize) -> usize {
        a + (self.next() % (b - a + 1) as u64) as usize
    }
    pub(crate) fn chance(&mut self, p: f64) -> bool {
        self.range(0.0, 1.0) < p
    }
    /// -1 or +1.
    pub(crate) fn sign(&mut self) -> f64 {
        if self.chance(0.5) {
            1.0
        } else {
            -1.0
        }
    }
}

/// A reference path: poses every `STEP` m, integrated from piecewise linear curvature (lines,
/// arcs, clothoids and their sequences).
pub(crate) struct Path {
    poses: Vec<(f64, f64, f64)>,
}

const STEP: f64 = 0.05;

impl Path {
    /// From `(x, y, heading)` through segments `(length, curvature at start, curvature at end)`.
    pub(crate) fn new(start: (f64, f64, f64), segments: &[(f64, f64, f64)]) -> Self {
        let (mut x, mut y, mut h) = start;
        let mut poses = vec![(x, y, h)];
        for &(len, k0, k1) in segments {
            let n = (len / STEP).round().max(1.0) as usize;
            let ds = len / n as f64;
            for i in 0..n {
                let k = k0 + (k1 - k0) * (i as f64 + 0.5) / n as f64;
                let hm = h + 0.5 * k * ds;
                x += hm.cos() * ds;
                y += hm.sin() * ds;
                h += k * ds;
                poses.push((x, y, h));
            }
        }
        Self { poses }
    }
    pub(crate) fn len(&self) -> f64 {
        (self.poses.len() - 1) as f64 * STEP
    }
    /// The pose at `s` (interpolated; straight on beyond the ends).
    pub(crate) fn pose(&self, s: f64) -> (f64, f64, f64) {
        let last = self.poses.len() - 1;
        let i = ((s / STEP).floor().max(0.0) as usize).min(last.saturating_sub(1));
        let (a, b) = (self.poses[i], self.poses[(i + 1).min(last)]);
        let f = s / STEP - i as f64;
        let h = a.2 + (b.2 - a.2) * f.clamp(0.0, 1.0);
        let (bx, by) = (a.0 + (b.0 - a.0) * f.clamp(0.0, 1.0), a.1 + (b.1 - a.1) * f.clamp(0.0, 1.0));
        let extra = if f > 1.0 {
            (f - 1.0) * STEP
        } else if f < 0.0 {
            f * STEP
        } else {
            0.0
        };
        (bx + extra * h.cos(), by + extra * h.sin(), h)
    }
    /// The point `t` to the left of the path at `s`.
    pub(crate) fn at(&self, s: f64, t: f64) -> P {
        let (x, y, h) = self.pose(s);
        (x - h.sin() * t, y + h.cos() * t)
    }
}

fn smooth(u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

/// One lane of a road, right to left across the path.
#[derive(Clone)]
pub(crate) struct LaneSpec {
    /// Width at the road's start and end (smoothly between).
    pub w0: f64,
    pub w1: f64,
    /// Drives against the path.
    pub reversed: bool,
    /// The pieces (indices) where it exists: first..=last.
    pub first: usize,
    pub last: usize,
    /// Width grows from 0.3 m over this length after its first piece starts (a lane appearing).
    pub taper_in: Option<f64>,
    /// Width shrinks to 0.3 m over this length before its last piece ends.
    pub taper_out: Option<f64>,
}

impl LaneSpec {
    /// A lane of width `w` over the whole road.
    pub(crate) fn plain(w: f64, reversed: bool) -> Self {
        Self { w0: w, w1: w, reversed, first: 0, last: 0, taper_in: None, taper_out: None }
    }
}

/// How points are placed along a road.
#[derive(Clone, Copy)]
pub(crate) struct Style {
    /// Point spacing range (m).
    pub spacing: (f64, f64),
    /// Largest noise on a point (m).
    pub noise: f64,
    /// Chance that a point gets a nearly coincident twin.
    pub twins: f64,
}

/// A road: lanes along a path, cut into pieces at `cuts` (the first 0, the last the path's
/// length); each cut's cross-section is shifted along the path by `slant·t + bow·t²` (t from
/// the road's middle).
pub(crate) struct RoadSpec {
    pub path: Path,
    pub lanes: Vec<LaneSpec>,
    pub cuts: Vec<f64>,
    pub slant: Vec<(f64, f64)>,
    pub style: Style,
    /// Points replacing the computed ones of the first / last cross-section, per border
    /// (right to left), so that a road starts or ends exactly where another does.
    pub start_points: Option<Vec<P>>,
    pub end_points: Option<Vec<P>>,
    pub kind: LaneletType,
}

impl RoadSpec {
    /// A road of one piece `len` m along the path, its cross-sections square to it.
    pub(crate) fn whole(path: Path, len: f64, lanes: Vec<LaneSpec>, style: Style, kind: LaneletType) -> Self {
        Self { path, lanes, cuts: vec![0.0, len], slant: vec![], style, start_points: None, end_points: None, kind }
    }
}

/// A built road: lanelet ids per lane and piece, and its border points at the cuts.
pub(crate) struct Road {
    pub ids: Vec<Vec<Option<LaneletId>>>,
    pub reversed: Vec<bool>,
    /// Border points (right to left) of the last cross-section, and the heading there.
    pub end: Vec<P>,
    pub heading_end: f64,
}

impl Road {
    /// The lanelet of `lane` where the lane ends (`at_end`) or starts, in its driving direction.
    pub(crate) fn at(&self, lane: usize, at_end: bool) -> Option<LaneletId> {
        let row = self.ids.get(lane)?;
        if at_end != self.reversed.get(lane).copied().unwrap_or(false) {
            row.iter().rev().find_map(|x| *x)
        } else {
            row.iter().find_map(|x| *x)
        }
    }
}

/// A network under construction.
pub(crate) struct Net {
    pub ids: IdAllocator,
    pub net: LaneletNetwork,
}

impl Net {
    pub(crate) fn new() -> Self {
        Self { ids: IdAllocator::new(), net: LaneletNetwork::default() }
    }

    fn index(&self, id: LaneletId) -> Option<usize> {
        self.net.lanelets.iter().position(|l| l.id == id)
    }

    pub(crate) fn lanelet(&self, id: LaneletId) -> Option<&Lanelet> {
        self.index(id).map(|i| &self.net.lanelets[i])
    }

    /// A lanelet from its bounds (left and right in driving order); `None` when the bounds
    /// cannot be one.
    pub(crate) fn add(&mut self, left: Vec<P>, right: Vec<P>, kind: LaneletType) -> Option<LaneletId> {
        let pts = |v: Vec<P>| v.into_iter().map(|(x, y)| Point::new(x, y)).collect::<Vec<_>>();
        let bounds = LaneletBounds::new(pts(left), pts(right)).ok()?;
        let id = self.ids.lanelet();
        self.net.lanelets.push(Lanelet::new(id, bounds, kind));
        Some(id)
    }

    /// `b` follows `a`.
    pub(crate) fn link(&mut self, a: LaneletId, b: LaneletId) {
        if let Some(i) = self.index(a) {
            if !self.net.lanelets[i].successors.contains(&b) {
                self.net.lanelets[i].successors.push(b);
            }
        }
        if let Some(j) = self.index(b) {
            if !self.net.lanelets[j].predecessors.contains(&a) {
                self.net.lanelets[j].predecessors.push(a);
            }
        }
    }

    /// `l` lies on the left of `r` (r's left bound is l's left bound when `opposite`, else
    /// l's right bound).
    fn neighbours(&mut self, r: LaneletId, l: LaneletId, opposite: bool) {
        let dir = if opposite { DrivingDir::Opposite } else { DrivingDir::Same };
        if let Some(i) = self.index(r) {
            self.net.lanelets[i].adjacent_left = Some(Adjacent { lanelet: l, driving_dir: dir });
        }
        if let Some(j) = self.index(l) {
            let back = Some(Adjacent { lanelet: r, driving_dir: dir });
            if opposite {
                self.net.lanelets[j].adjacent_left = back;
            } else {
                self.net.lanelets[j].adjacent_right = back;
            }
        }
    }

    /// Builds a road (see [`RoadSpec`]).
    pub(crate) fn road(&mut self, rng: &mut Rng, spec: &RoadSpec) -> Road {
        let len = spec.path.len();
        let n = spec.lanes.len();
        let n_fwd = spec.lanes.iter().filter(|l| !l.reversed).count();
        let last_piece = spec.cuts.len() - 2;
        let width = |i: usize, s: f64| {
            let l = &spec.lanes[i];
            let mut w = l.w0 + (l.w1 - l.w0) * smooth(s / len);
            if let Some(t) = l.taper_in {
                w *= 0.3 / l.w0.max(0.3) + (1.0 - 0.3 / l.w0.max(0.3)) * smooth((s - spec.cuts[l.first]) / t);
            }
            if let Some(t) = l.taper_out {
                w *= 0.3 / l.w0.max(0.3) + (1.0 - 0.3 / l.w0.max(0.3)) * smooth((spec.cuts[l.last + 1] - s) / t);
            }
            w
        };
        let border = |b: usize, s: f64| -> f64 { (0..b).map(|i| width(i, s)).sum::<f64>() - (0..n_fwd).map(|i| width(i, s)).sum::<f64>() };
        let mid = |s: f64| 0.5 * (border(0, s) + border(n, s));
        // stations: irregular spacing, none too near a cut, cuts themselves
        let mut margin = 0.3;
        for (k, &c) in spec.cuts.iter().enumerate() {
            let half = 0.5 * (border(n, c) - border(0, c)).abs() + 0.5;
            let (sl, bw) = spec.slant.get(k).copied().unwrap_or((0.0, 0.0));
            margin = f64::max(margin, sl.abs() * half + bw.abs() * half * half + 0.2);
        }
        let mut stations: Vec<(f64, Option<usize>)> = Vec::new();
        let mut s = 0.0;
        while s < len {
            if spec.cuts.iter().all(|c| (s - c).abs() > margin) {
                stations.push((s, None));
                if rng.chance(spec.style.twins) {
                    stations.push((s + rng.range(1e-5, 1e-3), None));
                }
            }
            s += rng.range(spec.style.spacing.0, spec.style.spacing.1);
        }
        stations.extend(spec.cuts.iter().enumerate().map(|(k, &c)| (c, Some(k))));
        stations.sort_by(|a, b| a.0.total_cmp(&b.0));
        let cut_at: Vec<usize> = stations.iter().enumerate().filter(|(_, st)| st.1.is_some()).map(|(j, _)| j).collect();
        // border points
        let mut points: Vec<Vec<P>> = vec![Vec::with_capacity(stations.len()); n + 1];
        for (j, &(s, cut)) in stations.iter().enumerate() {
            for (b, row) in points.iter_mut().enumerate() {
                let t = border(b, s);
                let shift = cut.and_then(|k| spec.slant.get(k)).map_or(0.0, |&(sl, bw)| sl * (t - mid(s)) + bw * (t - mid(s)).powi(2));
                let se = s + shift;
                let mut p = spec.path.at(se, border(b, se));
                let fixed = match (j, &spec.start_points, &spec.end_points) {
                    (0, Some(sp), _) => sp.get(b).copied(),
                    (j, _, Some(ep)) if j + 1 == stations.len() => ep.get(b).copied(),
                    _ => None,
                };
                if let Some(f) = fixed {
                    p = f;
                } else if spec.style.noise > 0.0 {
                    p = (p.0 + rng.range(-1.0, 1.0) * spec.style.noise, p.1 + rng.range(-1.0, 1.0) * spec.style.noise);
                }
                row.push(p);
            }
        }
        let mut ids = vec![vec![None; last_piece + 1]; n];
        for (i, lane) in spec.lanes.iter().enumerate() {
            for k in lane.first..=lane.last.min(last_piece) {
                let (a, b) = (cut_at[k], cut_at[k + 1]);
                let (mut left, mut right) = (points[i + 1][a..=b].to_vec(), points[i][a..=b].to_vec());
                if lane.reversed {
                    (left, right) = (right, left);
                    left.reverse();
                    right.reverse();
                }
                ids[i][k] = self.add(left, right, spec.kind);
            }
            // successors along the lane
            for k in lane.first..lane.last.min(last_piece) {
                if let (Some(a), Some(b)) = (ids[i][k], ids[i][k + 1]) {
                    if lane.reversed {
                        self.link(b, a);
                    } else {
                        self.link(a, b);
                    }
                }
            }
        }
        // neighbours in each piece
        for (i, pair) in ids.windows(2).enumerate() {
            for (&a, &b) in pair[0].iter().zip(&pair[1]) {
                let (Some(r), Some(l)) = (a, b) else { continue };
                match (spec.lanes[i].reversed, spec.lanes[i + 1].reversed) {
                    (false, false) => self.neighbours(r, l, false),
                    (false, true) => self.neighbours(r, l, true),
                    (true, true) => self.neighbours(l, r, false),
                    (true, false) => {} // two right-hand sides facing: no adjacency declared
                }
            }
        }
        let last = stations.len() - 1;
        Road {
            ids,
            reversed: spec.lanes.iter().map(|l| l.reversed).collect(),
            end: points.iter().map(|r| r[last]).collect(),
            heading_end: spec.path.pose(len).2,
        }
    }

    /// A lanelet from cross-section (left0, right0) with heading h0 to (left1, right1) with
    /// heading h1, both bounds cubic Hermite curves, `n` + 1 points each.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn hermite(&mut self, from: (P, P), h0: f64, to: (P, P), h1: f64, n: usize, kind: LaneletType) -> Option<LaneletId> {
        let curve = |a: P, b: P| -> Vec<P> {
            let d = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
            let (t0, t1) = ((d * h0.cos(), d * h0.sin()), (d * h1.cos(), d * h1.sin()));
            (0..=n)
                .map(|k| {
                    let u = k as f64 / n as f64;
                    let (h00, h10, h01, h11) =
                        (2.0 * u.powi(3) - 3.0 * u * u + 1.0, u.powi(3) - 2.0 * u * u + u, -2.0 * u.powi(3) + 3.0 * u * u, u.powi(3) - u * u);
                    (h00 * a.0 + h10 * t0.0 + h01 * b.0 + h11 * t1.0, h00 * a.1 + h10 * t0.1 + h01 * b.1 + h11 * t1.1)
                })
                .collect()
        };
        self.add(curve(from.0, to.0), curve(from.1, to.1), kind)
    }

    /// The end (or start) cross-section of a lanelet as (left, right) and its heading there.
    pub(crate) fn cross_section(&self, id: LaneletId, at_end: bool) -> Option<((P, P), f64)> {
        let l = self.lanelet(id)?;
        let (lb, rb) = (l.bounds.left(), l.bounds.right());
        let k = if at_end { lb.len() - 1 } else { 0 };
        let p = |q: &Point| (q.x, q.y);
        // heading from the centre line over about 2 m from the end
        let c = |i: usize| ((lb[i].x + rb[i].x) * 0.5, (lb[i].y + rb[i].y) * 0.5);
        let mut j = k;
        loop {
            let next = if at_end { j.checked_sub(1) } else { Some(j + 1).filter(|&x| x < lb.len()) };
            let Some(nj) = next else { break };
            j = nj;
            let (a, b) = (c(k), c(j));
            if ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt() > 2.0 {
                break;
            }
        }
        let (a, b) = if at_end { (c(j), c(k)) } else { (c(k), c(j)) };
        Some(((p(&lb[k]), p(&rb[k])), (b.1 - a.1).atan2(b.0 - a.0)))
    }

    /// Moves and turns the whole network (recorded maps sit anywhere).
    pub(crate) fn place(&mut self, angle: f64, dx: f64, dy: f64) {
        let (c, s) = (angle.cos(), angle.sin());
        let f = |q: &Point| Point::new(c * q.x - s * q.y + dx, s * q.x + c * q.y + dy);
        for l in &mut self.net.lanelets {
            if let Ok(b) = LaneletBounds::new(l.bounds.left().iter().map(f).collect(), l.bounds.right().iter().map(f).collect()) {
                l.bounds = b;
            }
        }
    }
}

/// Why a network is not a valid CommonRoad network, if it is not: the model's consistency
/// check (links and adjacency declared both ways, ids) and no lanelet whose outline crosses
/// itself.
pub(crate) fn invalid(net: &LaneletNetwork) -> Option<String> {
    let mut scenario = Scenario::new(header());
    scenario.network = net.clone();
    if let Some(p) = scenario.validate(None).first() {
        return Some(p.to_string());
    }
    for l in &net.lanelets {
        let ring: Vec<P> = l.bounds.left().iter().chain(l.bounds.right().iter().rev()).map(|q| (q.x, q.y)).collect();
        if crosses_itself(&ring) {
            return Some(format!("lanelet {} crosses itself", l.id));
        }
    }
    None
}

/// The header of a generated network's scenario file.
pub(crate) fn header() -> Header {
    Header {
        benchmark_id: BenchmarkId::parse("DEU_Generated-1_1_T-1").expect("a valid benchmark id"),
        date: Date::new(2026, 11, 28).expect("a valid date"),
        author: "generator".into(),
        affiliation: "osc2cr".into(),
        source: "generated".into(),
        time_step_size: 0.1,
    }
}

fn crosses_itself(ring: &[P]) -> bool {
    let n = ring.len();
    let seg = |i: usize| (ring[i], ring[(i + 1) % n]);
    let cross = |o: P, a: P, b: P| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let ((a, b), (c, d)) = (seg(i), seg(j));
            let (d1, d2, d3, d4) = (cross(a, b, c), cross(a, b, d), cross(c, d, a), cross(c, d, b));
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                return true;
            }
        }
    }
    false
}
