//! A planning problem's goal as the condition of an ego's `GoalReached` event, where
//! OpenSCENARIO can say it. A goal state holds when the ego is in its region at a time of its
//! interval with a speed (and, in 1.3, a heading) of its intervals; the goal when one of its
//! states holds: one condition group per state and disc.
//!
//! OpenSCENARIO's only region is a disc around a position (1.0 `ReachPositionCondition`, 1.3 a
//! Euclidean `DistanceCondition`), so a region becomes discs inside it: a circle is itself; a
//! rectangle a chain of discs of half its width along its length; a lanelet discs of half its
//! width along its centre line. The discs lie within the region, so the event never fires
//! outside the goal (it may miss a corner of it: a warning says so). A polygon has no such
//! cover here: such a goal state is left out, with a warning. Headings have no condition in
//! 1.0: left out there, with a warning.

use commonroad::{GoalPosition, GoalState, LaneletId, LaneletNetwork, PlanningProblem};

use crate::actions::{after, before, by_entity, condition, rule, show};
use crate::options::OscVersion;
use crate::xml::El;

/// Most discs one region becomes (a longer region gets sparser discs; a warning says so).
const MAX_DISCS: usize = 64;

/// A disc: centre and radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Disc {
    pub x: f64,
    pub y: f64,
    pub r: f64,
}

/// Discs of radius `r` evenly from `a` to `b`, at most `r` apart (sparser beyond
/// [`MAX_DISCS`]).
fn chain(a: (f64, f64), b: (f64, f64), r: f64, out: &mut Vec<Disc>) {
    let len = (b.0 - a.0).hypot(b.1 - a.1);
    let wanted = (len / r).ceil() as usize + 1;
    let n = wanted.clamp(1, MAX_DISCS);
    for i in 0..n {
        let f = if n == 1 { 0.5 } else { i as f64 / (n - 1) as f64 };
        out.push(Disc { x: a.0 + f * (b.0 - a.0), y: a.1 + f * (b.1 - a.1), r });
    }
}

/// Discs along a lanelet's centre line, each as wide as the lanelet where it is.
fn lanelet_discs(network: &LaneletNetwork, id: LaneletId, out: &mut Vec<Disc>) -> Result<(), String> {
    let l = network.lanelets.iter().find(|l| l.id == id).ok_or_else(|| format!("goal lanelet {id} is not in the lanelet network"))?;
    let centre: Vec<(f64, f64, f64)> =
        l.bounds.left().iter().zip(l.bounds.right()).map(|(a, b)| (0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.x - b.x).hypot(a.y - b.y))).collect();
    let length: f64 = centre.windows(2).map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1)).sum();
    let r_min = centre.iter().map(|c| c.2).fold(f64::INFINITY, f64::min).max(0.05);
    // spacing r_min (overlapping discs), or sparser for a long lanelet
    let spacing = (length / (MAX_DISCS - 1) as f64).max(r_min);
    let mut next = 0.0;
    let mut walked = 0.0;
    for w in centre.windows(2) {
        let seg = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
        while next <= walked + seg {
            let f = if seg > 0.0 { (next - walked) / seg } else { 0.0 };
            let lerp = |p: f64, q: f64| p + f * (q - p);
            out.push(Disc { x: lerp(w[0].0, w[1].0), y: lerp(w[0].1, w[1].1), r: lerp(w[0].2, w[1].2) });
            next += spacing;
        }
        walked += seg;
    }
    Ok(())
}

/// The discs of a goal position (and whether they are the region itself), or why there are
/// none.
fn discs(position: &GoalPosition, network: &LaneletNetwork) -> Result<(Vec<Disc>, bool), String> {
    let mut out = Vec::new();
    match position {
        GoalPosition::Circles(cs) => out.extend(cs.iter().map(|c| Disc { x: c.center.x, y: c.center.y, r: c.circle.radius() })),
        GoalPosition::Rectangles(rs) => {
            for r in rs {
                let (l, w) = (r.rectangle.length(), r.rectangle.width());
                let (long, short, h) = if l >= w { (l, w, r.orientation) } else { (w, l, r.orientation + std::f64::consts::FRAC_PI_2) };
                let half = 0.5 * (long - short);
                let (s, c) = h.sin_cos();
                let a = (r.center.x - c * half, r.center.y - s * half);
                let b = (r.center.x + c * half, r.center.y + s * half);
                chain(a, b, 0.5 * short, &mut out);
            }
        }
        GoalPosition::Lanelets(ids) => {
            for id in ids {
                lanelet_discs(network, *id, &mut out)?;
            }
        }
        GoalPosition::Polygons(_) => return Err("a polygon goal region has no OpenSCENARIO condition here".to_string()),
    }
    Ok((out, matches!(position, GoalPosition::Circles(_))))
}

