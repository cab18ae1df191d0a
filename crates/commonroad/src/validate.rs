//! Whole-file consistency checks that the types alone cannot guarantee: unique ids, resolving
//! references, traffic signs referenced by a lanelet, consecutive trajectories, non-empty lists
//! the XSD requires, finite numbers. Problems are returned as data, never printed.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use crate::geometry::{AbsoluteShape, Point, Shape};
use crate::ids::LaneletId;
use crate::lanelet::{DrivingDir, Lanelet};
use crate::planning::{GoalPosition, PlanningProblemSet};
use crate::scenario::Scenario;
use crate::sign_ids::is_xsd_traffic_sign_id;
use crate::xml::is_written_positive;

/// The kind of element a problem is about (or that an id belongs to).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ElementKind {
    Scenario,
    Lanelet,
    TrafficSign,
    TrafficLight,
    Intersection,
    Incoming,
    StaticObstacle,
    DynamicObstacle,
    EnvironmentObstacle,
    PlanningProblem,
}

impl ElementKind {
    /// The XML element name.
    pub fn as_str(self) -> &'static str {
        match self {
            ElementKind::Scenario => "commonRoad",
            ElementKind::Lanelet => "lanelet",
            ElementKind::TrafficSign => "trafficSign",
            ElementKind::TrafficLight => "trafficLight",
            ElementKind::Intersection => "intersection",
            ElementKind::Incoming => "incoming",
            ElementKind::StaticObstacle => "staticObstacle",
            ElementKind::DynamicObstacle => "dynamicObstacle",
            ElementKind::EnvironmentObstacle => "environmentObstacle",
            ElementKind::PlanningProblem => "planningProblem",
        }
    }
}

/// What is wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ProblemKind {
    /// Two elements share an id (ids are unique over the whole file).
    DuplicateId,
    /// A reference to an id that no element of the expected kind has.
    DanglingRef,
    /// A traffic sign no lanelet references (the readers assert).
    UnreferencedTrafficSign,
    /// A traffic light without position that no lanelet references (the readers fail).
    UnreferencedTrafficLight,
    /// A sign id outside the XSD's `trafficSignID` enumeration.
    UnknownTrafficSignId,
    /// A dynamic obstacle without trajectory states (XSD needs >= 1).
    EmptyTrajectory,
    /// Trajectory time steps are not `t0+1, t0+2, …`.
    TrajectoryNotConsecutive,
    /// A list the XSD requires to be non-empty is empty.
    EmptyList,
    /// NaN or infinity.
    NonFinite,
    /// A value that must be > 0 is not (or rounds to 0 when written).
    NotPositive,
    /// A scenario file without planning problem.
    NoPlanningProblem,
    /// `A.successor ∋ B` without `B.predecessor ∋ A`, or the reverse.
    AsymmetricSuccessor,
    /// Adjacency not mirrored by the neighbour with the same driving direction.
    AsymmetricAdjacency,
    /// The left bound lies right of the driving direction everywhere (bounds swapped).
    LeftBoundOnRight,
}

/// One finding of [`Scenario::validate`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    pub kind: ProblemKind,
    pub element: ElementKind,
    /// The id of the element, if it has one.
    pub id: Option<u64>,
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.id {
            Some(id) => write!(f, "{} {}: {}", self.element.as_str(), id, self.message),
            None => write!(f, "{}: {}", self.element.as_str(), self.message),
        }
    }
}

struct Checker {
    problems: Vec<Problem>,
    ids: BTreeMap<u64, ElementKind>,
}

impl Checker {
    fn push(&mut self, kind: ProblemKind, element: ElementKind, id: Option<u64>, message: String) {
        self.problems.push(Problem { kind, element, id, message });
    }

    fn register(&mut self, kind: ElementKind, id: u64) {
        if let Some(first) = self.ids.get(&id).copied() {
            self.push(ProblemKind::DuplicateId, kind, Some(id), format!("id {id} is already used by a {}", first.as_str()));
        } else {
            self.ids.insert(id, kind);
        }
    }

    /// `register` for each id of one element family, in order.
    fn register_all(&mut self, kind: ElementKind, ids: impl IntoIterator<Item = u64>) {
        for id in ids {
            self.register(kind, id);
        }
    }

