//! Serialises a [`Scenario`] (+ planning problems) in exactly the element order of the 2020a
//! XSD (`xs:sequence` everywhere it matters; `xs:all` state elements in declaration order).

use super::emitter::Emitter;
use crate::geometry::{AbsoluteShape, PlacedCircle, PlacedRectangle, Point, Polygon, Shape};
use crate::intersection::Intersection;
use crate::lanelet::{Adjacent, Lanelet, LineMarking};
use crate::obstacle::{DynamicObstacle, EnvironmentObstacle, State, StaticObstacle};
use crate::planning::{GoalPosition, GoalState, Interval, PlanningProblem, PlanningProblemSet};
use crate::scenario::Scenario;
use crate::traffic::{TrafficLight, TrafficSign};
use crate::Error;

/// Writes a scenario file: the scenario and at least one planning problem.
pub fn write_scenario(scenario: &Scenario, problems: &PlanningProblemSet) -> Result<Vec<u8>, Error> {
    if problems.problems.is_empty() {
        return Err(Error::NoPlanningProblem { hint: " (write a map instead)" });
    }
    write(scenario, &problems.problems)
}

/// Writes a map file (`osc2cr map`): the scenario without planning problems. The 2020a XSD
/// requires a planning problem, so such a file is checked with `cr_check.py --map-only`.
pub fn write_map(scenario: &Scenario) -> Result<Vec<u8>, Error> {
    write(scenario, &[])
}

fn write(scenario: &Scenario, problems: &[PlanningProblem]) -> Result<Vec<u8>, Error> {
    let mut e = Emitter::with_capacity(estimated_size(scenario, problems));
    let h = &scenario.header;
    let step = e.decimal("timeStepSize", h.time_step_size)?;
    e.open(
        "commonRoad",
        &[
            ("commonRoadVersion", &"2020a"),
            ("benchmarkID", &h.benchmark_id),
            ("date", &h.date),
            ("author", &h.author),
            ("affiliation", &h.affiliation),
            ("source", &h.source),
            ("timeStepSize", &step),
        ],
    )?;
    location(&mut e, scenario)?;
    if scenario.tags.is_empty() {
        e.empty("scenarioTags", &[])?;
    } else {
        e.open("scenarioTags", &[])?;
        for t in &scenario.tags {
            e.empty(t.as_str(), &[])?;
        }
        e.close("scenarioTags");
    }
    let net = &scenario.network;
    each_with_context(&mut e, "lanelet", &net.lanelets, |x| &x.id, lanelet)?;
    each_with_context(&mut e, "trafficSign", &net.traffic_signs, |x| &x.id, traffic_sign)?;
    each_with_context(&mut e, "trafficLight", &net.traffic_lights, |x| &x.id, traffic_light)?;
    each_with_context(&mut e, "intersection", &net.intersections, |x| &x.id, intersection)?;
    each_with_context(&mut e, "staticObstacle", &scenario.static_obstacles, |x| &x.id, static_obstacle)?;
    each_with_context(&mut e, "dynamicObstacle", &scenario.dynamic_obstacles, |x| &x.id, dynamic_obstacle)?;
    each_with_context(&mut e, "environmentObstacle", &scenario.environment_obstacles, |x| &x.id, environment_obstacle)?;
    each_with_context(&mut e, "planningProblem", problems, |x| &x.id, planning_problem)?;
    e.close("commonRoad");
    Ok(e.finish())
}

/// Bytes the file will roughly take (a `<point>` line is ~60 bytes, a trajectory state
/// ~420), so that the buffer is allocated once.
fn estimated_size(scenario: &Scenario, problems: &[PlanningProblem]) -> usize {
    let net = &scenario.network;
    let points: usize = net.lanelets.iter().map(|l| 2 * l.bounds.len()).sum();
    let states: usize = scenario.dynamic_obstacles.iter().map(|o| o.trajectory.len() + 1).sum();
    let others = net.lanelets.len() + net.traffic_signs.len() + net.traffic_lights.len() + net.intersections.len();
    4096 + 64 * points + 450 * states + 400 * (others + scenario.static_obstacles.len() + problems.len())
}

