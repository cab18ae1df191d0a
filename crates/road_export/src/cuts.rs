//! Lanelets cut where a neighbour starts or ends beside them. A lane section needs lanes that
//! start and end together, and CommonRoad often has a long lanelet beside shorter ones (a lane
//! that begins halfway along its neighbour, staggered lanelets of a recorded map). Such a
//! lanelet is cut into pieces at the cross-sections where its neighbours' shared bounds end;
//! the pieces are ordinary lanelets to the rest of the export: successors of each other, the
//! first taking the lanelet's predecessors, the last its successors, each adjacent to the
//! piece of the neighbour beside it. A reader gets a chain of lanelets back, which the round
//! trip compares as the one lanelet it came from.
//!
//! A lanelet is also cut where its bound meets a neighbour's after running apart from it (a
//! lane that joins its neighbour: they are neighbours from there on), and the cuts are
//! repeated on the pieces, since a piece's new end may cut its other neighbour in turn.
//!
//! The cut is made on the bound shared with the neighbour, at the same parameter (segment and
//! fraction) on both bounds: CommonRoad pairs the points of its bounds across the lanelet.
//! Lanelets of an intersection are not cut (the junction's connecting roads stay one lanelet
//! each). Warnings about a piece name the lanelet it was cut from.

use crate::groups::{SHARED, SHARED_ENDS};
use crate::topology::intersection_of;
use crate::vec2::{to_segment, SegmentIndex, V2};
use crate::warning::{Subject, Warning};
use commonroad::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletId, LaneletNetwork, Point};
use std::collections::BTreeMap;

/// Cuts closer together than this are one cut (m along the bound).
const MIN_PIECE: f64 = 1.0;
/// A cut this close to a bound vertex is made at the vertex (m): no sliver segments.
const SNAP: f64 = 0.05;
/// Bounds this close share a border where they meet (m; two bounds 2·CLOSE apart make a
/// border that is CLOSE from each).
const CLOSE: f64 = 0.03;
/// Rounds of cutting at most (a cut piece may cut its other neighbour).
const PASSES: usize = 6;
/// Spacing of the samples that find where bounds meet (m).
const STEP: f64 = 0.25;
/// A neighbour piece whose bound is farther than this from a piece's bound is not beside it (m).
const BESIDE: f64 = 1.0;
/// The shortest end piece where two forked lanelets come side by side at their ends (m).
const MIN_END_PIECE: f64 = 0.05;
/// Step of the walk back from the end of a bound that meets its neighbour's only there (m).
const FINE: f64 = 0.005;

/// The network with its lanelets cut, and where each piece came from.
pub(crate) struct Cut {
    pub network: LaneletNetwork,
    /// Piece id → id of the lanelet it was cut from (pieces only).
    pub origin: BTreeMap<u64, u64>,
    /// Neighbours no piece lies beside (named by the lanelet as it was before the cut).
    pub warnings: Vec<Warning>,
}

impl Cut {
    /// This cut followed by `next` (made on this one's network): pieces of pieces name the
    /// lanelet of the original network they come from.
    pub(crate) fn then(self, next: Cut) -> Cut {
        let mut origin = self.origin;
        for (piece, from) in next.origin {
            let root = origin.get(&from).copied().unwrap_or(from);
            origin.insert(piece, root);
        }
        let mut warnings = self.warnings;
        warnings.extend(next.warnings);
        Cut { network: next.network, origin, warnings }
    }

    /// Warnings about pieces name the lanelet they were cut from (each said once).
    pub(crate) fn rename(&self, warnings: Vec<Warning>) -> Vec<Warning> {
        let mut out: Vec<Warning> = Vec::with_capacity(warnings.len());
        for mut w in warnings {
            if let Subject::Lanelet(id) = w.subject {
                if let Some(&o) = self.origin.get(&id) {
                    w.subject = Subject::Lanelet(o);
                }
            }
            if !out.contains(&w) {
                out.push(w);
            }
        }
        out
    }
}

