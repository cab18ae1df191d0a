//! The geometry of one lane section: its reference line (along the middle of the group,
//! perpendicular to the section's first and last cross-section) and every lane border fitted
//! as an offset from it.

use crate::groups::Group;
use crate::lanelets::Prepared;
use crate::offsets::{fit_section, Border, FittedBorders};
use crate::reference::{knots_along, Knot, RefLine};
use crate::vec2::{SegmentIndex, V2};
use crate::warning::{Subject, Warning};
use commonroad::LaneletNetwork;
use std::f64::consts::FRAC_PI_2;

/// How far the reference line may stray from the group's middle before it gets a knot (m),
/// tried in this order until its normals do not cross inside the road; the lane offsets
/// absorb the rest.
const REFERENCE_TOLS: [f64; 5] = [0.1, 0.4, 1.2, 3.0, 8.0];
/// A border folds where 1 − κ·t falls below this (the offset curve's speed along s).
const MIN_SPEED: f64 = 0.15;

/// How much the fitted borders fold: 0 when none does, else the worst shortfall of 1 − κ·t
/// below [`MIN_SPEED`] (sampled every 0.25 m).
fn folding(line: &RefLine, fitted: &crate::offsets::FittedBorders) -> f64 {
    let n = ((line.length / 0.25).ceil() as usize).clamp(2, 40_000);
    let mut worst: f64 = 0.0;
    for k in 0..=n {
        let s = line.length * k as f64 / n as f64;
        let kappa = line.pose(s).curvature;
        let i = fitted.pieces.partition_point(|&p| p <= s).saturating_sub(1);
        for border in &fitted.cubics {
            if let Some(c) = border.get(i) {
                worst = worst.max(MIN_SPEED - (1.0 - kappa * c.value(s)));
            }
        }
    }
    worst
}
/// A cut more oblique than this (rad from perpendicular) is not followed: the section
/// starts perpendicular to its lanes instead, with a warning.
const MAX_SLANT: f64 = 1.2;
/// Two bounds closer than this everywhere are one border polyline (m).
const SAME_BORDER: f64 = 1e-9;