    fn reference(&mut self, from: ElementKind, from_id: u64, field: &str, target: u64, expected: ElementKind) {
        match self.ids.get(&target) {
            Some(k) if *k == expected => {}
            Some(k) => {
                let msg = format!("{field} refers to {target}, a {}, expected a {}", k.as_str(), expected.as_str());
                self.push(ProblemKind::DanglingRef, from, Some(from_id), msg);
            }
            None => {
                let msg = format!("{field} refers to {target}, but no {} has that id", expected.as_str());
                self.push(ProblemKind::DanglingRef, from, Some(from_id), msg);
            }
        }
    }

    fn finite(&mut self, element: ElementKind, id: Option<u64>, field: &str, v: f64) {
        if !v.is_finite() {
            self.push(ProblemKind::NonFinite, element, id, format!("{field} is {v}"));
        }
    }

    fn point(&mut self, element: ElementKind, id: Option<u64>, field: &str, p: &Point) {
        if !p.is_finite() {
            self.push(ProblemKind::NonFinite, element, id, format!("{field} ({}, {}) is not finite", p.x, p.y));
        }
    }

    fn positive(&mut self, element: ElementKind, id: Option<u64>, field: &str, v: f64) {
        if !is_written_positive(v) {
            self.push(ProblemKind::NotPositive, element, id, format!("{field} is {v}, must be > 0 when written"));
        }
    }

    fn non_empty(&mut self, element: ElementKind, id: Option<u64>, what: &str, len: usize) {
        if len == 0 {
            self.push(ProblemKind::EmptyList, element, id, format!("{what} must not be empty"));
        }
    }

    fn shape(&mut self, element: ElementKind, id: u64, shape: &Shape) {
        match shape {
            Shape::Rectangle(r) => {
                self.positive(element, Some(id), "rectangle length", r.length());
                self.positive(element, Some(id), "rectangle width", r.width());
            }
            Shape::Circle(c) => self.positive(element, Some(id), "circle radius", c.radius()),
            Shape::Polygon(_) => {}
        }
    }
}

impl Scenario {
    /// Checks the scenario and its planning problems as one file. `problems: None` means a map
    /// file (`osc2cr map`): no planning problem is required. An empty list means the file is
    /// consistent; it does not replace the XSD.
    pub fn validate(&self, problems: Option<&PlanningProblemSet>) -> Vec<Problem> {
        let mut c = Checker { problems: Vec::new(), ids: BTreeMap::new() };
        self.register_ids(&mut c, problems);
        self.check_header(&mut c);
        self.check_network(&mut c);
        self.check_obstacles(&mut c);
        if let Some(set) = problems {
            check_planning(&mut c, set);
        }
        c.problems
    }

    fn register_ids(&self, c: &mut Checker, problems: Option<&PlanningProblemSet>) {
        let net = &self.network;
        c.register_all(ElementKind::Lanelet, net.lanelets.iter().map(|l| l.id.get()));
        c.register_all(ElementKind::TrafficSign, net.traffic_signs.iter().map(|s| s.id.get()));
        c.register_all(ElementKind::TrafficLight, net.traffic_lights.iter().map(|l| l.id.get()));
        for i in &net.intersections {
            c.register(ElementKind::Intersection, i.id.get());
            c.register_all(ElementKind::Incoming, i.incomings.iter().map(|inc| inc.id.get()));
        }
        c.register_all(ElementKind::StaticObstacle, self.static_obstacles.iter().map(|o| o.id.get()));
        c.register_all(ElementKind::DynamicObstacle, self.dynamic_obstacles.iter().map(|o| o.id.get()));
        c.register_all(ElementKind::EnvironmentObstacle, self.environment_obstacles.iter().map(|o| o.id.get()));
        c.register_all(ElementKind::PlanningProblem, problems.map(|s| s.problems.as_slice()).unwrap_or(&[]).iter().map(|p| p.id.get()));
    }