fn v2(line: &[Point]) -> Option<Vec<V2>> {
    let v: Vec<V2> = line.iter().map(V2::of).collect();
    v.iter().all(|p| p.is_finite()).then_some(v)
}

/// Where `p` is nearest on `line`: (distance, parameter k + fraction, arc length).
fn locate(line: &[V2], p: V2) -> (f64, f64, f64) {
    let mut best = (f64::INFINITY, 0.0, 0.0);
    let mut arc = 0.0;
    for (k, w) in line.windows(2).enumerate() {
        let (d, u) = to_segment(p, w[0], w[1]);
        let len = w[0].dist(w[1]);
        if d < best.0 {
            best = (d, k as f64 + u, arc + u * len);
        }
        arc += len;
    }
    best
}

fn length(line: &[V2]) -> f64 {
    crate::vec2::length(line)
}

/// The point at parameter `u` (vertex index + fraction) of `line`.
fn at(line: &[Point], u: f64) -> Point {
    let k = (u.floor().max(0.0) as usize).min(line.len().saturating_sub(1));
    let f = u - k as f64;
    match (line.get(k), line.get(k + 1)) {
        (Some(a), Some(b)) if f > 0.0 => {
            let z = match (a.z, b.z) {
                (Some(za), Some(zb)) => Some(za + f * (zb - za)),
                _ => None,
            };
            Point { x: a.x + f * (b.x - a.x), y: a.y + f * (b.y - a.y), z }
        }
        (Some(a), _) => *a,
        _ => Point::new(0.0, 0.0),
    }
}

/// The part of `line` between parameters `u0` < `u1`.
fn part(line: &[Point], u0: f64, u1: f64) -> Vec<Point> {
    let mut out = vec![at(line, u0)];
    let first = u0.floor() as usize + 1;
    for v in first..line.len() {
        if v as f64 >= u1 {
            break;
        }
        if let Some(p) = line.get(v) {
            out.push(*p);
        }
    }
    out.push(at(line, u1));
    out
}

/// The neighbour's bound facing `l`'s side `left`, in `l`'s direction.
fn facing(n: &Lanelet, left: bool, adj: Adjacent) -> Option<Vec<V2>> {
    let opposite = adj.driving_dir == DrivingDir::Opposite;
    let b = match (left, opposite) {
        (true, false) | (false, true) => n.bounds.right(),
        (false, false) | (true, true) => n.bounds.left(),
    };
    let mut v = v2(b)?;
    if opposite {
        v.reverse();
    }
    Some(v)
}

/// Where `mine` starts or stops sharing the bound `theirs`: (arc length, parameter) of the
/// first sample within [`CLOSE`] after one farther than [`SHARED`], and of the last within
/// [`CLOSE`] before one farther than [`SHARED`]; distances between the two decide nothing,
/// so bounds a few centimetres apart all along are not cut up.
fn meeting_points(mine: &[V2], theirs: &[V2]) -> Vec<(f64, f64)> {
    let index = SegmentIndex::new(std::iter::once(theirs), 2.0);
    // (arc, parameter, distance) every STEP m and at every vertex
    let mut samples: Vec<(f64, f64, f64)> = Vec::new();
    let mut arc = 0.0;
    for (k, w) in mine.windows(2).enumerate() {
        let len = w[0].dist(w[1]);
        let n = ((len / STEP).ceil() as usize).clamp(1, 1_000_000);
        for m in 0..n {
            let f = m as f64 / n as f64;
            samples.push((arc + f * len, k as f64 + f, index.distance(w[0].lerp(w[1], f), 4.0 * SHARED)));
        }
        arc += len;
    }
    if let Some(&last) = mine.last() {
        samples.push((arc, (mine.len() - 1) as f64, index.distance(last, 4.0 * SHARED)));
    }
    let mut out = Vec::new();
    // the state of the last decisive sample: Some(true) close, Some(false) far
    let mut state: Option<bool> = None;
    let mut last_close: Option<(f64, f64)> = None;
    for &(a, u, d) in &samples {
        if d <= CLOSE {
            if state == Some(false) {
                out.push((a, u));
            }
            state = Some(true);
            last_close = Some((a, u));
        } else if d > SHARED {
            if state == Some(true) {
                out.extend(last_close);
            }
            state = Some(false);
        }
    }
    out
}

