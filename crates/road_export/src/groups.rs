//! Lanelets side by side become the lanes of one lane section: adjacency (of either driving
//! direction) whose shared bound really is shared — both ends and the whole length within
//! [`SHARED`] — chains lanelets left to right. The chain's driving directions must change
//! at most once (OpenDRIVE puts one direction left of the centre line and the other right);
//! where they change again, or where adjacency is not backed by a shared bound, the chain is
//! cut and the adjacency lost, with a warning naming the lanelets.

use crate::lanelets::Prepared;
use crate::vec2::{one_sided_distance, V2};
use crate::warning::{Subject, Warning};
use commonroad::{DrivingDir, LaneletNetwork};
use std::collections::BTreeMap;

/// Largest distance (m) between two bounds that count as one shared border.
pub(crate) const SHARED: f64 = 0.1;

/// A lanelet in a section, and whether it drives against the section's reference direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Member {
    pub idx: usize,
    pub flipped: bool,
}

/// Lanelets side by side, left to right in the reference direction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Group {
    pub members: Vec<Member>,
    /// Left-hand traffic: the lanes along the reference direction are on the left.
    pub lht: bool,
    /// Number of members left of the centre line.
    pub centre: usize,
}

impl Group {
    /// Reverses the reference direction.
    pub(crate) fn flip(&mut self) {
        self.members.reverse();
        for m in &mut self.members {
            m.flipped = !m.flipped;
        }
        self.centre = self.members.len() - self.centre;
    }
}

/// Neighbour of a lanelet on one of its own sides: (index, drives the opposite way).
type Nb = Option<(usize, bool)>;

/// How far apart (m) the ends of a shared bound may be along the road (one lanelet a little
/// longer than its neighbour: the section's cross-section covers both).
pub(crate) const SHARED_ENDS: f64 = 0.5;

/// The polyline with its end segments extended by `by` m.
fn extended(line: &[V2], by: f64) -> Vec<V2> {
    let mut out = line.to_vec();
    if let (Some(&a), Some(&b)) = (line.first(), line.get(1)) {
        let d = a.sub(b);
        if d.len() > 0.0 {
            out.insert(0, a.add(d.scale(by / d.len())));
        }
    }
    if let (Some(&a), Some(&b)) = (line.last(), line.len().checked_sub(2).and_then(|i| line.get(i))) {
        let d = a.sub(b);
        if d.len() > 0.0 {
            out.push(a.add(d.scale(by / d.len())));
        }
    }
    out
}

/// Whether `a`'s bound `mine` and the neighbour's bound `theirs` (both in `a`'s direction)
/// are one border: within [`SHARED`] of each other sideways, their ends close.
fn shared(mine: &[V2], theirs: &[V2]) -> bool {
    let ends = |x: &[V2], y: &[V2]| match (x.first(), y.first(), x.last(), y.last()) {
        (Some(a), Some(b), Some(c), Some(d)) => a.dist(*b).max(c.dist(*d)),
        _ => f64::INFINITY,
    };
    ends(mine, theirs) <= SHARED_ENDS
        && one_sided_distance(mine, &extended(theirs, SHARED_ENDS), 1.0, 2.0 * SHARED) <= SHARED
        && one_sided_distance(theirs, &extended(mine, SHARED_ENDS), 1.0, 2.0 * SHARED) <= SHARED
}

/// Verified neighbours of every lanelet, (left, right) on its own sides.
fn neighbours(net: &LaneletNetwork, prep: &[Option<Prepared>], pos: &BTreeMap<u64, usize>, warnings: &mut Vec<Warning>) -> Vec<(Nb, Nb)> {
    let mut nb: Vec<(Nb, Nb)> = vec![(None, None); net.lanelets.len()];
    for (i, l) in net.lanelets.iter().enumerate() {
        let Some(me) = prep.get(i).and_then(Option::as_ref) else { continue };
        for (left, adj) in [(true, l.adjacent_left), (false, l.adjacent_right)] {
            let Some(adj) = adj else { continue };
            let Some(&j) = pos.get(&adj.lanelet.get()) else {
                warnings.push(Warning::new(Subject::Lanelet(l.id.get()), format!("adjacent lanelet {} does not exist; adjacency dropped", adj.lanelet.get())));
                continue;
            };
            let Some(other) = prep.get(j).and_then(Option::as_ref) else { continue };
            let opposite = adj.driving_dir == DrivingDir::Opposite;
            let mine = if left { &me.left } else { &me.right };
            // the neighbour's bound on my side, in my direction
            let theirs: Vec<V2> = match (left, opposite) {
                (true, false) => other.right.clone(),
                (false, false) => other.left.clone(),
                (true, true) => other.left.iter().rev().copied().collect(),
                (false, true) => other.right.iter().rev().copied().collect(),
            };
            if j == i || !shared(mine, &theirs) {
                warnings.push(Warning::new(
                    Subject::Lanelet(l.id.get()),
                    format!(
                        "adjacent {} lanelet {} does not share its bound over the whole length (within {SHARED} m); they become lanes of different roads and the adjacency is not written",
                        if left { "left" } else { "right" },
                        adj.lanelet.get()
                    ),
                ));
                continue;
            }
            if left {
                nb[i].0 = Some((j, opposite));
            } else {
                nb[i].1 = Some((j, opposite));
            }
            // the neighbour's side facing me, unless it names another lanelet there
            // opposite: my left faces its left; same: my left faces its right
            let Some(theirs) = nb.get_mut(j) else { continue };
            let back = if opposite == left { &mut theirs.0 } else { &mut theirs.1 };
            if back.is_none() {
                *back = Some((i, opposite));
            }
        }
    }
    nb
}

