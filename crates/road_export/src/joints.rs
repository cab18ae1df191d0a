//! Joints whose cross-section is not a straight line, sliced. Where side-by-side lanelets
//! (same direction) each go on into exactly one successor, and their shared end points do not
//! lie on one line (recorded and hand-made maps cut each lane on its own: a zig-zag or bowed
//! joint), a lane section cannot end there: OpenDRIVE ends all lanes of a section on one
//! straight cross-section. The section boundary is then laid on parallel straight lines
//! through the joint, at most [`SLICE`] apart, from just behind its rearmost point to just
//! ahead of its foremost: each lane becomes the part of its first lanelet before the first
//! line, thin slices between the lines, and the part of its successor after the last. Every
//! piece lies within a metre of the lanelets it comes from, so a reader's chain of pieces
//! compares as those lanelets; no area is added or lost (the pieces tile the two lanelets).
//!
//! The lanes may also fan out into separate roads there (or come together from them): a
//! connecting road of five lanes whose first two go on into one road and the other three into
//! another, its end bent where they part. At an intersection's edge the slices belong to the
//! road outside it (the connecting road, which is not cut, ends on the first line); a joint
//! inside an intersection is left as it is.
//! Warnings about a piece name the lanelet it was cut from.

use crate::cuts::Cut;
use crate::topology::intersection_of;
use crate::vec2::V2;
use commonroad::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletId, LaneletNetwork, Point};
use std::collections::{BTreeMap, BTreeSet};

/// Joints whose end points lie within a strip this wide are left as they are: the section
/// is cut a little further out, which the lanelets on either side tolerate (m).
pub(crate) const STRAIGHT: f64 = 0.25;
/// Largest spacing of the slicing lines (m).
const SLICE: f64 = 0.5;
/// Closest spacing of the slicing lines (m): an end point nearer than this to a line is
/// left inside a slice.
const MIN_SLICE: f64 = 0.1;
/// The joint's end points of two lanelets in a chain must meet within this (m).
const MEET: f64 = 0.01;
/// Joints spread wider than this are left as they are (m).
pub(crate) const MAX_SPREAD: f64 = 10.0;

/// One lane through a joint: the lanelet before it and its successor (in the lane's driving
/// direction), and whether the lane drives against the first lane of the joint.
struct Pair {
    a: usize,
    b: usize,
    reversed: bool,
}

impl Pair {
    /// The lanelet before the joint along the first lane's direction.
    fn before(&self) -> usize {
        if self.reversed {
            self.b
        } else {
            self.a
        }
    }
    fn after(&self) -> usize {
        if self.reversed {
            self.a
        } else {
            self.b
        }
    }
}

pub(crate) fn pos_of(net: &LaneletNetwork) -> BTreeMap<u64, usize> {
    net.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect()
}

/// `a`'s only successor, whose only predecessor is `a`.
fn chain_next(net: &LaneletNetwork, pos: &BTreeMap<u64, usize>, a: usize) -> Option<usize> {
    let l = net.lanelets.get(a)?;
    let [s] = l.successors.as_slice() else { return None };
    let b = *pos.get(&s.get())?;
    let [p] = net.lanelets.get(b)?.predecessors.as_slice() else { return None };
    (p.get() == l.id.get() && b != a).then_some(b)
}

/// `b`'s only predecessor, whose only successor is `b`.
fn chain_prev(net: &LaneletNetwork, pos: &BTreeMap<u64, usize>, b: usize) -> Option<usize> {
    let [p] = net.lanelets.get(b)?.predecessors.as_slice() else { return None };
    let a = *pos.get(&p.get())?;
    (chain_next(net, pos, a) == Some(b)).then_some(a)
}

/// The neighbour of `l` on the side that is `left` along the first lane's direction.
pub(crate) fn beside(l: &Lanelet, reversed: bool, left: bool) -> Option<Adjacent> {
    if left != reversed {
        l.adjacent_left
    } else {
        l.adjacent_right
    }
}