/// Where `mine` comes within [`CLOSE`] of `theirs` for good when that happens only in the
/// last [`SHARED_ENDS`] of it, after running farther than [`SHARED`] from it: two "adjacent"
/// lanelets that fork from one cross-section and end side by side, touching only near their
/// ends. Their ends are neighbours there (a border [`CLOSE`] from each bound), so the last
/// stretch becomes a piece of its own: (arc length, parameter) of the cut, if the piece is at
/// least [`MIN_END_PIECE`] long.
fn fork_end(mine: &[V2], theirs: &[V2]) -> Option<(f64, f64)> {
    let total = length(mine);
    let index = SegmentIndex::new(std::iter::once(theirs), 2.0);
    let near = |arc: f64| index.distance(walk(mine, arc), 4.0 * SHARED);
    if near(total) > CLOSE || total <= SHARED_ENDS {
        return None;
    }
    // the close stretch at the end, walked back in fine steps
    let mut back = 0.0;
    while back + FINE < SHARED_ENDS && near(total - back - FINE) <= CLOSE {
        back += FINE;
    }
    if back + FINE >= SHARED_ENDS || back < MIN_END_PIECE {
        return None;
    }
    // farther than SHARED somewhere before it: not one shared bound
    let n = ((total / STEP).ceil() as usize).clamp(1, 1_000_000);
    let parts = (0..n).any(|k| near(total * k as f64 / n as f64) > SHARED);
    if !parts {
        return None;
    }
    let arc = total - back;
    Some((arc, locate(mine, walk(mine, arc)).1))
}

/// Where one lanelet is cut.
#[derive(Clone, Default)]
struct Plan {
    /// Cut parameters (sorted, inside the lanelet).
    at: Vec<f64>,
    /// Length of the last piece when it is a forked pair's side-by-side end ([`fork_end`]),
    /// on the (left, right) side: that piece alone is beside the neighbour there, and beside
    /// nothing on its other side.
    fork: [Option<f64>; 2],
}

