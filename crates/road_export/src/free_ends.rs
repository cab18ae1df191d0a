//! Free road ends whose points lie on no straight line, sliced. Where side-by-side lanelets
//! (either direction) end with no link at one cross-section whose points lie on a bow or a
//! zig-zag, one lane section cannot end there: it ends on one straight line that covers every
//! end, so the lanes whose own end lies behind it come back longer, by as much as the end is
//! deep (more than the metre a read-back piece may stray from its lanelet). The end is laid
//! on parallel straight lines instead, one through every end point (`joints::slicing_lines`),
//! and each slice between two lines holds only the lanes that have begun there (those with
//! any of their material in it): a lane is then longer by no more than its own end is slanted
//! to the lines (which are turned to make that least), and a line's spacing where end points
//! closer than `joints::MIN_SLICE` share one. The lanes present in every
//! slice must be side by side, else the end is left as it is. A lane's bound that begins
//! beyond a slice it is in is carried back along its first segment (the lane is a little
//! longer there). The lanelet keeps its id for the part after the last line, so its links,
//! signs and neighbours there stay as they are; the slices are new lanelets.

use crate::cuts::Cut;
use crate::joints::{beside, bounds, crossing, least_slanted, part, pos_of, slicing_lines, MAX_SPREAD, STRAIGHT};
use crate::topology::intersection_of;
use crate::vec2::V2;
use commonroad::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletId, LaneletNetwork, Point};
use std::collections::{BTreeMap, BTreeSet};

/// A lane must go on at least this far beyond the last line (m).
const BEYOND: f64 = 1.0;
/// A bound carried back must leave its end at least this steeply across the lines (the cosine
/// of its angle to their normal).
const MIN_ACROSS: f64 = 0.3;

/// One lane at the end: its lanelet and whether it runs against the working direction (which
/// starts at the free end).
#[derive(Clone, Copy)]
struct Member {
    idx: usize,
    rev: bool,
}

/// The lanelet's bounds in the working direction: (left, right), starting at the free end.
fn working(l: &Lanelet, rev: bool) -> (Vec<Point>, Vec<Point>) {
    if rev {
        let mut left = l.bounds.right().to_vec();
        let mut right = l.bounds.left().to_vec();
        left.reverse();
        right.reverse();
        (left, right)
    } else {
        (l.bounds.left().to_vec(), l.bounds.right().to_vec())
    }
}

/// Whether the lanelet has no link at its end that is the working start.
fn free(l: &Lanelet, rev: bool) -> bool {
    // the working start is the lanelet's own start unless it runs against it
    if rev {
        l.successors.is_empty()
    } else {
        l.predecessors.is_empty()
    }
}

/// The lanes of the cross-section at `a`'s start (`flip`: at its end), right to left in the
/// working direction; `None` unless every one of them ends there with no link and none has a
/// neighbour outside them.
fn cross_section(net: &LaneletNetwork, pos: &BTreeMap<u64, usize>, a: usize, flip: bool) -> Option<Vec<Member>> {
    let mut lanes = vec![Member { idx: a, rev: flip }];
    for left in [true, false] {
        let mut at = lanes.iter().find(|m| m.idx == a).copied()?;
        while let Some(n) = beside(net.lanelets.get(at.idx)?, at.rev, left) {
            let idx = *pos.get(&n.lanelet.get())?;
            if lanes.iter().any(|m| m.idx == idx) {
                return None;
            }
            let next = Member { idx, rev: at.rev != (n.driving_dir == DrivingDir::Opposite) };
            if left {
                lanes.push(next);
            } else {
                lanes.insert(0, next);
            }
            at = next;
        }
    }
    let ours: BTreeSet<u64> = lanes.iter().filter_map(|m| net.lanelets.get(m.idx)).map(|l| l.id.get()).collect();
    let whole = lanes
        .iter()
        .filter_map(|m| net.lanelets.get(m.idx))
        .all(|l| [l.adjacent_left, l.adjacent_right].iter().flatten().all(|x| ours.contains(&x.lanelet.get())));
    let all_free = lanes.iter().all(|m| net.lanelets.get(m.idx).is_some_and(|l| free(l, m.rev)));
    (lanes.len() >= 2 && whole && all_free).then_some(lanes)
}