/// The lanes through the joint at the end of `a`, right to left along `a`'s direction
/// (lanes of either direction).
fn group(net: &LaneletNetwork, pos: &BTreeMap<u64, usize>, a: usize) -> Option<Vec<Pair>> {
    let b = chain_next(net, pos, a)?;
    let mut lanes = vec![Pair { a, b, reversed: false }];
    for left in [true, false] {
        let (mut before, mut after, mut rev) = (a, b, false);
        loop {
            let (n1, n2) = (beside(&net.lanelets[before], rev, left), beside(&net.lanelets[after], rev, left));
            let pair = match (n1, n2) {
                (Some(n1), Some(n2)) => {
                    if n1.driving_dir != n2.driving_dir {
                        break;
                    }
                    let (Some(&x1), Some(&x2)) = (pos.get(&n1.lanelet.get()), pos.get(&n2.lanelet.get())) else { break };
                    // x1 lies beside the part before the joint: the lane's first lanelet unless it drives the other way
                    if rev != (n1.driving_dir == DrivingDir::Opposite) {
                        Pair { a: x2, b: x1, reversed: true }
                    } else {
                        Pair { a: x1, b: x2, reversed: false }
                    }
                }
                // a neighbour on one side of the joint only, whose lane goes on beside nothing
                // on the other: the lanes fan out into separate roads (or come together from
                // them), as a connecting road of several lanes whose end meets two roads
                (Some(n), None) | (None, Some(n)) if !rev && n.driving_dir == DrivingDir::Same => {
                    let Some(&x) = pos.get(&n.lanelet.get()) else { break };
                    let pair = if n1.is_some() {
                        let Some(b) = chain_next(net, pos, x) else { break };
                        Pair { a: x, b, reversed: false }
                    } else {
                        let Some(a) = chain_prev(net, pos, x) else { break };
                        Pair { a, b: x, reversed: false }
                    };
                    let lone = if n1.is_some() { pair.b } else { pair.a };
                    if beside(&net.lanelets[lone], false, !left).is_some() {
                        break;
                    }
                    pair
                }
                _ => break,
            };
            let nrev = pair.reversed;
            if chain_next(net, pos, pair.a) != Some(pair.b) || lanes.iter().any(|p| p.a == pair.a) {
                break;
            }
            (before, after, rev) = (pair.before(), pair.after(), nrev);
            if left {
                lanes.push(pair);
            } else {
                lanes.insert(0, pair);
            }
        }
    }
    // the whole cross-section, or nothing: a neighbour beside only one side of the joint (a
    // lane that begins or ends there, a fork) is left to `cuts`
    let ours: BTreeSet<u64> = lanes.iter().flat_map(|p| [p.a, p.b]).filter_map(|i| net.lanelets.get(i)).map(|l| l.id.get()).collect();
    let whole = lanes
        .iter()
        .flat_map(|p| [p.a, p.b])
        .filter_map(|i| net.lanelets.get(i))
        .all(|l| [l.adjacent_left, l.adjacent_right].iter().flatten().all(|x| ours.contains(&x.lanelet.get())));
    (lanes.len() >= 2 && whole).then_some(lanes)
}

/// The parameter (vertex index + fraction) where `line` crosses {p : p·n = s}, the crossing
/// nearest to `near`.
pub(crate) fn crossing(line: &[V2], n: V2, s: f64, near: V2) -> Option<f64> {
    let mut best: Option<(f64, f64)> = None;
    for (k, w) in line.windows(2).enumerate() {
        let (fa, fb) = (w[0].dot(n) - s, w[1].dot(n) - s);
        if fa == fb || fa * fb > 0.0 {
            continue;
        }
        let f = fa / (fa - fb);
        let d = w[0].lerp(w[1], f).dist(near);
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, k as f64 + f));
        }
    }
    best.map(|(_, u)| u)
}

fn at(line: &[Point], u: f64) -> Point {
    let k = (u.floor().max(0.0) as usize).min(line.len().saturating_sub(1));
    let f = u - k as f64;
    match (line.get(k), line.get(k + 1)) {
        (Some(a), Some(b)) if f > 0.0 => Point::new(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)),
        (Some(a), _) => *a,
        _ => Point::new(0.0, 0.0),
    }
}

/// The part of `line` between parameters `u0` < `u1`.
pub(crate) fn part(line: &[Point], u0: f64, u1: f64) -> Vec<Point> {
    let mut out = vec![at(line, u0)];
    out.extend(line.iter().enumerate().filter(|&(v, _)| (v as f64) > u0 && (v as f64) < u1).map(|(_, p)| *p));
    out.push(at(line, u1));
    out
}

/// `line` with points added in its longest segments until it has `n`.
fn grow(mut line: Vec<Point>, n: usize) -> Vec<Point> {
    while line.len() < n {
        let d = |k: usize| V2::of(&line[k]).dist(V2::of(&line[k + 1]));
        let Some(k) = (0..line.len() - 1).max_by(|&i, &j| d(i).total_cmp(&d(j))) else { break };
        let (a, b) = (line[k], line[k + 1]);
        line.insert(k + 1, Point::new(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)));
    }
    line
}

