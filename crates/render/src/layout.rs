//! Where things landed on a picture, in pixels: the map area and every road user's box and
//! label. Returned next to the picture so callers (and tests) can check it — or crop, or
//! annotate — without looking for colours.

use crate::view::Bounds;

/// An axis-aligned pixel rectangle (x right, y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PxRect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

impl PxRect {
    pub fn new(x: f64, y: f64, w: f64, h: f64) -> Self {
        Self { x0: x, y0: y, x1: x + w, y1: y + h }
    }
    /// The smallest rectangle holding every point (empty input: a zero rectangle at 0, 0).
    pub fn around(points: &[(f64, f64)]) -> Self {
        let mut r = Self { x0: f64::INFINITY, y0: f64::INFINITY, x1: f64::NEG_INFINITY, y1: f64::NEG_INFINITY };
        for &(x, y) in points {
            r.x0 = r.x0.min(x);
            r.y0 = r.y0.min(y);
            r.x1 = r.x1.max(x);
            r.y1 = r.y1.max(y);
        }
        if r.x0 > r.x1 {
            return Self::new(0.0, 0.0, 0.0, 0.0);
        }
        r
    }
    pub fn width(&self) -> f64 {
        self.x1 - self.x0
    }
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }
    pub fn center(&self) -> (f64, f64) {
        (0.5 * (self.x0 + self.x1), 0.5 * (self.y0 + self.y1))
    }
    /// Area of the overlap with `o` (0 when apart).
    pub fn overlap(&self, o: &PxRect) -> f64 {
        let w = self.x1.min(o.x1) - self.x0.max(o.x0);
        let h = self.y1.min(o.y1) - self.y0.max(o.y0);
        if w > 0.0 && h > 0.0 {
            w * h
        } else {
            0.0
        }
    }
    /// Whether this rectangle lies wholly inside `o`.
    pub fn inside(&self, o: &PxRect) -> bool {
        self.x0 >= o.x0 && self.y0 >= o.y0 && self.x1 <= o.x1 && self.y1 <= o.y1
    }
    /// Moved the least distance to lie inside `area` (as far as it fits).
    pub fn pushed_into(&self, area: &PxRect) -> PxRect {
        let dx = if self.x0 < area.x0 {
            area.x0 - self.x0
        } else if self.x1 > area.x1 {
            (area.x1 - self.x1).max(area.x0 - self.x0)
        } else {
            0.0
        };
        let dy = if self.y0 < area.y0 {
            area.y0 - self.y0
        } else if self.y1 > area.y1 {
            (area.y1 - self.y1).max(area.y0 - self.y0)
        } else {
            0.0
        };
        PxRect { x0: self.x0 + dx, y0: self.y0 + dy, x1: self.x1 + dx, y1: self.y1 + dy }
    }
}

/// A label as drawn: its text and its box.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub text: String,
    pub rect: PxRect,
}

/// A road user (dynamic obstacle) as drawn at the picture's time.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnObstacle {
    pub id: u64,
    /// Its name from `RenderOptions::names`, if any.
    pub name: Option<String>,
    pub ego: bool,
    /// CommonRoad type (`car`, `pedestrian`, …).
    pub obstacle_type: &'static str,
    /// Its shape's length on the picture (a box's length, a circle's diameter), pixels.
    pub length_px: f64,
    /// The box holding its shape.
    pub bbox: PxRect,
    /// Where its centre (the state's position) is drawn.
    pub center: (f64, f64),
    pub label: Option<Label>,
}

/// What a picture shows, where.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    pub width: u32,
    pub height: u32,
    /// The part of the picture that shows the map (between the header and footer strips).
    pub map: PxRect,
    /// The world rectangle the map area shows, m.
    pub world: Bounds,
    /// Pixels per metre.
    pub scale: f64,
    pub obstacles: Vec<DrawnObstacle>,
}
