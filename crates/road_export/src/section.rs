//! The geometry of one lane section: its reference line (along the middle of the group,
//! perpendicular to the section's first and last cross-section) and every lane border fitted
//! as an offset from it.

use crate::groups::Group;
use crate::lanelets::Prepared;
use crate::offsets::{fit_section, Border, FittedBorders};
use crate::reference::{knots_along, Knot, RefLine};
use crate::vec2::{one_sided_distance, V2};
use crate::warning::{Subject, Warning};
use commonroad::LaneletNetwork;
use std::f64::consts::FRAC_PI_2;

/// How far the reference line may stray from the group's middle before it gets a knot (m);
/// the lane offsets absorb the rest.
const REFERENCE_TOL: f64 = 0.1;
/// A cut more oblique than this (rad from perpendicular) is not followed: the section
/// starts perpendicular to its lanes instead, with a warning.
const MAX_SLANT: f64 = 1.2;
/// Two bounds closer than this everywhere are one border polyline (m).
const SAME_BORDER: f64 = 1e-9;

/// A fitted lane section.
#[derive(Debug, Clone)]
pub struct SectionGeom {
    pub line: RefLine,
    /// Borders 0 (leftmost) ..= members (rightmost).
    pub fitted: FittedBorders,
}

fn heading_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * std::f64::consts::PI);
    if d > std::f64::consts::PI {
        2.0 * std::f64::consts::PI - d
    } else {
        d
    }
}

/// Heading perpendicular to the cut from `right` to `left`, or `fallback` when the cut has no
/// length or is too oblique.
fn cut_heading(left: Option<V2>, right: Option<V2>, fallback: f64) -> (f64, bool) {
    match (left, right) {
        (Some(l), Some(r)) if l.dist(r) > 1e-3 => {
            let h = l.sub(r).angle() - FRAC_PI_2;
            if heading_diff(h, fallback) <= MAX_SLANT {
                (h, true)
            } else {
                (fallback, false)
            }
        }
        _ => (fallback, true),
    }
}

/// The borders of a group as polylines in its reference direction (a shared border holds
/// both neighbours' bounds unless they are the same).
pub fn border_polylines(g: &Group, prep: &[Option<Prepared>]) -> Vec<Vec<Vec<V2>>> {
    let p = |k: usize| g.members.get(k).and_then(|m| prep.get(m.idx).and_then(Option::as_ref).map(|pr| (pr, m.flipped)));
    let n = g.members.len();
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let mut set = Vec::new();
        if let Some((pr, f)) = k.checked_sub(1).and_then(p) {
            set.push(pr.ref_right(f));
        }
        if let Some((pr, f)) = p(k) {
            let l = pr.ref_left(f);
            let same = set.first().is_some_and(|r: &Vec<V2>| r.len() == l.len() && r.iter().zip(&l).all(|(a, b)| a.dist(*b) <= SAME_BORDER));
            if !same {
                set.push(l);
            }
        }
        out.push(set);
    }
    out
}

/// Builds the section of group `g`; `start`, if given, is where its reference line must
/// begin (the end of the previous section of the same road).
pub fn build(g: &Group, net: &LaneletNetwork, prep: &[Option<Prepared>], tol: f64, start: Option<Knot>, warnings: &mut Vec<Warning>) -> Option<SectionGeom> {
    let borders = border_polylines(g, prep);
    let n = g.members.len();
    let id_of = |k: usize| g.members.get(k).and_then(|m| net.lanelets.get(m.idx)).map_or(0, |l| l.id.get());
    let middle: Vec<V2> = if n % 2 == 1 {
        let m = g.members.get(n / 2)?;
        prep.get(m.idx)?.as_ref()?.ref_centre(m.flipped)
    } else {
        borders.get(n / 2)?.first()?.clone()
    };
    let (first, last) = (*middle.first()?, *middle.last()?);
    let dir0 = middle.get(1).map_or(0.0, |q| q.sub(first).angle());
    let dir1 = middle.len().checked_sub(2).and_then(|i| middle.get(i)).map_or(dir0, |q| last.sub(*q).angle());
    let ends = |at_end: bool| {
        let pick = |set: &Vec<Vec<V2>>| set.first().and_then(|b| if at_end { b.last().copied() } else { b.first().copied() });
        (borders.first().and_then(pick), borders.last().and_then(pick))
    };
    let (l0, r0) = ends(false);
    let (l1, r1) = ends(true);
    let (h0, ok0) = cut_heading(l0, r0, dir0);
    let (h1, ok1) = cut_heading(l1, r1, dir1);
    for (ok, at) in [(ok0, "start"), (ok1, "end")] {
        if !ok {
            warnings.push(Warning::new(
                Subject::Lanelet(id_of(0)),
                format!(
                    "the {at} of its road is cut more than {:.0}° from perpendicular; the lane section {at}s perpendicular to the lanes instead",
                    MAX_SLANT.to_degrees()
                ),
            ));
        }
    }
    let start_knot = start.unwrap_or(Knot { p: first, hdg: h0 });
    let end_knot = Knot { p: last, hdg: h1 };
    let knots = knots_along(&middle, start_knot, end_knot, REFERENCE_TOL, middle.len() + 2);
    let line = RefLine::through(&knots);
    if !(line.length > 0.0) {
        warnings.push(Warning::new(Subject::Lanelet(id_of(0)), "its road has no length; not exported"));
        return None;
    }
    let projected: Vec<Vec<Border>> = borders.iter().map(|set| set.iter().map(|b| Border::new(b, &line)).collect()).collect();
    for (k, set) in projected.iter().enumerate() {
        for b in set {
            if b.backwards > 0.01 {
                let who = id_of(k.min(n.saturating_sub(1)));
                warnings.push(Warning::new(
                    Subject::Lanelet(who),
                    format!("a bound runs {:.2} m backwards along its road's reference line (a very tight bend or a folded bound); the lane border there is approximate", b.backwards),
                ));
            }
        }
    }
    let breaks: Vec<f64> = line.knots_s.iter().copied().filter(|&s| s > 0.0 && s < line.length).collect();
    let fitted = fit_section(&line, &projected, 0.0, line.length, &breaks, tol);
    // how far the written ends are from the bounds' own end points
    let (p0, p1) = (line.pose(0.0), line.pose(line.length));
    for (k, set) in borders.iter().enumerate() {
        for b in set {
            let off = |pose: &crate::reference::Pose, q: Option<&V2>| q.map_or(0.0, |q| q.sub(pose.p).dot(V2::unit(pose.hdg)).abs());
            let worst = off(&p0, b.first()).max(off(&p1, b.last()));
            if worst > 0.02 {
                warnings.push(Warning::new(
                    Subject::Lanelet(id_of(k.min(n.saturating_sub(1)))),
                    format!("a bound ends {worst:.3} m off its road's cross-section (the lanelets side by side do not start or end on one line); the lane border ends on the cross-section"),
                ));
            }
        }
    }
    let _ = one_sided_distance;
    Some(SectionGeom { line, fitted })
}