/// Where each lanelet is cut, from its neighbours' ends.
fn cut_params(net: &LaneletNetwork, pos: &BTreeMap<u64, usize>, keep: &BTreeMap<usize, u64>) -> Vec<Plan> {
    let mut out = vec![Plan::default(); net.lanelets.len()];
    for (i, l) in net.lanelets.iter().enumerate() {
        if keep.contains_key(&i) {
            continue;
        }
        let mut found: Vec<(f64, f64)> = Vec::new();
        let mut runs: Vec<(f64, f64)> = Vec::new();
        let mut fork_ends: Vec<(f64, f64, usize)> = Vec::new();
        for (left, adj) in [(true, l.adjacent_left), (false, l.adjacent_right)] {
            let Some(adj) = adj else { continue };
            let Some(n) = pos.get(&adj.lanelet.get()).and_then(|&j| net.lanelets.get(j)) else { continue };
            let Some(mine) = v2(if left { l.bounds.left() } else { l.bounds.right() }) else { continue };
            let Some(theirs) = facing(n, left, adj) else { continue };
            let total = length(&mine);
            // where the bounds meet or part (a lane forking off on top of its neighbour
            // shares a bound with it only after the fork)
            fork_ends.extend(fork_end(&mine, &theirs).map(|(arc, u)| (arc, u, usize::from(!left))));
            for (arc, u) in meeting_points(&mine, &theirs) {
                if arc > SHARED_ENDS && arc < total - SHARED_ENDS {
                    runs.push((arc, u));
                }
            }
            for end in [theirs.first(), theirs.last()].into_iter().flatten() {
                let (d, u, arc) = locate(&mine, *end);
                if d <= SHARED && arc > SHARED_ENDS && arc < total - SHARED_ENDS {
                    // at a vertex when the cut is that close to one
                    let k = u.round();
                    let snapped = mine.get(k as usize).is_some_and(|p| p.dist(*end) <= SNAP);
                    found.push((arc, if snapped { k } else { u }));
                }
            }
        }
        // a meeting point near a neighbour's end is that end
        let meetings: Vec<(f64, f64)> = runs.into_iter().filter(|r| found.iter().all(|f| (f.0 - r.0).abs() >= MIN_PIECE)).collect();
        found.extend(meetings);
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut kept: Vec<(f64, f64)> = Vec::new();
        for c in found {
            if kept.last().is_none_or(|last| c.0 - last.0 >= MIN_PIECE) && kept.last().is_none_or(|last| c.1 > last.1) {
                kept.push(c);
            }
        }
        // a forked pair's side-by-side ends: a short last piece
        let mut fork = [None, None];
        for (arc, u, side) in fork_ends {
            let total = v2(if side == 0 { l.bounds.left() } else { l.bounds.right() }).map_or(0.0, |b| length(&b));
            match kept.last() {
                Some(last) if last.1 == u => fork[side] = Some(total - arc),
                Some(last) if arc - last.0 < MIN_PIECE || u <= last.1 => {}
                _ => {
                    kept.push((arc, u));
                    fork[side] = Some(total - arc);
                }
            }
        }
        out[i] = Plan { at: kept.into_iter().map(|c| c.1).collect(), fork };
    }
    out
}

/// Index of the piece of `pieces` nearest to `p` (by its centre line), if any.
fn nearest_piece(pieces: &[Lanelet], p: V2) -> usize {
    let centre = |l: &Lanelet| -> Vec<V2> { l.bounds.left().iter().zip(l.bounds.right()).map(|(a, b)| V2::of(a).lerp(V2::of(b), 0.5)).collect() };
    let mut best = (f64::INFINITY, 0);
    for (k, l) in pieces.iter().enumerate() {
        let d = locate(&centre(l), p).0;
        if d < best.0 {
            best = (d, k);
        }
    }
    best.1
}

/// The network with every lanelet cut where a neighbour starts or ends beside it; `None`
/// when no lanelet needs cutting.
pub(crate) fn cut(net: &LaneletNetwork) -> Option<Cut> {
    let mut done: Option<Cut> = None;
    // a piece's new end can cut its other neighbour in turn
    for _ in 0..PASSES {
        let Some(next) = cut_once(done.as_ref().map_or(net, |c| &c.network)) else { break };
        done = Some(match done {
            None => next,
            Some(prev) => prev.then(next),
        });
    }
    done
}