/// Bounds from two parts (made the same length).
pub(crate) fn bounds(left: Vec<Point>, right: Vec<Point>) -> Option<LaneletBounds> {
    let n = left.len().max(right.len());
    LaneletBounds::new(grow(left, n), grow(right, n)).ok()
}

/// The pieces of one lane (their bounds, in driving order), or `None` when the lines do not
/// cut both lanelets cleanly.
fn pieces(a: &Lanelet, b: &Lanelet, n: V2, lines: &[f64]) -> Option<Vec<LaneletBounds>> {
    let join = |x: &[Point], y: &[Point]| -> Option<Vec<Point>> {
        let (last, first) = (x.last()?, y.first()?);
        (V2::of(last).dist(V2::of(first)) <= MEET).then(|| x.iter().chain(&y[1..]).copied().collect())
    };
    let left = join(a.bounds.left(), b.bounds.left())?;
    let right = join(a.bounds.right(), b.bounds.right())?;
    let lv: Vec<V2> = left.iter().map(V2::of).collect();
    let rv: Vec<V2> = right.iter().map(V2::of).collect();
    let (jl, jr) = (V2::of(a.bounds.left().last()?), V2::of(a.bounds.right().last()?));
    let mut ul = vec![0.0];
    let mut ur = vec![0.0];
    for &s in lines {
        ul.push(crossing(&lv, n, s, jl)?);
        ur.push(crossing(&rv, n, s, jr)?);
    }
    ul.push((left.len() - 1) as f64);
    ur.push((right.len() - 1) as f64);
    // the lines must cut each bound in order, every piece with some length
    if ul.windows(2).chain(ur.windows(2)).any(|w| w[1] <= w[0] + 1e-9) {
        return None;
    }
    ul.windows(2).zip(ur.windows(2)).map(|(l, r)| bounds(part(&left, l[0], l[1]), part(&right, r[0], r[1]))).collect()
}

/// The slicing lines from `lo` to `hi` (along their normal): one through every end point
/// (`ends`, where a bound kinks from one lanelet into the next: a section boundary there keeps
/// the corner, which a border fitted across it would cut), none closer than [`MIN_SLICE`] to
/// another, at most [`SLICE`] apart.
pub(crate) fn slicing_lines(mut ends: Vec<f64>, lo: f64, hi: f64) -> Vec<f64> {
    ends.sort_by(f64::total_cmp);
    let mut fixed = vec![lo];
    for e in ends.into_iter().chain([hi]) {
        let close = fixed.last().is_some_and(|&last| e - last < MIN_SLICE);
        // the outermost lines stay where they are
        if close && e == hi && fixed.len() > 1 {
            fixed.pop();
        }
        if !close || e == hi {
            fixed.push(e);
        }
    }
    let mut out = Vec::new();
    for w in fixed.windows(2) {
        let m = ((w[1] - w[0]) / SLICE).ceil().max(1.0) as usize;
        out.extend((0..m).map(|j| w[0] + (w[1] - w[0]) * j as f64 / m as f64));
    }
    out.push(hi);
    out
}

/// The slicing lines' normal near `n` (±30°) along which each lane's own two end points (`own`:
/// from the right one to the left one) lie
/// closest together: a slice then holds the end of one lanelet beside the start of its
/// successor over as little of the lane's length as can be, so each piece stays within a
/// metre of the lanelets it comes from. Where the lanes fan out (their ends on lines at an
/// angle) the line through the outermost ends can be a metre off a wide lane's own end.
pub(crate) fn least_slanted(own: &[V2], n: V2) -> V2 {
    let slant = |m: V2| own.iter().map(|d| d.dot(m).abs()).fold(0.0, f64::max);
    let base = n.y.atan2(n.x);
    let mut best = (slant(n), n);
    for k in -120i32..=120 {
        let m = V2::unit(base + f64::from(k) * 0.25f64.to_radians());
        // only a real gain turns the lines
        let s = slant(m);
        if s < best.0 - 0.01 {
            best = (s, m);
        }
    }
    best.1
}