    fn check_header(&self, c: &mut Checker) {
        let k = ElementKind::Scenario;
        c.positive(k, None, "timeStepSize", self.header.time_step_size);
        c.finite(k, None, "gpsLatitude", self.location.gps_latitude);
        c.finite(k, None, "gpsLongitude", self.location.gps_longitude);
        if let Some(g) = &self.location.geo_transformation {
            c.finite(k, None, "xTranslation", g.x_translation);
            c.finite(k, None, "yTranslation", g.y_translation);
            c.finite(k, None, "zRotation", g.z_rotation);
            c.positive(k, None, "scaling", g.scaling);
        }
    }

    fn check_network(&self, c: &mut Checker) {
        use ElementKind as K;
        let net = &self.network;
        c.non_empty(K::Scenario, None, "the lanelet list (the XSD needs >= 1 lanelet)", net.lanelets.len());
        let by_id: BTreeMap<u64, &Lanelet> = net.lanelets.iter().map(|l| (l.id.get(), l)).collect();
        let mut referenced_signs = BTreeSet::new();
        let mut referenced_lights = BTreeSet::new();
        for l in &net.lanelets {
            let id = l.id.get();
            // each link must be listed the other way round by the lanelet it names
            type BackLinks = fn(&Lanelet) -> &[LaneletId];
            let links: [(&[LaneletId], &str, &str, BackLinks); 2] =
                [(&l.predecessors, "predecessor", "successor", |o| &o.successors), (&l.successors, "successor", "predecessor", |o| &o.predecessors)];
            for (refs, field, back, back_refs) in links {
                for p in refs {
                    c.reference(K::Lanelet, id, field, p.get(), K::Lanelet);
                    if let Some(other) = by_id.get(&p.get()) {
                        if !back_refs(other).contains(&l.id) {
                            let msg = format!("has {field} {p}, but {p} does not list {id} as {back}");
                            c.push(ProblemKind::AsymmetricSuccessor, K::Lanelet, Some(id), msg);
                        }
                    }
                }
            }
            for (side, adj) in [("adjacentLeft", l.adjacent_left), ("adjacentRight", l.adjacent_right)] {
                let Some(adj) = adj else { continue };
                c.reference(K::Lanelet, id, side, adj.lanelet.get(), K::Lanelet);
                let Some(other) = by_id.get(&adj.lanelet.get()) else {
                    continue;
                };
                // same direction: my left neighbour has me on its right; opposite: on its left.
                let mirrored_left = (side == "adjacentLeft") == (adj.driving_dir == DrivingDir::Opposite);
                let back = if mirrored_left { other.adjacent_left } else { other.adjacent_right };
                let ok = adj.lanelet != l.id && back.is_some_and(|b| b.lanelet == l.id && b.driving_dir == adj.driving_dir);
                if !ok {
                    let back_side = if mirrored_left { "adjacentLeft" } else { "adjacentRight" };
                    let msg = format!(
                        "{side}={} ({}) but lanelet {}'s {back_side} is not {id} ({})",
                        adj.lanelet,
                        adj.driving_dir.as_str(),
                        adj.lanelet,
                        adj.driving_dir.as_str()
                    );
                    c.push(ProblemKind::AsymmetricAdjacency, K::Lanelet, Some(id), msg);
                }
            }
            if let Some(sl) = &l.stop_line {
                for p in sl.points.iter().flatten() {
                    c.point(K::Lanelet, Some(id), "stop line point", p);
                }
                for r in &sl.traffic_sign_refs {
                    c.reference(K::Lanelet, id, "stopLine trafficSignRef", r.get(), K::TrafficSign);
                }
                for r in &sl.traffic_light_refs {
                    c.reference(K::Lanelet, id, "stopLine trafficLightRef", r.get(), K::TrafficLight);
                }
            }
            c.non_empty(K::Lanelet, Some(id), "laneletType", l.lanelet_types.len());
            for r in &l.traffic_sign_refs {
                c.reference(K::Lanelet, id, "trafficSignRef", r.get(), K::TrafficSign);
                referenced_signs.insert(*r);
            }
            for r in &l.traffic_light_refs {
                c.reference(K::Lanelet, id, "trafficLightRef", r.get(), K::TrafficLight);
                referenced_lights.insert(*r);
            }
            if left_bound_on_right(l) {
                let msg = "the left bound lies right of the driving direction at every point".to_string();
                c.push(ProblemKind::LeftBoundOnRight, K::Lanelet, Some(id), msg);
            }
        }
        for s in &net.traffic_signs {
            let id = Some(s.id.get());
            c.non_empty(K::TrafficSign, id, "trafficSignElement", s.elements.len());
            for e in &s.elements {
                if !is_xsd_traffic_sign_id(&e.sign_id) {
                    let msg = format!("trafficSignID {:?} is not in the 2020a XSD enumeration", e.sign_id);
                    c.push(ProblemKind::UnknownTrafficSignId, K::TrafficSign, id, msg);
                }
            }
            if let Some(p) = &s.position {
                c.point(K::TrafficSign, id, "position", p);
            }
            if !referenced_signs.contains(&s.id) {
                let msg = "no lanelet references this sign (commonroad-io asserts one does)".to_string();
                c.push(ProblemKind::UnreferencedTrafficSign, K::TrafficSign, id, msg);
            }
        }
        for t in &net.traffic_lights {
            let id = Some(t.id.get());
            c.non_empty(K::TrafficLight, id, "cycle", t.cycle.len());
            match &t.position {
                Some(p) => c.point(K::TrafficLight, id, "position", p),
                None if !referenced_lights.contains(&t.id) => {
                    let msg = "a light without position must be referenced by a lanelet".to_string();
                    c.push(ProblemKind::UnreferencedTrafficLight, K::TrafficLight, id, msg);
                }
                None => {}
            }
        }
        for i in &net.intersections {
            let iid = i.id.get();
            c.non_empty(K::Intersection, Some(iid), "incoming", i.incomings.len());
            for inc in &i.incomings {
                let id = inc.id.get();
                c.non_empty(K::Incoming, Some(id), "incomingLanelet", inc.incoming_lanelets.len());
                for (field, refs) in inc.lanelet_groups() {
                    for r in refs {
                        c.reference(K::Incoming, id, field, r.get(), K::Lanelet);
                    }
                }
                if let Some(r) = inc.is_left_of {
                    c.reference(K::Incoming, id, "isLeftOf", r.get(), K::Incoming);
                }
            }
            for crossing in &i.crossings {
                c.non_empty(K::Intersection, Some(iid), "crossing", crossing.len());
                for r in crossing {
                    c.reference(K::Intersection, iid, "crossingLanelet", r.get(), K::Lanelet);
                }
            }
        }
    }