/// One round of cuts (each lanelet against its neighbours as they are).
fn cut_once(net: &LaneletNetwork) -> Option<Cut> {
    let pos: BTreeMap<u64, usize> = net.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let keep = intersection_of(net);
    let params = cut_params(net, &pos, &keep);
    if params.iter().all(|p| p.at.is_empty()) {
        return None;
    }
    let mut next = net.max_id() + 1;
    let mut origin = BTreeMap::new();
    // pieces of every lanelet, in order (an uncut lanelet is its own single piece)
    let mut pieces: Vec<Vec<Lanelet>> = Vec::with_capacity(net.lanelets.len());
    for (l, plan) in net.lanelets.iter().zip(&params) {
        let cuts = &plan.at;
        if cuts.is_empty() {
            pieces.push(vec![l.clone()]);
            continue;
        }
        let last = (l.bounds.len() - 1) as f64;
        let stops: Vec<f64> = std::iter::once(0.0).chain(cuts.iter().copied()).chain(std::iter::once(last)).collect();
        let mut out = Vec::with_capacity(stops.len() - 1);
        for (k, w) in stops.windows(2).enumerate() {
            let Ok(bounds) = LaneletBounds::new(part(l.bounds.left(), w[0], w[1]), part(l.bounds.right(), w[0], w[1])) else {
                out.clear();
                break;
            };
            let id = if k == 0 {
                l.id
            } else {
                let id = LaneletId::new(next)?;
                next += 1;
                origin.insert(id.get(), l.id.get());
                id
            };
            let mut p = l.clone();
            p.id = id;
            p.bounds = bounds;
            (p.traffic_sign_refs, p.traffic_light_refs, p.stop_line) = (Vec::new(), Vec::new(), None);
            out.push(p);
        }
        if out.is_empty() {
            pieces.push(vec![l.clone()]);
            continue;
        }
        // inner links; the ends keep the lanelet's own links (mapped below)
        let ids: Vec<LaneletId> = out.iter().map(|p| p.id).collect();
        for (k, p) in out.iter_mut().enumerate() {
            if k > 0 {
                p.predecessors = vec![ids[k - 1]];
            }
            if k + 1 < ids.len() {
                p.successors = vec![ids[k + 1]];
            }
        }
        pieces.push(out);
    }
    let first = |id: LaneletId| pos.get(&id.get()).and_then(|&j| pieces.get(j)).and_then(|p| p.first()).map_or(id, |p| p.id);
    let last = |id: LaneletId| pos.get(&id.get()).and_then(|&j| pieces.get(j)).and_then(|p| p.last()).map_or(id, |p| p.id);
    let mut lanelets = Vec::new();
    let mut warnings = Vec::new();
    for ((l, ps), plan) in net.lanelets.iter().zip(&pieces).zip(&params) {
        let n = ps.len();
        // whether some piece kept its left / right neighbour
        let mut kept = [l.adjacent_left.is_none(), l.adjacent_right.is_none()];
        for (k, piece) in ps.iter().enumerate() {
            let mut p = piece.clone();
            if k == 0 {
                p.predecessors = l.predecessors.iter().map(|&x| last(x)).collect();
            }
            if k + 1 == n {
                p.successors = l.successors.iter().map(|&x| first(x)).collect();
            }
            // beside the piece of each neighbour that runs along it
            for left in [true, false] {
                let adj = if left { l.adjacent_left } else { l.adjacent_right };
                let Some(adj) = adj else { continue };
                let Some(theirs) = pos.get(&adj.lanelet.get()).and_then(|&j| pieces.get(j)) else { continue };
                if n == 1 && theirs.len() == 1 {
                    kept[usize::from(!left)] = true;
                    continue;
                }
                // a forked pair is beside each other only at its end piece, which is
                // beside nothing else
                let end_piece = k + 1 == n && plan.fork.iter().any(Option::is_some);
                if plan.fork[usize::from(!left)].is_some() != end_piece {
                    let none = None;
                    if left {
                        p.adjacent_left = none;
                    } else {
                        p.adjacent_right = none;
                    }
                    continue;
                }
                let mine = v2(if left { p.bounds.left() } else { p.bounds.right() }).unwrap_or_default();
                let total = length(&mine);
                let mid = walk(&mine, 0.5 * total);
                // the neighbour piece whose bound runs beside the middle of mine (the foot
                // of the middle inside it, not at one of its ends)
                let beside = |b: &[V2]| {
                    let (d, _, arc) = locate(b, mid);
                    (arc > 1e-6 && arc < length(b) - 1e-6 && d <= BESIDE).then_some(d)
                };
                let best = theirs.iter().filter_map(|q| facing(q, left, adj).and_then(|b| beside(&b)).map(|d| (d, q.id))).min_by(|a, b| a.0.total_cmp(&b.0));
                let new = best.map(|(_, id)| Adjacent { lanelet: id, driving_dir: adj.driving_dir });
                kept[usize::from(!left)] |= new.is_some();
                if left {
                    p.adjacent_left = new;
                } else {
                    p.adjacent_right = new;
                }
            }
            lanelets.push(p);
        }
        for (side, (fork, adj)) in ["left", "right"].iter().zip(plan.fork.iter().zip([l.adjacent_left, l.adjacent_right])) {
            if let (Some(len), Some(adj)) = (fork, adj) {
                warnings.push(Warning::new(
                    Subject::Lanelet(l.id.get()),
                    format!(
                        "adjacent {side} lanelet {} overlaps it and shares its bound (within {CLOSE} m) only over its last {len:.2} m: that end is a lane section of its own, where they are adjacent; before it they are lanes of different roads",
                        adj.lanelet.get()
                    ),
                ));
            }
        }
        for (side, (ok, adj)) in ["left", "right"].iter().zip(kept.iter().zip([l.adjacent_left, l.adjacent_right])) {
            if let (false, Some(adj)) = (ok, adj) {
                warnings.push(Warning::new(
                    Subject::Lanelet(l.id.get()),
                    format!(
                        "adjacent {side} lanelet {} lies beside no part of it where the lanelets are cut into lane sections (within {BESIDE} m); the adjacency is not written",
                        adj.lanelet.get()
                    ),
                ));
            }
        }
        // references go to the piece where they stand
        let base = lanelets.len() - n;
        let sign_at = |id: u64| net.traffic_signs.iter().find(|s| s.id.get() == id).and_then(|s| s.position.as_ref()).map(V2::of);
        let light_at = |id: u64| net.traffic_lights.iter().find(|s| s.id.get() == id).and_then(|s| s.position.as_ref()).map(V2::of);
        if n > 1 {
            for s in &l.traffic_sign_refs {
                let k = sign_at(s.get()).map_or(0, |p| nearest_piece(ps, p));
                lanelets[base + k].traffic_sign_refs.push(*s);
            }
            for s in &l.traffic_light_refs {
                let k = light_at(s.get()).map_or(n - 1, |p| nearest_piece(ps, p));
                lanelets[base + k].traffic_light_refs.push(*s);
            }
            if let Some(stop) = &l.stop_line {
                let k = stop.points.as_ref().map_or(n - 1, |[a, b]| nearest_piece(ps, V2::of(a).lerp(V2::of(b), 0.5)));
                lanelets[base + k].stop_line = Some(stop.clone());
            }
        }
    }
    let network = rebuilt(net, lanelets, last, first);
    Some(Cut { network, origin, warnings })
}