/// The network with every zig-zag joint sliced; `None` when there is none.
pub(crate) fn slice(net: &LaneletNetwork) -> Option<Cut> {
    let pos = pos_of(net);
    let keep = intersection_of(net);
    let mut used: BTreeSet<usize> = BTreeSet::new();
    // per sliced joint: its lanes, their pieces (bounds) and whether the slices belong to
    // the lanelets after the joint (the ones before it are an intersection's)
    let mut plans: Vec<(Vec<Pair>, Vec<Vec<LaneletBounds>>, bool)> = Vec::new();
    for a in 0..net.lanelets.len() {
        if used.contains(&a) {
            continue;
        }
        let Some(lanes) = group(net, &pos, a) else { continue };
        if lanes.iter().any(|p| used.contains(&p.a) || used.contains(&p.b)) {
            continue;
        }
        // a joint at an intersection's edge is sliced outside it (its lanelets, the
        // connecting roads, are not cut: the slices go to the road they meet); one inside
        // an intersection, or half in it, is left as it is
        let inside = |i: usize| keep.contains_key(&i);
        let (ka, kb) = (lanes.iter().map(|p| inside(p.a)).collect::<BTreeSet<_>>(), lanes.iter().map(|p| inside(p.b)).collect::<BTreeSet<_>>());
        if ka.len() > 1 || kb.len() > 1 || ka.contains(&true) && kb.contains(&true) {
            continue;
        }
        let slices_after = ka.contains(&true);
        let ends: Vec<V2> = lanes
            .iter()
            .flat_map(|p| {
                let l = &net.lanelets[p.a];
                [l.bounds.left().last(), l.bounds.right().last()]
            })
            .flatten()
            .map(V2::of)
            .collect();
        let outer = |i: usize, left: bool| {
            lanes.get(i).and_then(|p| {
                let b = &net.lanelets[p.a].bounds;
                if left != p.reversed { b.left().last() } else { b.right().last() }.map(V2::of)
            })
        };
        let (Some(r0), Some(l1)) = (outer(0, false), outer(lanes.len() - 1, true)) else { continue };
        let c = l1.sub(r0);
        if c.len() < 1e-3 {
            continue;
        }
        let n = V2::new(c.y, -c.x).scale(1.0 / c.len());
        let spread_along = |n: V2| {
            let s: Vec<f64> = ends.iter().map(|p| p.dot(n)).collect();
            s.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
        };
        let (lo, hi) = spread_along(n);
        if hi - lo <= STRAIGHT || hi - lo > MAX_SPREAD {
            continue;
        }
        let own: Vec<V2> = lanes
            .iter()
            .filter_map(|p| {
                let b = &net.lanelets.get(p.a)?.bounds;
                Some(V2::of(b.left().last()?).sub(V2::of(b.right().last()?)))
            })
            .collect();
        let n = least_slanted(&own, n);
        let (lo, hi) = spread_along(n);
        if hi - lo > MAX_SPREAD {
            continue;
        }
        let lines = slicing_lines(ends.iter().map(|p| p.dot(n)).collect(), lo - 1e-3, hi + 1e-3);
        let back: Vec<f64> = lines.iter().rev().copied().collect();
        let cut: Option<Vec<Vec<LaneletBounds>>> = lanes
            .iter()
            .map(|p| {
                pieces(
                    &net.lanelets[p.a],
                    &net.lanelets[p.b],
                    if p.reversed { n.scale(-1.0) } else { n },
                    &if p.reversed { back.iter().map(|s| -s).collect::<Vec<_>>() } else { lines.clone() },
                )
            })
            .collect();
        let Some(cut) = cut else { continue };
        for p in &lanes {
            used.insert(p.a);
            used.insert(p.b);
        }
        plans.push((lanes, cut, slices_after));
    }
    if plans.is_empty() {
        return None;
    }
    let mut next = net.max_id() + 1;
    let mut origin = BTreeMap::new();
    // old id → (first piece, last piece)
    let mut renamed: BTreeMap<u64, (LaneletId, LaneletId)> = BTreeMap::new();
    let mut made: Vec<Lanelet> = Vec::new();
    for (lanes, cut, slices_after) in &plans {
        let mut ids: Vec<Vec<LaneletId>> = Vec::new();
        for (p, parts) in lanes.iter().zip(cut) {
            let (la, lb) = (&net.lanelets[p.a], &net.lanelets[p.b]);
            let mut row = Vec::new();
            for (k, bd) in parts.iter().enumerate() {
                let id = LaneletId::new(next)?;
                next += 1;
                let from = if k + 1 == parts.len() || (k > 0 && *slices_after) { lb } else { la };
                origin.insert(id.get(), from.id.get());
                let mut piece = Lanelet::new(id, bd.clone(), commonroad::LaneletType::Unknown);
                piece.lanelet_types = from.lanelet_types.clone();
                piece.left_marking = from.left_marking;
                piece.right_marking = from.right_marking;
                piece.user_one_way = from.user_one_way.clone();
                piece.user_bidirectional = from.user_bidirectional.clone();
                if k == 0 {
                    piece.predecessors = la.predecessors.clone();
                    piece.traffic_sign_refs = la.traffic_sign_refs.clone();
                }
                if (k + 2 == parts.len() && !slices_after) || (k == 0 && *slices_after) {
                    piece.stop_line = la.stop_line.clone();
                    piece.traffic_light_refs = la.traffic_light_refs.clone();
                }
                if k + 1 == parts.len() {
                    piece.successors = lb.successors.clone();
                    piece.stop_line = lb.stop_line.clone();
                    piece.traffic_sign_refs = lb.traffic_sign_refs.clone();
                    piece.traffic_light_refs = lb.traffic_light_refs.clone();
                }
                row.push(id);
                made.push(piece);
            }
            renamed.insert(la.id.get(), (row[0], row[0]));
            renamed.insert(lb.id.get(), (row[row.len() - 1], row[row.len() - 1]));
            ids.push(row);
        }
        // links along each lane, neighbours across (right to left, same direction)
        let find = |made: &[Lanelet], id: LaneletId| made.iter().position(|l| l.id == id);
        for (i, row) in ids.iter().enumerate() {
            for w in row.windows(2) {
                if let Some(x) = find(&made, w[0]) {
                    made[x].successors = vec![w[1]];
                }
                if let Some(y) = find(&made, w[1]) {
                    made[y].predecessors = vec![w[0]];
                }
            }
            let (la, lb) = (&net.lanelets[lanes[i].a], &net.lanelets[lanes[i].b]);
            let last = row.len() - 1;
            let rev = lanes[i].reversed;
            for (k, &id) in row.iter().enumerate() {
                let Some(x) = find(&made, id) else { continue };
                let outer = if k == last { lb } else { la };
                // the slot along the first lane's direction, and the pieces beside it
                let slot = if rev { last - k } else { k };
                let at = |j: usize| {
                    let dir = if lanes[j].reversed == rev { DrivingDir::Same } else { DrivingDir::Opposite };
                    let piece = if lanes[j].reversed { ids[j].get(last - slot) } else { ids[j].get(slot) };
                    piece.map(|&p| Adjacent { lanelet: p, driving_dir: dir })
                };
                let mut left = if i + 1 < ids.len() { at(i + 1) } else { None };
                let mut right = i.checked_sub(1).and_then(at);
                // the outermost lanes keep their other neighbours where those stand
                if i + 1 == ids.len() && (k == 0 || k == last) {
                    left = beside(outer, rev, true);
                }
                if i == 0 && (k == 0 || k == last) {
                    right = beside(outer, rev, false);
                }
                // where the lanes fan out into separate roads, the end pieces are beside
                // what their own lanelets are beside
                if k == 0 || k == last {
                    left = left.filter(|_| beside(outer, rev, true).is_some());
                    right = right.filter(|_| beside(outer, rev, false).is_some());
                }
                (made[x].adjacent_left, made[x].adjacent_right) = if rev { (right, left) } else { (left, right) };
            }
        }
    }
    let gone: BTreeSet<u64> = renamed.keys().copied().collect();
    let first = |id: LaneletId| renamed.get(&id.get()).map_or(id, |r| r.0);
    let mut lanelets: Vec<Lanelet> = Vec::with_capacity(net.lanelets.len() + made.len());
    for l in net.lanelets.iter().filter(|l| !gone.contains(&l.id.get())).chain(&made) {
        let mut l = l.clone();
        // links and neighbours that named a replaced lanelet name its piece at that end
        l.successors = l.successors.iter().map(|&x| first(x)).collect();
        l.predecessors = l.predecessors.iter().map(|&x| first(x)).collect();
        for a in [&mut l.adjacent_left, &mut l.adjacent_right].into_iter().flatten() {
            a.lanelet = first(a.lanelet);
        }
        lanelets.push(l);
    }
    let network = crate::cuts::rebuilt(net, lanelets, first, first);
    Some(Cut { network, origin, warnings: Vec::new() })
}
