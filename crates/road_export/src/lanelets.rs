//! The input lanelets made fit for geometry: bounds as plane polylines without repeated
//! points, checked for what the export cannot use (too few points, non-finite values, a
//! length of zero) and for what it can use but a reader may not (a self-intersecting outline).

use crate::vec2::{dedup, length, segments_cross, V2};
use crate::warning::{Subject, Warning};
use commonroad::{Lanelet, LaneletNetwork};

/// Points closer than this are one point (m).
pub(crate) const SAME_POINT: f64 = 1e-6;
/// Lanelets shorter than this are not exported (m).
pub(crate) const MIN_LENGTH: f64 = 1e-3;
/// Outlines with more segments than this are not checked for self-intersection (quadratic).
const MAX_CHECKED_SEGMENTS: usize = 4_000;

/// A lanelet ready for geometry.
#[derive(Debug, Clone)]
pub(crate) struct Prepared {
    pub left: Vec<V2>,
    pub right: Vec<V2>,
    /// Centre line (pairs of bound points), without repeated points.
    pub centre: Vec<V2>,
}

impl Prepared {
    /// The bound on the left of the reference direction (`flipped`: the lanelet drives
    /// against it, so its right bound reversed).
    pub(crate) fn ref_left(&self, flipped: bool) -> Vec<V2> {
        if flipped {
            self.right.iter().rev().copied().collect()
        } else {
            self.left.clone()
        }
    }
    pub(crate) fn ref_right(&self, flipped: bool) -> Vec<V2> {
        if flipped {
            self.left.iter().rev().copied().collect()
        } else {
            self.right.clone()
        }
    }
    pub(crate) fn ref_centre(&self, flipped: bool) -> Vec<V2> {
        if flipped {
            self.centre.iter().rev().copied().collect()
        } else {
            self.centre.clone()
        }
    }
}

fn outline_crosses(left: &[V2], right: &[V2]) -> bool {
    let ring: Vec<V2> = left.iter().chain(right.iter().rev()).copied().collect();
    let n = ring.len();
    if !(4..=MAX_CHECKED_SEGMENTS).contains(&n) {
        return false;
    }
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        for j in i + 2..n {
            if i == 0 && j + 1 == n {
                continue;
            }
            if segments_cross(a, b, ring[j], ring[(j + 1) % n]) {
                return true;
            }
        }
    }
    false
}

/// Prepares one lanelet; `None` (with a warning) when it cannot become a lane.
pub(crate) fn prepare(l: &Lanelet, warnings: &mut Vec<Warning>) -> Option<Prepared> {
    let id = Subject::Lanelet(l.id.get());
    let raw_l: Vec<V2> = l.bounds.left().iter().map(V2::of).collect();
    let raw_r: Vec<V2> = l.bounds.right().iter().map(V2::of).collect();
    if raw_l.iter().chain(&raw_r).any(|p| !p.is_finite()) {
        warnings.push(Warning::new(id, "a bound point is not a finite number; the lanelet is not exported"));
        return None;
    }
    if raw_l.len() < 2 || raw_r.len() < 2 {
        warnings.push(Warning::new(id, "a bound has fewer than 2 points; the lanelet is not exported"));
        return None;
    }
    let centre_raw: Vec<V2> = raw_l.iter().zip(&raw_r).map(|(a, b)| a.lerp(*b, 0.5)).collect();
    let (left, right, centre) = (dedup(&raw_l, SAME_POINT), dedup(&raw_r, SAME_POINT), dedup(&centre_raw, SAME_POINT));
    if length(&centre) < MIN_LENGTH || left.len() < 2 && right.len() < 2 {
        warnings.push(Warning::new(id, "the lanelet has (almost) zero length; it is not exported"));
        return None;
    }
    // a bound shrunk to one point (a lane opening from a point) keeps two equal points
    let two = |v: Vec<V2>, raw: &[V2]| if v.len() < 2 { vec![raw[0], raw[raw.len() - 1]] } else { v };
    let (left, right) = (two(left, &raw_l), two(right, &raw_r));
    if outline_crosses(&left, &right) {
        warnings.push(Warning::new(id, "its outline intersects itself (the bounds cross); exported as given, lane widths clamped at zero where they cross"));
    }
    Some(Prepared { left, right, centre })
}

/// Prepares every lanelet of the network (`None` where it cannot be exported).
pub(crate) fn prepare_all(net: &LaneletNetwork, warnings: &mut Vec<Warning>) -> Vec<Option<Prepared>> {
    net.lanelets.iter().map(|l| prepare(l, warnings)).collect()
}