/// Writes each of `items` with `write`, errors naming the element (`tag` and its id).
fn each_with_context<T, I: std::fmt::Display>(
    e: &mut Emitter,
    tag: &str,
    items: &[T],
    id: impl Fn(&T) -> &I,
    write: impl Fn(&mut Emitter, &T) -> Result<(), Error>,
) -> Result<(), Error> {
    for item in items {
        with_context(e, format!("{tag} {}", id(item)), |e| write(e, item))?;
    }
    Ok(())
}

fn with_context(e: &mut Emitter, label: String, f: impl FnOnce(&mut Emitter) -> Result<(), Error>) -> Result<(), Error> {
    e.push_context(label);
    let r = f(e);
    e.pop_context();
    r
}

fn id_attr(id: &dyn std::fmt::Display) -> [(&'static str, &dyn std::fmt::Display); 1] {
    [("id", id)]
}

fn ref_attr(id: &dyn std::fmt::Display) -> [(&'static str, &dyn std::fmt::Display); 1] {
    [("ref", id)]
}

/// `<tag><x>…</x><y>…</y>[<z>…</z>]</tag>` (no indentation, no line end).
fn point_markup(e: &mut Emitter, tag: &str, p: &Point) -> Result<(), Error> {
    e.push("<");
    e.push(tag);
    e.push("><x>");
    e.push_decimal(p.x, || format!("{tag}/x"))?;
    e.push("</x><y>");
    e.push_decimal(p.y, || format!("{tag}/y"))?;
    e.push("</y>");
    if let Some(z) = p.z {
        e.push("<z>");
        e.push_decimal(z, || format!("{tag}/z"))?;
        e.push("</z>");
    }
    e.push("</");
    e.push(tag);
    e.push(">");
    Ok(())
}

/// A point element on its own line.
fn point(e: &mut Emitter, tag: &str, p: &Point) -> Result<(), Error> {
    e.begin_line();
    point_markup(e, tag, p)?;
    e.end_line();
    Ok(())
}

/// `<position><point>…</point></position>` on one line.
fn position(e: &mut Emitter, p: &Point) -> Result<(), Error> {
    e.begin_line();
    e.push("<position>");
    point_markup(e, "point", p)?;
    e.push("</position>");
    e.end_line();
    Ok(())
}

fn exact(e: &mut Emitter, tag: &str, v: f64) -> Result<(), Error> {
    e.begin_line();
    e.push("<");
    e.push(tag);
    e.push("><exact>");
    e.push_decimal(v, || tag.to_string())?;
    e.push("</exact></");
    e.push(tag);
    e.push(">");
    e.end_line();
    Ok(())
}

fn exact_int(e: &mut Emitter, tag: &str, v: u64) {
    e.begin_line();
    e.push("<");
    e.push(tag);
    e.push("><exact>");
    e.push_display(v);
    e.push("</exact></");
    e.push(tag);
    e.push(">");
    e.end_line();
}

fn interval(e: &mut Emitter, tag: &str, i: &Interval) -> Result<(), Error> {
    e.begin_line();
    e.push("<");
    e.push(tag);
    e.push("><intervalStart>");
    e.push_decimal(i.start(), || tag.to_string())?;
    e.push("</intervalStart><intervalEnd>");
    e.push_decimal(i.end(), || tag.to_string())?;
    e.push("</intervalEnd></");
    e.push(tag);
    e.push(">");
    e.end_line();
    Ok(())
}

fn location(e: &mut Emitter, s: &Scenario) -> Result<(), Error> {
    let l = &s.location;
    e.open("location", &[])?;
    e.int("geoNameId", l.geo_name_id);
    e.num("gpsLatitude", l.gps_latitude)?;
    e.num("gpsLongitude", l.gps_longitude)?;
    if let Some(g) = &l.geo_transformation {
        e.open("geoTransformation", &[])?;
        e.text("geoReference", &g.geo_reference)?;
        e.open("additionalTransformation", &[])?;
        e.num("xTranslation", g.x_translation)?;
        e.num("yTranslation", g.y_translation)?;
        e.num("zRotation", g.z_rotation)?;
        e.positive_num("scaling", g.scaling)?;
        e.close("additionalTransformation");
        e.close("geoTransformation");
    }
    e.close("location");
    Ok(())
}

fn bound(e: &mut Emitter, tag: &str, points: &[Point], marking: Option<LineMarking>) -> Result<(), Error> {
    e.open(tag, &[])?;
    for p in points {
        point(e, "point", p)?;
    }
    if let Some(m) = marking {
        e.text("lineMarking", m.as_str())?;
    }
    e.close(tag);
    Ok(())
}

fn adjacent(e: &mut Emitter, tag: &str, a: &Option<Adjacent>) -> Result<(), Error> {
    if let Some(a) = a {
        e.empty(tag, &[("ref", &a.lanelet), ("drivingDir", &a.driving_dir.as_str())])?;
    }
    Ok(())
}

fn lanelet(e: &mut Emitter, l: &Lanelet) -> Result<(), Error> {
    e.open("lanelet", &id_attr(&l.id))?;
    bound(e, "leftBound", l.bounds.left(), l.left_marking)?;
    bound(e, "rightBound", l.bounds.right(), l.right_marking)?;
    for r in &l.predecessors {
        e.empty("predecessor", &ref_attr(r))?;
    }
    for r in &l.successors {
        e.empty("successor", &ref_attr(r))?;
    }
    adjacent(e, "adjacentLeft", &l.adjacent_left)?;
    adjacent(e, "adjacentRight", &l.adjacent_right)?;
    if let Some(sl) = &l.stop_line {
        e.open("stopLine", &[])?;
        for p in sl.points.iter().flatten() {
            point(e, "point", p)?;
        }
        e.text("lineMarking", sl.line_marking.as_str())?;
        for r in &sl.traffic_sign_refs {
            e.empty("trafficSignRef", &ref_attr(r))?;
        }
        for r in &sl.traffic_light_refs {
            e.empty("trafficLightRef", &ref_attr(r))?;
        }
        e.close("stopLine");
    }
    for t in &l.lanelet_types {
        e.text("laneletType", t.as_str())?;
    }
    for u in &l.user_one_way {
        e.text("userOneWay", u.as_str())?;
    }
    for u in &l.user_bidirectional {
        e.text("userBidirectional", u.as_str())?;
    }
    for r in &l.traffic_sign_refs {
        e.empty("trafficSignRef", &ref_attr(r))?;
    }
    for r in &l.traffic_light_refs {
        e.empty("trafficLightRef", &ref_attr(r))?;
    }
    e.close("lanelet");
    Ok(())
}

fn traffic_sign(e: &mut Emitter, s: &TrafficSign) -> Result<(), Error> {
    e.open("trafficSign", &id_attr(&s.id))?;
    for el in &s.elements {
        e.open("trafficSignElement", &[])?;
        e.text("trafficSignID", &el.sign_id)?;
        for v in &el.additional_values {
            e.text("additionalValue", v)?;
        }
        e.close("trafficSignElement");
    }
    if let Some(p) = &s.position {
        position(e, p)?;
    }
    e.text("virtual", if s.is_virtual { "true" } else { "false" })?;
    e.close("trafficSign");
    Ok(())
}

fn traffic_light(e: &mut Emitter, t: &TrafficLight) -> Result<(), Error> {
    e.open("trafficLight", &id_attr(&t.id))?;
    e.open("cycle", &[])?;
    for c in &t.cycle {
        e.raw_line(&format!("<cycleElement><duration>{}</duration><color>{}</color></cycleElement>", c.duration, c.color.as_str()));
    }
    if t.time_offset > 0 {
        e.int("timeOffset", t.time_offset);
    }
    e.close("cycle");
    if let Some(p) = &t.position {
        position(e, p)?;
    }
    if let Some(d) = t.direction {
        e.text("direction", d.as_str())?;
    }
    if let Some(a) = t.active {
        e.text("active", if a { "true" } else { "false" })?;
    }
    e.close("trafficLight");
    Ok(())
}

fn intersection(e: &mut Emitter, i: &Intersection) -> Result<(), Error> {
    e.open("intersection", &id_attr(&i.id))?;
    for inc in &i.incomings {
        e.open("incoming", &id_attr(&inc.id))?;
        for (tag, refs) in inc.lanelet_groups() {
            for r in refs {
                e.empty(tag, &ref_attr(r))?;
            }
        }
        if let Some(r) = inc.is_left_of {
            e.empty("isLeftOf", &ref_attr(&r))?;
        }
        e.close("incoming");
    }
    for crossing in &i.crossings {
        e.open("crossing", &[])?;
        for r in crossing {
            e.empty("crossingLanelet", &ref_attr(r))?;
        }
        e.close("crossing");
    }
    e.close("intersection");
    Ok(())
}

fn polygon(e: &mut Emitter, p: &Polygon) -> Result<(), Error> {
    e.open("polygon", &[])?;
    for pt in p.points() {
        point(e, "point", pt)?;
    }
    e.close("polygon");
    Ok(())
}

fn placed_rectangle(e: &mut Emitter, r: &PlacedRectangle) -> Result<(), Error> {
    e.open("rectangle", &[])?;
    e.positive_num("length", r.rectangle.length())?;
    e.positive_num("width", r.rectangle.width())?;
    e.num("orientation", r.orientation)?;
    point(e, "center", &r.center)?;
    e.close("rectangle");
    Ok(())
}

fn placed_circle(e: &mut Emitter, c: &PlacedCircle) -> Result<(), Error> {
    e.open("circle", &[])?;
    e.positive_num("radius", c.circle.radius())?;
    point(e, "center", &c.center)?;
    e.close("circle");
    Ok(())
}

/// An obstacle shape: no centre or orientation (see `geometry.rs` for why).
fn shape(e: &mut Emitter, s: &Shape) -> Result<(), Error> {
    e.open("shape", &[])?;
    match s {
        Shape::Rectangle(r) => {
            e.open("rectangle", &[])?;
            e.positive_num("length", r.length())?;
            e.positive_num("width", r.width())?;
            e.close("rectangle");
        }
        Shape::Circle(c) => {
            e.open("circle", &[])?;
            e.positive_num("radius", c.radius())?;
            e.close("circle");
        }
        Shape::Polygon(p) => polygon(e, p)?,
    }
    e.close("shape");
    Ok(())
}

/// A dynamic obstacle's state; the same fields for the initial state and every trajectory
/// state, so the readers see one state class.
fn state(e: &mut Emitter, tag: &str, s: &State) -> Result<(), Error> {
    e.push_context(format!("time step {}", s.time_step));
    let r = (|| {
        e.open(tag, &[])?;
        position(e, &Point::new(s.x, s.y))?;
        exact(e, "orientation", s.orientation)?;
        exact_int(e, "time", s.time_step);
        exact(e, "velocity", s.velocity)?;
        exact(e, "acceleration", s.acceleration)?;
        exact(e, "yawRate", s.yaw_rate)?;
        e.close(tag);
        Ok(())
    })();
    e.pop_context();
    r
}

/// An obstacle element `tag` with its id and `type`, its content written by `body`.
fn obstacle(e: &mut Emitter, tag: &str, id: &dyn std::fmt::Display, kind: &str, body: impl FnOnce(&mut Emitter) -> Result<(), Error>) -> Result<(), Error> {
    e.open(tag, &id_attr(id))?;
    e.text("type", kind)?;
    body(e)?;
    e.close(tag);
    Ok(())
}

fn static_obstacle(e: &mut Emitter, o: &StaticObstacle) -> Result<(), Error> {
    obstacle(e, "staticObstacle", &o.id, o.obstacle_type.as_str(), |e| {
        shape(e, &o.shape)?;
        e.open("initialState", &[])?;
        position(e, &Point::new(o.x, o.y))?;
        exact(e, "orientation", o.orientation)?;
        exact_int(e, "time", 0);
        e.close("initialState");
        Ok(())
    })
}

fn dynamic_obstacle(e: &mut Emitter, o: &DynamicObstacle) -> Result<(), Error> {
    obstacle(e, "dynamicObstacle", &o.id, o.obstacle_type.as_str(), |e| {
        shape(e, &o.shape)?;
        state(e, "initialState", &o.initial_state)?;
        e.open("trajectory", &[])?;
        for s in &o.trajectory {
            state(e, "state", s)?;
        }
        e.close("trajectory");
        Ok(())
    })
}

fn environment_obstacle(e: &mut Emitter, o: &EnvironmentObstacle) -> Result<(), Error> {
    obstacle(e, "environmentObstacle", &o.id, o.obstacle_type.as_str(), |e| {
        e.open("shape", &[])?;
        match &o.shape {
            AbsoluteShape::Rectangle(r) => placed_rectangle(e, r)?,
            AbsoluteShape::Circle(c) => placed_circle(e, c)?,
            AbsoluteShape::Polygon(p) => polygon(e, p)?,
        }
        e.close("shape");
        Ok(())
    })
}

fn goal_state(e: &mut Emitter, g: &GoalState) -> Result<(), Error> {
    e.open("goalState", &[])?;
    e.raw_line(&format!("<time><intervalStart>{}</intervalStart><intervalEnd>{}</intervalEnd></time>", g.time.start(), g.time.end()));
    if let Some(pos) = &g.position {
        e.open("position", &[])?;
        match pos {
            GoalPosition::Rectangles(rs) => rs.iter().try_for_each(|r| placed_rectangle(e, r))?,
            GoalPosition::Circles(cs) => cs.iter().try_for_each(|c| placed_circle(e, c))?,
            GoalPosition::Polygons(ps) => ps.iter().try_for_each(|p| polygon(e, p))?,
            GoalPosition::Lanelets(ls) => ls.iter().try_for_each(|l| e.empty("lanelet", &ref_attr(l)))?,
        }
        e.close("position");
    }
    if let Some(o) = &g.orientation {
        interval(e, "orientation", o)?;
    }
    if let Some(v) = &g.velocity {
        interval(e, "velocity", v)?;
    }
    e.close("goalState");
    Ok(())
}

fn planning_problem(e: &mut Emitter, p: &PlanningProblem) -> Result<(), Error> {
    e.open("planningProblem", &id_attr(&p.id))?;
    let s = &p.initial_state;
    e.open("initialState", &[])?;
    position(e, &Point::new(s.x, s.y))?;
    exact(e, "velocity", s.velocity)?;
    exact(e, "orientation", s.orientation)?;
    exact(e, "yawRate", s.yaw_rate)?;
    exact(e, "slipAngle", s.slip_angle)?;
    exact_int(e, "time", 0);
    if let Some(a) = s.acceleration {
        exact(e, "acceleration", a)?;
    }
    e.close("initialState");
    for g in &p.goal_states {
        goal_state(e, g)?;
    }
    e.close("planningProblem");
    Ok(())
}

/// The root element of [`write_planning_problem`]'s text.
pub const PLANNING_PROBLEM_ROOT: &str = "commonRoadPlanningProblem";

/// One planning problem as a self-contained piece of CommonRoad 2020a XML on one line (no
/// prolog): `<commonRoadPlanningProblem>` holding the `<planningProblem>` element and copies of
/// the `<lanelet>` elements `lanelets` (those its goals name, so that a reader can find them
/// again in another network). For carrying a planning problem inside another format
/// (`osc2cr export` puts it in an OpenSCENARIO property); read back with
/// [`super::read_planning_problem_str`]. Decimals as in a scenario file (6 digits).
pub fn write_planning_problem(problem: &PlanningProblem, lanelets: &[&Lanelet]) -> Result<String, Error> {
    let mut e = Emitter::with_capacity(1024);
    e.open(PLANNING_PROBLEM_ROOT, &[])?;
    with_context(&mut e, format!("planningProblem {}", problem.id), |e| planning_problem(e, problem))?;
    for l in lanelets {
        with_context(&mut e, format!("lanelet {}", l.id), |e| lanelet(e, l))?;
    }
    e.close(PLANNING_PROBLEM_ROOT);
    let text = String::from_utf8(e.finish()).unwrap_or_default();
    // one line: the lines' indentation and breaks are whitespace between elements (no element
    // of the format has mixed content), so joining the trimmed lines keeps the meaning
    Ok(text.lines().skip(1).map(str::trim).collect())
}