/// The condition groups of `problem`'s goal for the entity `ego`, and the warnings; no group
/// when no goal state could be said.
pub(crate) fn goal_groups(
    problem: &PlanningProblem,
    ego: &str,
    network: &LaneletNetwork,
    dt: f64,
    version: OscVersion,
    warnings: &mut Vec<String>,
) -> Vec<Vec<El>> {
    let mut groups = Vec::new();
    for (i, g) in problem.goal_states.iter().enumerate() {
        let what = format!("planning problem {} goal state {}", problem.id, i + 1);
        let discs = match &g.position {
            None => vec![None],
            Some(p) => match discs(p, network) {
                Ok((d, whole)) => {
                    if !whole {
                        warnings.push(format!(
                            "{what}: its region is written as {} disc(s) inside it (OpenSCENARIO's region is a disc): the event may miss its edges",
                            d.len()
                        ));
                    }
                    d.into_iter().map(Some).collect()
                }
                Err(e) => {
                    warnings.push(format!("{what}: {e}; left out of the end condition"));
                    continue;
                }
            },
        };
        let common = rest(g, ego, dt, version, &what, i, warnings);
        for (k, disc) in discs.into_iter().enumerate() {
            let mut group = Vec::new();
            if let Some(d) = disc {
                group.push(disc_condition(d, ego, version, format!("{ego}_goal{}_region{}", i + 1, k + 1)));
            }
            group.extend(common.iter().cloned());
            groups.push(group);
        }
    }
    groups
}

fn disc_condition(d: Disc, ego: &str, version: OscVersion, name: String) -> El {
    let position = crate::actions::world(d.x, d.y, 0.0);
    let inner = match version {
        OscVersion::V1_0 => El::new("ReachPositionCondition").num("tolerance", d.r).child(position),
        OscVersion::V1_3 => El::new("DistanceCondition")
            .num("value", d.r)
            .attr("freespace", "false")
            .attr("rule", "lessThan")
            .attr("coordinateSystem", "entity")
            .attr("relativeDistanceType", "euclidianDistance")
            .child(position),
    };
    by_entity(name, ego, inner)
}

/// The time, speed and heading conditions of a goal state.
fn rest(g: &GoalState, ego: &str, dt: f64, version: OscVersion, what: &str, i: usize, warnings: &mut Vec<String>) -> Vec<El> {
    let margin = crate::obstacles::TIME_MARGIN * dt;
    let tag = |s: &str| format!("{ego}_goal{}_{s}", i + 1);
    let mut out = Vec::new();
    if g.time.start() > 0 {
        out.push(after(tag("from"), g.time.start() as f64 * dt - margin));
    }
    out.push(before(tag("until"), g.time.end() as f64 * dt + margin));
    if let Some(v) = &g.velocity {
        out.push(by_entity(tag("speed_min"), ego, El::new("SpeedCondition").num("value", v.start()).attr("rule", rule(version, true))));
        out.push(by_entity(tag("speed_max"), ego, El::new("SpeedCondition").num("value", v.end()).attr("rule", rule(version, false))));
    }
    if let Some(o) = &g.orientation {
        let half = 0.5 * (o.end() - o.start());
        match version {
            _ if half >= std::f64::consts::PI => {}
            OscVersion::V1_0 => warnings.push(format!(
                "{what}: OpenSCENARIO 1.0 has no heading condition: the orientation interval [{}, {}] is left out of the end condition",
                show(o.start()),
                show(o.end())
            )),
            OscVersion::V1_3 => out.push(by_entity(
                tag("heading"),
                ego,
                El::new("AngleCondition")
                    .attr("angleType", "heading")
                    .num("angle", 0.5 * (o.start() + o.end()))
                    .num("angleTolerance", half)
                    .attr("coordinateSystem", "world"),
            )),
        }
    }
    out
}

/// The ego's goal event: it sets the flag `flag` once the goal is reached.
pub(crate) fn goal_event(ego: &str, flag: &str, groups: Vec<Vec<El>>, version: OscVersion) -> El {
    let name = goal_event_name(ego);
    El::new("Event")
        .attr("name", name.clone())
        .attr("priority", "parallel")
        .attr("maximumExecutionCount", "1")
        .child(crate::actions::action(format!("{name}_flag"), crate::actions::set_flag(version, flag)))
        .child(crate::actions::trigger("StartTrigger", groups))
}

/// The name of `ego`'s goal event.
pub(crate) fn goal_event_name(ego: &str) -> String {
    format!("{ego}_GoalReached")
}

/// The goal event of `ego` is complete.
pub(crate) fn goal_reached(ego: &str) -> El {
    condition(
        format!("{ego}_goal_reached"),
        El::new("ByValueCondition").child(
            El::new("StoryboardElementStateCondition")
                .attr("storyboardElementType", "event")
                .attr("storyboardElementRef", goal_event_name(ego))
                .attr("state", "completeState"),
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rectangle_becomes_overlapping_discs_inside_it() {
        let mut out = Vec::new();
        // 50 × 10 along x: discs of radius 5 from x = -20 to 20
        chain((-20.0, 0.0), (20.0, 0.0), 5.0, &mut out);
        assert_eq!(out.len(), 9);
        assert!(out.windows(2).all(|w| (w[1].x - w[0].x) <= 5.0 + 1e-12));
        assert!(out.iter().all(|d| d.x.abs() + d.r <= 25.0 + 1e-12));
    }
}