    fn check_obstacles(&self, c: &mut Checker) {
        use ElementKind as K;
        for o in &self.static_obstacles {
            let id = o.id.get();
            c.shape(K::StaticObstacle, id, &o.shape);
            for (f, v) in [("x", o.x), ("y", o.y), ("orientation", o.orientation)] {
                c.finite(K::StaticObstacle, Some(id), f, v);
            }
        }
        for o in &self.dynamic_obstacles {
            let id = o.id.get();
            c.shape(K::DynamicObstacle, id, &o.shape);
            let t0 = o.initial_state.time_step;
            if !o.initial_state.is_finite() {
                c.push(ProblemKind::NonFinite, K::DynamicObstacle, Some(id), format!("initial state at {t0} is not finite"));
            }
            if o.trajectory.is_empty() {
                let msg = "the trajectory has no state (the XSD needs >= 1)".to_string();
                c.push(ProblemKind::EmptyTrajectory, K::DynamicObstacle, Some(id), msg);
            }
            for (i, s) in o.trajectory.iter().enumerate() {
                let expected = t0.saturating_add(1).saturating_add(i as u64);
                if s.time_step != expected {
                    let msg = format!("trajectory state {i} has time step {}, expected {expected} (initial time step {t0} + {})", s.time_step, i + 1);
                    c.push(ProblemKind::TrajectoryNotConsecutive, K::DynamicObstacle, Some(id), msg);
                    break; // one report per trajectory is enough
                }
            }
            if let Some(s) = o.trajectory.iter().find(|s| !s.is_finite()) {
                let msg = format!("state at time step {} is not finite", s.time_step);
                c.push(ProblemKind::NonFinite, K::DynamicObstacle, Some(id), msg);
            }
        }
        for o in &self.environment_obstacles {
            let id = Some(o.id.get());
            match &o.shape {
                AbsoluteShape::Rectangle(r) => {
                    c.point(K::EnvironmentObstacle, id, "rectangle center", &r.center);
                    c.finite(K::EnvironmentObstacle, id, "rectangle orientation", r.orientation);
                    c.positive(K::EnvironmentObstacle, id, "rectangle length", r.rectangle.length());
                    c.positive(K::EnvironmentObstacle, id, "rectangle width", r.rectangle.width());
                }
                AbsoluteShape::Circle(ci) => {
                    c.point(K::EnvironmentObstacle, id, "circle center", &ci.center);
                    c.positive(K::EnvironmentObstacle, id, "circle radius", ci.circle.radius());
                }
                AbsoluteShape::Polygon(_) => {}
            }
        }
    }
}