/// `net` with new `lanelets`; its intersections name a cut lanelet's piece at the end that
/// stands there (`last` for incoming lanelets, `first` for their successors).
pub(crate) fn rebuilt(
    net: &LaneletNetwork,
    lanelets: Vec<Lanelet>,
    last: impl Fn(LaneletId) -> LaneletId,
    first: impl Fn(LaneletId) -> LaneletId,
) -> LaneletNetwork {
    let mut network = LaneletNetwork {
        lanelets,
        traffic_signs: net.traffic_signs.clone(),
        traffic_lights: net.traffic_lights.clone(),
        intersections: net.intersections.clone(),
    };
    for inter in &mut network.intersections {
        for inc in &mut inter.incomings {
            inc.incoming_lanelets = inc.incoming_lanelets.iter().map(|&x| last(x)).collect();
            for list in [&mut inc.successors_right, &mut inc.successors_straight, &mut inc.successors_left] {
                *list = list.iter().map(|&x| first(x)).collect();
            }
        }
    }
    network
}

/// The point `d` m along `line`.
fn walk(line: &[V2], d: f64) -> V2 {
    let mut left = d;
    for w in line.windows(2) {
        let len = w[0].dist(w[1]);
        if left <= len && len > 0.0 {
            return w[0].lerp(w[1], left / len);
        }
        left -= len;
    }
    line.last().copied().unwrap_or(V2::new(0.0, 0.0))
}