/// The part of `bound` (working direction, the free end first) between lines `s0` < `s1`
/// along `n`, carried back along its first segment where it begins beyond `s0`.
fn slab(bound: &[Point], n: V2, s0: f64, s1: f64) -> Option<Vec<Point>> {
    let v: Vec<V2> = bound.iter().map(V2::of).collect();
    let first = *v.first()?;
    let start = first.dot(n);
    if start <= s0 {
        let (u0, u1) = (crossing(&v, n, s0, first)?, crossing(&v, n, s1, first)?);
        return (u1 > u0).then(|| part(bound, u0, u1));
    }
    // the bound begins inside or beyond the slice: its first segment carried back to the
    // slice's first line (every piece of the slice then begins on it, and the section's cut
    // is that line)
    let d = v.get(1)?.sub(first);
    let across = d.dot(n) / d.len();
    if !across.is_finite() || across < MIN_ACROSS {
        return None;
    }
    let back = |s: f64| {
        let p = first.sub(d.scale((start - s) / d.dot(n)));
        Point::new(p.x, p.y)
    };
    if start < s1 {
        let u1 = crossing(&v, n, s1, first)?;
        let mut out = vec![back(s0)];
        out.extend(part(bound, 0.0, u1));
        return Some(out);
    }
    Some(vec![back(s0), back(s1)])
}

/// The pieces of one free end: per lane (right to left) the bounds of its slices (in the
/// working direction; `None` where it is not present) and of its rest after the last line.
type Plan = (Vec<Member>, Vec<Vec<Option<LaneletBounds>>>, Vec<LaneletBounds>);

fn plan(net: &LaneletNetwork, lanes: Vec<Member>) -> Option<Plan> {
    let ways: Vec<(Vec<Point>, Vec<Point>)> = lanes.iter().map(|m| working(&net.lanelets[m.idx], m.rev)).collect();
    let end = |(l, r): &(Vec<Point>, Vec<Point>)| Some((V2::of(l.first()?), V2::of(r.first()?)));
    let ends: Vec<(V2, V2)> = ways.iter().map(end).collect::<Option<_>>()?;
    let (r0, l1) = (ends.first()?.1, ends.last()?.0);
    let c = l1.sub(r0);
    if c.len() < 1e-3 {
        return None;
    }
    let chord = V2::new(c.y, -c.x).scale(1.0 / c.len());
    let points: Vec<V2> = ends.iter().flat_map(|&(l, r)| [l, r]).collect();
    let spread = |n: V2| {
        let s: Vec<f64> = points.iter().map(|p| p.dot(n)).collect();
        s.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
    };
    // an end the section's own slanted cut holds (within ±30°) is left to it
    let base = chord.y.atan2(chord.x);
    let narrowest = (-120i32..=120).map(|k| spread(V2::unit(base + f64::from(k) * 0.25f64.to_radians()))).map(|(lo, hi)| hi - lo).fold(f64::INFINITY, f64::min);
    if narrowest <= STRAIGHT {
        return None;
    }
    let own: Vec<V2> = ends.iter().map(|&(l, r)| l.sub(r)).collect();
    let n = least_slanted(&own, chord);
    let (lo, hi) = spread(n);
    if hi - lo > MAX_SPREAD {
        return None;
    }
    let lines = slicing_lines(points.iter().map(|p| p.dot(n)).collect(), lo - 1e-3, hi + 1e-3);
    let last = *lines.last()?;
    // every lane goes on well beyond the lines
    let beyond = |b: &[Point]| b.last().is_some_and(|p| V2::of(p).dot(n) > last + BEYOND);
    if !ways.iter().all(|(l, r)| beyond(l) && beyond(r)) {
        return None;
    }
    let nearer: Vec<f64> = ends.iter().map(|&(l, r)| l.dot(n).min(r.dot(n))).collect();
    let mut slices: Vec<Vec<Option<LaneletBounds>>> = vec![Vec::new(); lanes.len()];
    for w in lines.windows(2) {
        // a lane with any of its material in the slice is in it (from the slice's first
        // line on: a little longer, never shorter)
        let present: Vec<bool> = nearer.iter().map(|&s| s < w[1] - 1e-6).collect();
        // the lanes present must be side by side
        let runs =
            present.windows(2).filter(|p| p[0] != p[1]).count() + usize::from(present.first() == Some(&true)) + usize::from(present.last() == Some(&true));
        if runs > 2 {
            return None;
        }
        for (k, (way, &here)) in ways.iter().zip(&present).enumerate() {
            let piece = if here { Some(bounds(slab(&way.0, n, w[0], w[1])?, slab(&way.1, n, w[0], w[1])?)?) } else { None };
            slices[k].push(piece);
        }
    }
    let rest_of = |b: &[Point]| -> Option<Vec<Point>> {
        let v: Vec<V2> = b.iter().map(V2::of).collect();
        let u = crossing(&v, n, last, *v.first()?)?;
        Some(part(b, u, (b.len() - 1) as f64))
    };
    let rest: Vec<LaneletBounds> = ways.iter().map(|(l, r)| bounds(rest_of(l)?, rest_of(r)?)).collect::<Option<_>>()?;
    Some((lanes, slices, rest))
}

