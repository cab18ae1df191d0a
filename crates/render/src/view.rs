//! The view: a world rectangle that holds every lanelet, obstacle state and goal region with a
//! margin, mapped onto a picture `width` pixels wide (y up in the world, down in the picture).

use commonroad::{
    AbsoluteShape, GoalPosition, PlanningProblemSet, Point, Scenario, Shape,
};

use crate::error::RenderError;

/// Height / width of the picture is kept within these (a long straight road would otherwise
/// give a picture a few pixels high); the world rectangle is widened to match.
pub const MIN_ASPECT: f64 = 0.25;
pub const MAX_ASPECT: f64 = 2.0;

/// An axis-aligned world box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub min_x: f64,
    pub min_y: f64,
    pub max_x: f64,
    pub max_y: f64,
}

impl Bounds {
    fn empty() -> Self {
        Self {
            min_x: f64::INFINITY,
            min_y: f64::INFINITY,
            max_x: f64::NEG_INFINITY,
            max_y: f64::NEG_INFINITY,
        }
    }
    /// Grows the box to hold a disc of radius `r` at (x, y); non-finite values are ignored.
    fn add(&mut self, x: f64, y: f64, r: f64) {
        if !(x.is_finite() && y.is_finite() && r.is_finite()) {
            return;
        }
        self.min_x = self.min_x.min(x - r);
        self.min_y = self.min_y.min(y - r);
        self.max_x = self.max_x.max(x + r);
        self.max_y = self.max_y.max(y + r);
    }
    fn add_point(&mut self, p: &Point) {
        self.add(p.x, p.y, 0.0);
    }
    fn is_valid(&self) -> bool {
        self.min_x <= self.max_x && self.min_y <= self.max_y
    }
}

/// Half the largest extent of an obstacle shape: a disc around its centre that covers it.
fn shape_radius(s: &Shape) -> f64 {
    match s {
        Shape::Rectangle(r) => 0.5 * r.length().hypot(r.width()),
        Shape::Circle(c) => c.radius(),
        Shape::Polygon(p) => p
            .points()
            .iter()
            .map(|q| q.x.hypot(q.y))
            .fold(0.0, f64::max),
    }
}

fn add_absolute(b: &mut Bounds, s: &AbsoluteShape) {
    match s {
        AbsoluteShape::Rectangle(r) => b.add(
            r.center.x,
            r.center.y,
            0.5 * r.rectangle.length().hypot(r.rectangle.width()),
        ),
        AbsoluteShape::Circle(c) => b.add(c.center.x, c.center.y, c.circle.radius()),
        AbsoluteShape::Polygon(p) => p.points().iter().for_each(|q| b.add_point(q)),
    }
}

/// Everything the picture should show.
pub fn content_bounds(scenario: &Scenario, problems: Option<&PlanningProblemSet>) -> Bounds {
    let mut b = Bounds::empty();
    for l in &scenario.network.lanelets {
        l.bounds
            .left()
            .iter()
            .chain(l.bounds.right())
            .for_each(|p| b.add_point(p));
    }
    for o in &scenario.dynamic_obstacles {
        let r = shape_radius(&o.shape);
        for s in std::iter::once(&o.initial_state).chain(&o.trajectory) {
            b.add(s.x, s.y, r);
        }
    }
    for o in &scenario.static_obstacles {
        b.add(o.x, o.y, shape_radius(&o.shape));
    }
    for o in &scenario.environment_obstacles {
        add_absolute(&mut b, &o.shape);
    }
    for p in problems.iter().flat_map(|p| &p.problems) {
        b.add(p.initial_state.x, p.initial_state.y, 1.0);
        for g in &p.goal_states {
            match &g.position {
                Some(GoalPosition::Rectangles(rs)) => rs
                    .iter()
                    .for_each(|r| add_absolute(&mut b, &AbsoluteShape::Rectangle(*r))),
                Some(GoalPosition::Circles(cs)) => cs
                    .iter()
                    .for_each(|c| add_absolute(&mut b, &AbsoluteShape::Circle(*c))),
                Some(GoalPosition::Polygons(ps)) => ps
                    .iter()
                    .flat_map(|p| p.points())
                    .for_each(|q| b.add_point(q)),
                // goal lanelets are part of the network, already inside
                Some(GoalPosition::Lanelets(_)) | None => {}
            }
        }
    }
    b
}

/// World → pixel mapping of one picture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    pub width: u32,
    pub height: u32,
    /// Pixels per metre.
    pub scale: f64,
    /// World coordinates of the picture's left and top edges.
    pub left: f64,
    pub top: f64,
}

impl View {
    /// Fits `b` (plus a margin of 5 % and at least 2 m on each side) into `width` pixels.
    pub fn fit(b: Bounds, width: u32) -> Result<View, RenderError> {
        if !b.is_valid() {
            return Err(RenderError::View(
                "the scenario has no lanelet, obstacle or goal region".to_string(),
            ));
        }
        let mut w = b.max_x - b.min_x;
        let mut h = b.max_y - b.min_y;
        let margin = 2.0 + 0.05 * w.max(h);
        w += 2.0 * margin;
        h += 2.0 * margin;
        let aspect = (h / w).clamp(MIN_ASPECT, MAX_ASPECT);
        // widen whichever side is too short, keeping the content centred
        let (w, h) = if h / w < aspect { (w, w * aspect) } else { (h / aspect, h) };
        let scale = f64::from(width) / w;
        if !(w.is_finite() && h.is_finite() && scale.is_finite() && scale > 0.0) {
            return Err(RenderError::View(format!(
                "coordinates out of range (extent {w} m × {h} m)"
            )));
        }
        let cx = 0.5 * (b.min_x + b.max_x);
        let cy = 0.5 * (b.min_y + b.max_y);
        let height = (f64::from(width) * aspect).round().max(1.0) as u32;
        Ok(View {
            width,
            height,
            scale,
            left: cx - 0.5 * w,
            top: cy + 0.5 * f64::from(height) / scale,
        })
    }

    /// Pixel coordinates of a world point.
    pub fn px(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.left) * self.scale, (self.top - y) * self.scale)
    }
}
