//! Planning problems carried by an OpenSCENARIO scenario: `osc2cr export` writes each
//! CommonRoad planning problem into a property of its ego entity ([`PLANNING_PROBLEM_PROPERTY`],
//! the problem as CommonRoad 2020a XML with copies of the lanelets its goals name). Converting
//! such a scenario gives those problems back instead of deriving one from the ego's run, and the
//! entities that carry them are egos, not obstacles (in the CommonRoad scenario they came from
//! they were none).
//!
//! A goal's lanelets are found again in the converted map by their geometry (its lanelets have
//! other ids): a lanelet of the map is taken for a carried one when the middle of its centre
//! line lies inside the carried lanelet and runs its way. A carried lanelet no map lanelet
//! matches makes the goal its outline polygons, with a warning.

use commonroad::{GoalPosition, Lanelet, LaneletId, LaneletNetwork, PlanningProblem, Point, Polygon};
use openscenario::{Entity, EntityObject};

/// The property of an entity that carries a CommonRoad planning problem (`osc2cr export`'s).
pub const PLANNING_PROBLEM_PROPERTY: &str = "osc2cr:commonRoadPlanningProblem";

/// A planning problem carried by an entity.
#[derive(Debug, Clone, PartialEq)]
pub struct Carried {
    pub entity: String,
    pub problem: PlanningProblem,
    /// The lanelets its goals name, as they were where the problem came from.
    pub lanelets: Vec<Lanelet>,
}

fn property<'a>(e: &'a Entity, name: &str) -> Option<&'a str> {
    match &e.object {
        EntityObject::Vehicle(v) => v.properties.get(name),
        EntityObject::Pedestrian(p) => p.properties.get(name),
        EntityObject::MiscObject(m) => m.properties.get(name),
        EntityObject::External { .. } => None,
    }
}

/// The planning problems the scenario's entities carry, in entity order; a property that is
/// not a planning problem is a warning.
pub fn carried_problems(entities: &[Entity], warnings: &mut Vec<String>) -> Vec<Carried> {
    let mut out = Vec::new();
    for e in entities {
        let Some(text) = property(e, PLANNING_PROBLEM_PROPERTY) else { continue };
        let where_ = std::path::PathBuf::from(format!("entity {:?} property {PLANNING_PROBLEM_PROPERTY}", e.name));
        match commonroad::xml::read_planning_problem_str(text, &where_) {
            Ok(r) => {
                warnings.extend(r.warnings.iter().map(ToString::to_string));
                out.push(Carried { entity: e.name.clone(), problem: r.problem, lanelets: r.lanelets });
            }
            Err(err) => warnings.push(format!("{err}: not read; the entity is converted as any other")),
        }
    }
    out
}

/// Whether `p` lies inside the polygon `ring` (even-odd rule).
fn inside(p: (f64, f64), ring: &[Point]) -> bool {
    let mut c = false;
    let n = ring.len();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + n - 1) % n]);
        if (a.y > p.1) != (b.y > p.1) && p.0 < (b.x - a.x) * (p.1 - a.y) / (b.y - a.y) + a.x {
            c = !c;
        }
    }
    c
}

/// A lanelet's outline: its right bound, then its left bound backwards.
fn outline(l: &Lanelet) -> Vec<Point> {
    l.bounds.right().iter().chain(l.bounds.left().iter().rev()).copied().collect()
}

/// The point half way along a lanelet's centre line and the direction there.
fn middle(l: &Lanelet) -> Option<((f64, f64), (f64, f64))> {
    let c: Vec<(f64, f64)> = l.bounds.left().iter().zip(l.bounds.right()).map(|(a, b)| (0.5 * (a.x + b.x), 0.5 * (a.y + b.y))).collect();
    let lengths: Vec<f64> = c.windows(2).map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1)).collect();
    let half = 0.5 * lengths.iter().sum::<f64>();
    let mut walked = 0.0;
    for (w, len) in c.windows(2).zip(&lengths) {
        if *len > 0.0 && walked + len >= half {
            let f = (half - walked) / len;
            let dir = ((w[1].0 - w[0].0) / len, (w[1].1 - w[0].1) / len);
            return Some(((w[0].0 + f * (w[1].0 - w[0].0), w[0].1 + f * (w[1].1 - w[0].1)), dir));
        }
        walked += len;
    }
    None
}

/// The general direction of a lanelet (first to last centre point).
fn direction(l: &Lanelet) -> (f64, f64) {
    let c = |i: usize| {
        let (a, b) = (l.bounds.left()[i], l.bounds.right()[i]);
        (0.5 * (a.x + b.x), 0.5 * (a.y + b.y))
    };
    let n = l.bounds.len();
    if n < 2 {
        return (0.0, 0.0);
    }
    let (p, q) = (c(0), c(n - 1));
    (q.0 - p.0, q.1 - p.1)
}