/// Bounds from the working direction back to the lane's own.
fn own_bounds(b: &LaneletBounds, rev: bool) -> Option<LaneletBounds> {
    if !rev {
        return Some(b.clone());
    }
    let mut left = b.right().to_vec();
    let mut right = b.left().to_vec();
    left.reverse();
    right.reverse();
    LaneletBounds::new(left, right).ok()
}

/// The network with every bowed free end sliced; `None` when there is none.
pub(crate) fn slice(net: &LaneletNetwork) -> Option<Cut> {
    let pos = pos_of(net);
    let keep = intersection_of(net);
    let mut used: BTreeSet<usize> = BTreeSet::new();
    let mut plans: Vec<Plan> = Vec::new();
    for a in 0..net.lanelets.len() {
        for flip in [false, true] {
            if used.contains(&a) || keep.contains_key(&a) {
                continue;
            }
            let Some(lanes) = cross_section(net, &pos, a, flip) else { continue };
            if lanes.iter().any(|m| used.contains(&m.idx) || keep.contains_key(&m.idx)) {
                continue;
            }
            let Some(p) = plan(net, lanes) else { continue };
            used.extend(p.0.iter().map(|m| m.idx));
            plans.push(p);
        }
    }
    if plans.is_empty() {
        return None;
    }
    let mut next = net.max_id() + 1;
    let mut origin = BTreeMap::new();
    let mut lanelets: Vec<Lanelet> = net.lanelets.clone();
    let mut made: Vec<Lanelet> = Vec::new();
    for (lanes, slices, rest) in &plans {
        // ids of each lane's slices (working order; None where absent)
        let mut ids: Vec<Vec<Option<LaneletId>>> = Vec::new();
        for (m, row) in lanes.iter().zip(slices) {
            let mut out = Vec::new();
            for piece in row {
                out.push(match piece {
                    Some(_) => {
                        let id = LaneletId::new(next)?;
                        next += 1;
                        Some(id)
                    }
                    None => None,
                });
            }
            let Some(l) = net.lanelets.get(m.idx) else { continue };
            for id in out.iter().flatten() {
                origin.insert(id.get(), l.id.get());
            }
            ids.push(out);
        }
        for (k, (m, row)) in lanes.iter().zip(slices).enumerate() {
            let Some(l) = net.lanelets.get(m.idx) else { continue };
            let chain: Vec<LaneletId> = ids[k].iter().flatten().copied().chain([l.id]).collect();
            for (j, piece) in row.iter().enumerate() {
                let (Some(bd), Some(id)) = (piece, ids[k][j]) else { continue };
                let Some(bd) = own_bounds(bd, m.rev) else { continue };
                let mut p = Lanelet::new(id, bd, commonroad::LaneletType::Unknown);
                p.lanelet_types = l.lanelet_types.clone();
                p.left_marking = l.left_marking;
                p.right_marking = l.right_marking;
                p.user_one_way = l.user_one_way.clone();
                p.user_bidirectional = l.user_bidirectional.clone();
                // the chain in the working direction: the next piece (or the rest)
                let at = chain.iter().position(|&c| c == id).unwrap_or(0);
                let ahead = chain.get(at + 1).copied();
                let behind = at.checked_sub(1).and_then(|b| chain.get(b)).copied();
                let (before, after) = if m.rev { (ahead, behind) } else { (behind, ahead) };
                p.predecessors = before.into_iter().collect();
                p.successors = after.into_iter().collect();
                // beside the pieces of the same slice
                let nb = |i: usize| {
                    let other = lanes.get(i)?;
                    let dir = if other.rev == m.rev { DrivingDir::Same } else { DrivingDir::Opposite };
                    ids.get(i)?.get(j).copied().flatten().map(|x| Adjacent { lanelet: x, driving_dir: dir })
                };
                let (wl, wr) = (nb(k + 1), k.checked_sub(1).and_then(nb));
                (p.adjacent_left, p.adjacent_right) = if m.rev { (wr, wl) } else { (wl, wr) };
                made.push(p);
            }
            // the rest keeps the lanelet's id, its far end's links and its neighbours
            let Some(own) = rest.get(k).and_then(|b| own_bounds(b, m.rev)) else { continue };
            if let Some(r) = lanelets.get_mut(m.idx) {
                r.bounds = own;
                let last_slice = ids[k].iter().flatten().last().copied();
                if let Some(s) = last_slice {
                    if m.rev {
                        r.successors = vec![s];
                    } else {
                        r.predecessors = vec![s];
                    }
                }
            }
        }
    }
    lanelets.extend(made);
    let network = LaneletNetwork {
        lanelets,
        traffic_signs: net.traffic_signs.clone(),
        traffic_lights: net.traffic_lights.clone(),
        intersections: net.intersections.clone(),
    };
    Some(Cut { network, origin, warnings: Vec::new() })
}