fn check_planning(c: &mut Checker, set: &PlanningProblemSet) {
    use ElementKind as K;
    if set.problems.is_empty() {
        let msg = "a scenario file needs at least one planning problem".to_string();
        c.push(ProblemKind::NoPlanningProblem, K::Scenario, None, msg);
    }
    for p in &set.problems {
        let id = p.id.get();
        let s = &p.initial_state;
        let fields = [
            ("x", s.x),
            ("y", s.y),
            ("orientation", s.orientation),
            ("velocity", s.velocity),
            ("yawRate", s.yaw_rate),
            ("slipAngle", s.slip_angle),
            ("acceleration", s.acceleration.unwrap_or(0.0)),
        ];
        for (f, v) in fields {
            c.finite(K::PlanningProblem, Some(id), f, v);
        }
        c.non_empty(K::PlanningProblem, Some(id), "goalState", p.goal_states.len());
        for g in &p.goal_states {
            match &g.position {
                None => {}
                Some(GoalPosition::Lanelets(refs)) => {
                    c.non_empty(K::PlanningProblem, Some(id), "goal lanelet list", refs.len());
                    for r in refs {
                        c.reference(K::PlanningProblem, id, "goal lanelet", r.get(), K::Lanelet);
                    }
                }
                Some(GoalPosition::Rectangles(rs)) => {
                    c.non_empty(K::PlanningProblem, Some(id), "goal rectangle list", rs.len());
                    for r in rs {
                        c.point(K::PlanningProblem, Some(id), "goal rectangle center", &r.center);
                        c.finite(K::PlanningProblem, Some(id), "goal rectangle orientation", r.orientation);
                        c.positive(K::PlanningProblem, Some(id), "goal rectangle length", r.rectangle.length());
                        c.positive(K::PlanningProblem, Some(id), "goal rectangle width", r.rectangle.width());
                    }
                }
                Some(GoalPosition::Circles(cs)) => {
                    c.non_empty(K::PlanningProblem, Some(id), "goal circle list", cs.len());
                    for ci in cs {
                        c.point(K::PlanningProblem, Some(id), "goal circle center", &ci.center);
                        c.positive(K::PlanningProblem, Some(id), "goal circle radius", ci.circle.radius());
                    }
                }
                Some(GoalPosition::Polygons(ps)) => {
                    c.non_empty(K::PlanningProblem, Some(id), "goal polygon list", ps.len());
                }
            }
        }
    }
}

/// The check of cr_check.py: the left bound is on the right of the centre line's direction at
/// every segment where both the direction and the width are defined.
fn left_bound_on_right(l: &Lanelet) -> bool {
    let (left, right) = (l.bounds.left(), l.bounds.right());
    let mut total = 0usize;
    let mut wrong = 0usize;
    for (l, r) in left.windows(2).zip(right.windows(2)) {
        let (&[l0, l1], &[r0, r1]) = (l, r) else {
            continue;
        };
        let tx = (l1.x + r1.x - l0.x - r0.x) / 2.0;
        let ty = (l1.y + r1.y - l0.y - r0.y) / 2.0;
        let (wx, wy) = (l0.x - r0.x, l0.y - r0.y);
        if tx.hypot(ty) < 1e-6 || wx.hypot(wy) < 1e-6 {
            continue;
        }
        total += 1;
        if tx * wy - ty * wx < 0.0 {
            wrong += 1;
        }
    }
    total > 0 && wrong == total
}