/// A fitted lane section.
#[derive(Debug, Clone)]
pub(crate) struct SectionGeom {
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

/// Largest distance of a fitted border (sampled every 0.5 m) from its bound polylines: the
/// fit is against the offsets of projected vertices, so a vertex projected onto the wrong
/// part of the line would go unnoticed by the fit itself.
fn off_bounds(line: &RefLine, fitted: &crate::offsets::FittedBorders, borders: &[Vec<Vec<V2>>]) -> f64 {
    let n = ((line.length / 0.5).ceil() as usize).clamp(2, 40_000);
    let mut worst: f64 = 0.0;
    for (k, set) in borders.iter().enumerate() {
        let (Some(cubics), false) = (fitted.cubics.get(k), set.is_empty()) else { continue };
        let index = SegmentIndex::new(set.iter().map(Vec::as_slice), 1.0);
        for j in 0..=n {
            let s = line.length * j as f64 / n as f64;
            let i = fitted.pieces.partition_point(|&p| p <= s).saturating_sub(1);
            if let Some(c) = cubics.get(i) {
                worst = worst.max(index.distance(line.pose(s).at_t(c.value(s)), 2.0));
            }
        }
    }
    worst
}

/// The heading near `base` (±30°, never more than [`MAX_SLANT`] from the lanes' `dir`)
/// whose cross-section holds `points` in the narrowest strip: ends that are not quite on
/// one line then stick out of the section's cut as little as possible.
fn narrowest(points: &[V2], base: f64, dir: f64) -> f64 {
    let spread = |h: f64| {
        let u = V2::unit(h);
        let (lo, hi) = points.iter().map(|p| p.dot(u)).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
        hi - lo
    };
    let mut best = (spread(base), base);
    for k in -120i32..=120 {
        let h = base + f64::from(k) * 0.25f64.to_radians();
        if heading_diff(h, dir) > MAX_SLANT {
            continue;
        }
        // only a real gain turns the cut (noise would pick any angle for collinear ends)
        let s = spread(h);
        if s < best.0 - 1e-3 {
            best = (s, h);
        }
    }
    best.1
}

/// The borders of a group as polylines in its reference direction (a shared border holds
/// both neighbours' bounds unless they are the same).
pub(crate) fn border_polylines(g: &Group, prep: &[Option<Prepared>]) -> Vec<Vec<Vec<V2>>> {
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
pub(crate) fn build(
    g: &Group,
    net: &LaneletNetwork,
    prep: &[Option<Prepared>],
    tol: f64,
    start: Option<Knot>,
    warnings: &mut Vec<Warning>,
) -> Option<SectionGeom> {
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
    let firsts: Vec<V2> = borders.iter().flatten().filter_map(|b| b.first().copied()).collect();
    let lasts: Vec<V2> = borders.iter().flatten().filter_map(|b| b.last().copied()).collect();
    let (h0, ok0) = cut_heading(l0, r0, dir0);
    let (h1, ok1) = cut_heading(l1, r1, dir1);
    let (h0, h1) = (narrowest(&firsts, h0, dir0), narrowest(&lasts, h1, dir1));
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
    // the cross-sections are moved out until no bound starts before (ends after) them: the
    // lanes then cover every bound, at worst a few centimetres longer than it
    let (t0, t1) = (V2::unit(h0), V2::unit(h1));
    let back0 = firsts.iter().map(|p| -p.sub(first).dot(t0)).fold(0.0, f64::max);
    let ahead1 = lasts.iter().map(|p| p.sub(last).dot(t1)).fold(0.0, f64::max);
    for (d, at) in [(back0, "start"), (ahead1, "end")] {
        if d > 0.05 {
            warnings.push(Warning::new(
                Subject::Lanelet(id_of(0)),
                format!("the lanelets of its road do not {at} on one line; the lane section {at}s {d:.2} m further out, so some lanes are that much longer"),
            ));
        }
    }
    let start_knot = start.unwrap_or(Knot { p: first.sub(t0.scale(back0)), hdg: h0 });
    let end_knot = Knot { p: last.add(t1.scale(ahead1)), hdg: h1 };
    let mut middle = middle;
    if let Some(m) = middle.first_mut() {
        *m = start_knot.p;
    }
    if let Some(m) = middle.last_mut() {
        *m = end_knot.p;
    }
    // a line that follows the middle closely can bend tighter than the road is wide (its
    // normals would cross inside the road): then it is allowed to cut the bend more
    let mut best: Option<(SectionGeom, f64)> = None;
    // between parallel cuts, a straight line square to both is a last resort: the lanes may
    // cross it obliquely (a thin slice of a zig-zag joint, see `joints`), the lane offsets
    // then carry the sideways drift instead of a reference line bent back and forth
    let straight = (heading_diff(h0, h1) < 1e-6).then(|| {
        let along = end_knot.p.sub(start_knot.p).dot(t0);
        vec![start_knot, Knot { p: start_knot.p.add(t0.scale(along)), hdg: h1 }]
    });
    let candidates = REFERENCE_TOLS.iter().map(Some).chain(straight.iter().map(|_| None));
    for ref_tol in candidates {
        let knots = match (ref_tol, &straight) {
            (Some(&tol), _) => knots_along(&middle, start_knot, end_knot, tol, middle.len() + 2),
            (None, Some(k)) => k.clone(),
            (None, None) => continue,
        };
        let line = RefLine::through(&knots);
        if line.length.is_nan() || line.length <= 0.0 {
            continue;
        }
        let projected: Vec<Vec<Border>> = borders.iter().map(|set| set.iter().map(|b| Border::new(b, &line)).collect()).collect();
        let backwards = projected.iter().flatten().map(|b| b.backwards).fold(0.0, f64::max);
        let breaks: Vec<f64> = line.knots_s.iter().copied().filter(|&s| s > 0.0 && s < line.length).collect();
        let fitted = fit_section(&line, &projected, 0.0, line.length, &breaks, tol);
        let fold = folding(&line, &fitted).max(backwards - 0.01).max(off_bounds(&line, &fitted, &borders) - 2.0 * tol);
        let better = best.as_ref().is_none_or(|(_, f)| fold < *f);
        if better {
            best = Some((SectionGeom { line, fitted }, fold));
        }
        if fold <= 0.0 {
            break;
        }
    }
    let Some((geom, fold)) = best else {
        warnings.push(Warning::new(Subject::Lanelet(id_of(0)), "its road has no length; not exported"));
        return None;
    };
    if fold > 0.0 {
        warnings.push(Warning::new(
            Subject::Lanelet(id_of(0)),
            "its road bends tighter than it is wide (the lane borders fold over the reference line); the borders there are approximate",
        ));
    }
    let (line, fitted) = (geom.line, geom.fitted);
    if fitted.max_error > tol {
        warnings.push(Warning::new(
            Subject::Lanelet(id_of(0)),
            format!("its lane borders could be fitted only within {:.3} m of the bounds (asked: {tol} m)", fitted.max_error),
        ));
    }
    Some(SectionGeom { line, fitted })
}
