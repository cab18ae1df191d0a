//! The view: a world rectangle (the whole map, where the road users are, or one the user
//! chose) mapped onto the map area of a picture `width` pixels wide (y up in the world, down
//! in the picture), below the picture's header strip.

use commonroad::{AbsoluteShape, GoalPosition, PlanningProblemSet, Point, Scenario, Shape};

use crate::error::Error;

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
    pub fn empty() -> Self {
        Self { min_x: f64::INFINITY, min_y: f64::INFINITY, max_x: f64::NEG_INFINITY, max_y: f64::NEG_INFINITY }
    }
    /// Grows the box to hold a disc of radius `r` at (x, y); non-finite values are ignored.
    pub fn add(&mut self, x: f64, y: f64, r: f64) {
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
    pub fn is_valid(&self) -> bool {
        self.min_x <= self.max_x && self.min_y <= self.max_y
    }
    /// Whether the two boxes overlap (touching counts).
    pub fn intersects(&self, o: &Bounds) -> bool {
        self.min_x <= o.max_x && o.min_x <= self.max_x && self.min_y <= o.max_y && o.min_y <= self.max_y
    }
}

/// Half the largest extent of an obstacle shape: a disc around its centre that covers it.
pub fn shape_radius(s: &Shape) -> f64 {
    match s {
        Shape::Rectangle(r) => 0.5 * r.length().hypot(r.width()),
        Shape::Circle(c) => c.radius(),
        Shape::Polygon(p) => p.points().iter().map(|q| q.x.hypot(q.y)).fold(0.0, f64::max),
    }
}

fn add_absolute(b: &mut Bounds, s: &AbsoluteShape) {
    match s {
        AbsoluteShape::Rectangle(r) => b.add(r.center.x, r.center.y, 0.5 * r.rectangle.length().hypot(r.rectangle.width())),
        AbsoluteShape::Circle(c) => b.add(c.center.x, c.center.y, c.circle.radius()),
        AbsoluteShape::Polygon(p) => p.points().iter().for_each(|q| b.add_point(q)),
    }
}

/// Everything the picture should show.
pub fn content_bounds(scenario: &Scenario, problems: Option<&PlanningProblemSet>) -> Bounds {
    let mut b = Bounds::empty();
    for l in &scenario.network.lanelets {
        l.bounds.left().iter().chain(l.bounds.right()).for_each(|p| b.add_point(p));
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
                Some(GoalPosition::Rectangles(rs)) => rs.iter().for_each(|r| add_absolute(&mut b, &AbsoluteShape::Rectangle(*r))),
                Some(GoalPosition::Circles(cs)) => cs.iter().for_each(|c| add_absolute(&mut b, &AbsoluteShape::Circle(*c))),
                Some(GoalPosition::Polygons(ps)) => ps.iter().flat_map(|p| p.points()).for_each(|q| b.add_point(q)),
                // goal lanelets are part of the network, already inside
                Some(GoalPosition::Lanelets(_)) | None => {}
            }
        }
    }
    b
}

/// How a world box becomes a view: the margin added around it, the smallest extent shown and
/// the range of the map area's height / width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fit {
    /// Margin on each side: `margin_m` + `margin_share` × the larger extent, m.
    pub margin_m: f64,
    pub margin_share: f64,
    /// The wider side of the view is at least this long, m.
    pub min_extent_m: f64,
    /// Height / width of the map area is kept within (low, high); the world box is widened to
    /// match, keeping its centre.
    pub aspect: (f64, f64),
}

impl Fit {
    /// The whole map: 2 m + 5 % around it, aspect between 1/4 and 2.
    pub const WHOLE: Fit = Fit { margin_m: 2.0, margin_share: 0.05, min_extent_m: 0.0, aspect: (MIN_ASPECT, MAX_ASPECT) };
    /// Where the road users are: room for labels around them, at least 40 m shown, landscape.
    pub const ACTION: Fit = Fit { margin_m: 6.0, margin_share: 0.1, min_extent_m: 40.0, aspect: (0.4, 1.0) };
    /// A rectangle chosen by hand: exactly it (widened to an aspect between 1/4 and 2).
    pub const EXACT: Fit = Fit { margin_m: 0.0, margin_share: 0.0, min_extent_m: 0.0, aspect: (MIN_ASPECT, MAX_ASPECT) };
}

/// World → pixel mapping of one picture's map area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Width of the picture and of its map area, pixels.
    pub width: u32,
    /// Height of the map area, pixels.
    pub height: u32,
    /// Pixels per metre.
    pub scale: f64,
    /// World coordinates of the map area's left and top edges.
    pub left: f64,
    pub top: f64,
    /// Picture row where the map area starts (below the header strip).
    pub y0: f64,
}

impl View {
    /// Fits `b` with `fit`'s margin into a map area `width` pixels wide starting at row `y0`.
    pub fn fit(b: Bounds, width: u32, fit: &Fit, y0: f64) -> Result<View, Error> {
        if !b.is_valid() {
            return Err(Error::View("the scenario has no lanelet, obstacle or goal region".to_string()));
        }
        let mut w = b.max_x - b.min_x;
        let mut h = b.max_y - b.min_y;
        let margin = fit.margin_m + fit.margin_share * w.max(h);
        w += 2.0 * margin;
        h += 2.0 * margin;
        if w.max(h) < fit.min_extent_m {
            w = w.max(fit.min_extent_m);
        }
        let (lo, hi) = fit.aspect;
        let aspect = (h / w).clamp(lo, hi);
        // widen whichever side is too short, keeping the content centred
        let (w, h) = if h / w < aspect { (w, w * aspect) } else { (h / aspect, h) };
        let scale = f64::from(width) / w;
        if !(w.is_finite() && h.is_finite() && scale.is_finite() && scale > 0.0) {
            return Err(Error::View(format!("coordinates out of range (extent {w} m × {h} m)")));
        }
        let cx = 0.5 * (b.min_x + b.max_x);
        let cy = 0.5 * (b.min_y + b.max_y);
        let height = (f64::from(width) * aspect).round().max(1.0) as u32;
        Ok(View { width, height, scale, left: cx - 0.5 * w, top: cy + 0.5 * f64::from(height) / scale, y0 })
    }

    /// The same scale and size, centred on (x, y).
    pub fn centred_on(&self, x: f64, y: f64) -> View {
        View { left: x - 0.5 * f64::from(self.width) / self.scale, top: y + 0.5 * f64::from(self.height) / self.scale, ..*self }
    }

    /// Pixel coordinates of a world point.
    pub fn px(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.left) * self.scale, self.y0 + (self.top - y) * self.scale)
    }

    /// The world rectangle the map area shows.
    pub fn world(&self) -> Bounds {
        Bounds {
            min_x: self.left,
            max_x: self.left + f64::from(self.width) / self.scale,
            min_y: self.top - f64::from(self.height) / self.scale,
            max_y: self.top,
        }
    }

    /// The map area in pixels: (x0, y0, x1, y1).
    pub fn area(&self) -> (f64, f64, f64, f64) {
        (0.0, self.y0, f64::from(self.width), self.y0 + f64::from(self.height))
    }
}