/// Groups every exportable lanelet into sections.
pub(crate) fn group(net: &LaneletNetwork, prep: &[Option<Prepared>], warnings: &mut Vec<Warning>) -> Vec<Group> {
    let pos: BTreeMap<u64, usize> = net.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let nb = neighbours(net, prep, &pos, warnings);
    let id_of = |i: usize| net.lanelets.get(i).map_or(0, |l| l.id.get());
    let mut taken = vec![false; net.lanelets.len()];
    let mut groups = Vec::new();
    // lowest id first, so the result does not depend on the order of the file
    let mut order: Vec<usize> = (0..net.lanelets.len()).filter(|&i| prep.get(i).is_some_and(Option::is_some)).collect();
    order.sort_by_key(|&i| id_of(i));
    for seed in order {
        if taken[seed] {
            continue;
        }
        taken[seed] = true;
        let mut members = vec![Member { idx: seed, flipped: false }];
        // walk to the reference left, then to the reference right
        for to_left in [true, false] {
            let mut cur = Member { idx: seed, flipped: false };
            loop {
                let (l, r) = nb[cur.idx];
                let step = if to_left != cur.flipped { l } else { r };
                let Some((j, opposite)) = step else { break };
                if taken[j] {
                    break;
                }
                // it must name me back on the side facing me (or nothing there)
                let next = Member { idx: j, flipped: cur.flipped != opposite };
                let (jl, jr) = nb[j];
                let facing = if to_left != next.flipped { jr } else { jl };
                if facing.is_some_and(|(k, _)| k != cur.idx) {
                    break;
                }
                taken[j] = true;
                if to_left {
                    members.insert(0, next);
                } else {
                    members.push(next);
                }
                cur = next;
            }
        }
        groups.extend(split_directions(members, net, warnings));
    }
    groups
}

/// Cuts a chain where its driving direction changes a second time; orients each part.
fn split_directions(members: Vec<Member>, net: &LaneletNetwork, warnings: &mut Vec<Warning>) -> Vec<Group> {
    let mut out = Vec::new();
    let mut part: Vec<Member> = Vec::new();
    let mut changes = 0;
    for m in members {
        if let Some(last) = part.last() {
            if last.flipped != m.flipped {
                changes += 1;
                if changes == 2 {
                    let (a, b) = (net.lanelets.get(last.idx).map_or(0, |l| l.id.get()), net.lanelets.get(m.idx).map_or(0, |l| l.id.get()));
                    warnings.push(Warning::new(
                        Subject::Lanelet(b),
                        format!("the driving direction changes a second time across the road at its neighbour {a} (OpenDRIVE has one centre line per road); they become different roads and the adjacency is not written"),
                    ));
                    out.push(orient(std::mem::take(&mut part)));
                    changes = 0;
                }
            }
        }
        part.push(m);
    }
    if !part.is_empty() {
        out.push(orient(part));
    }
    out
}

/// The group of a chain with at most one change of direction, along its first lane's way if
/// it has one direction.
fn orient(members: Vec<Member>) -> Group {
    let n = members.len();
    let against_first = members.first().is_some_and(|m| m.flipped);
    let change = members.windows(2).position(|w| w[0].flipped != w[1].flipped).map(|p| p + 1);
    let mut g = match change {
        // one direction: all along the reference, right lanes of right-hand traffic
        None => Group { members, lht: false, centre: 0 },
        // against on the left: right-hand traffic
        Some(c) if against_first => Group { members, lht: false, centre: c },
        Some(c) => Group { members, lht: true, centre: c },
    };
    if change.is_none() && against_first {
        g.flip();
        g.centre = 0;
    }
    debug_assert!(g.centre <= n);
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_of_chains() {
        let m = |idx, flipped| Member { idx, flipped };
        let g = orient(vec![m(0, true), m(1, false), m(2, false)]);
        assert_eq!((g.lht, g.centre), (false, 1));
        let g = orient(vec![m(0, false), m(1, true)]);
        assert_eq!((g.lht, g.centre), (true, 1));
        let g = orient(vec![m(0, true), m(1, true)]);
        assert_eq!((g.lht, g.centre), (false, 0));
        assert_eq!(g.members, vec![m(1, false), m(0, false)]);
    }
}