/// The lanelets of `network` that lie in the carried lanelet `original`, in network order.
fn matches(original: &Lanelet, network: &LaneletNetwork) -> Vec<LaneletId> {
    let ring = outline(original);
    let dir = direction(original);
    network.lanelets.iter().filter(|l| middle(l).is_some_and(|(p, d)| inside(p, &ring) && d.0 * dir.0 + d.1 * dir.1 > 0.0)).map(|l| l.id).collect()
}

/// The carried problem with its goal lanelets found again in `network` (`None`: no map).
pub fn retarget(c: &Carried, network: Option<&LaneletNetwork>, warnings: &mut Vec<String>) -> PlanningProblem {
    let mut problem = c.problem.clone();
    for (k, g) in problem.goal_states.iter_mut().enumerate() {
        let Some(GoalPosition::Lanelets(ids)) = &g.position else { continue };
        let originals: Vec<&Lanelet> = ids.iter().filter_map(|id| c.lanelets.iter().find(|l| l.id == *id)).collect();
        let found: Option<Vec<LaneletId>> = match network {
            Some(net) if originals.len() == ids.len() => {
                let per: Vec<Vec<LaneletId>> = originals.iter().map(|l| matches(l, net)).collect();
                per.iter().all(|m| !m.is_empty()).then(|| {
                    let mut all: Vec<LaneletId> = Vec::new();
                    for id in per.into_iter().flatten() {
                        if !all.contains(&id) {
                            all.push(id);
                        }
                    }
                    all
                })
            }
            _ => None,
        };
        match found {
            Some(all) => g.position = Some(GoalPosition::Lanelets(all)),
            None => {
                let polygons: Vec<Polygon> = originals.iter().filter_map(|l| Polygon::new(outline(l)).ok()).collect();
                warnings.push(format!(
                    "planning problem {} (entity {:?}) goal state {}: its goal lanelets are not found in the converted map; the goal is their outlines",
                    c.problem.id,
                    c.entity,
                    k + 1
                ));
                g.position = if polygons.is_empty() { None } else { Some(GoalPosition::Polygons(polygons)) };
            }
        }
    }
    problem
}

#[cfg(test)]
mod tests {
    use super::*;
    use commonroad::{GoalState, LaneletBounds, LaneletType, PlanningInitialState, PlanningProblemId, TimeInterval};

    fn lanelet(id: u64, x0: f64, x1: f64, y0: f64) -> Lanelet {
        let line = |y: f64| vec![Point::new(x0, y), Point::new(x1, y)];
        let bounds = LaneletBounds::new(line(y0 + 3.0), line(y0)).unwrap_or_else(|e| panic!("{e}"));
        Lanelet::new(LaneletId::new(id).unwrap_or_else(|| unreachable!()), bounds, LaneletType::Urban)
    }

    fn carried(goal_lanelet: Lanelet) -> Carried {
        let problem = PlanningProblem {
            id: PlanningProblemId::new(9).unwrap_or_else(|| unreachable!()),
            initial_state: PlanningInitialState { x: 0.0, y: 1.5, orientation: 0.0, velocity: 5.0, yaw_rate: 0.0, slip_angle: 0.0, acceleration: None },
            goal_states: vec![GoalState {
                time: TimeInterval::new(0, 10).unwrap_or_else(|e| panic!("{e}")),
                position: Some(GoalPosition::Lanelets(vec![goal_lanelet.id])),
                orientation: None,
                velocity: None,
            }],
        };
        Carried { entity: "Ego".into(), problem, lanelets: vec![goal_lanelet] }
    }

    #[test]
    fn goal_lanelets_are_found_again_by_geometry() {
        // the carried goal lanelet 7 (x 0..100, y 0..3) is split in the converted map into
        // lanelets 40 and 41; 42 lies beside it, 43 runs the other way over it
        let mut reversed = lanelet(43, 100.0, 0.0, 3.0);
        reversed.bounds = LaneletBounds::new(reversed.bounds.right().to_vec(), reversed.bounds.left().to_vec()).unwrap_or_else(|e| panic!("{e}"));
        let network = LaneletNetwork {
            lanelets: vec![lanelet(40, 0.0, 60.0, 0.0), lanelet(41, 60.0, 100.0, 0.0), lanelet(42, 0.0, 100.0, 3.0), reversed],
            ..Default::default()
        };
        let mut warnings = Vec::new();
        let p = retarget(&carried(lanelet(7, 0.0, 100.0, 0.0)), Some(&network), &mut warnings);
        let ids: Vec<u64> = match &p.goal_states[0].position {
            Some(GoalPosition::Lanelets(ids)) => ids.iter().map(|i| i.get()).collect(),
            other => panic!("{other:?}"),
        };
        assert_eq!(ids, vec![40, 41]);
        assert!(warnings.is_empty(), "{warnings:?}");
        // no map: the goal is the lanelet's outline, with a warning
        let p = retarget(&carried(lanelet(7, 0.0, 100.0, 0.0)), None, &mut warnings);
        assert!(matches!(&p.goal_states[0].position, Some(GoalPosition::Polygons(v)) if v.len() == 1 && v[0].points().len() == 4));
        assert_eq!(warnings.len(), 1);
    }
}
