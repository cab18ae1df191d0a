//! Points and shapes. Obstacle shapes ([`Shape`]) live in the obstacle's own frame (centred on
//! the state position, length along the heading); goal regions and environment obstacles use
//! [`AbsoluteShape`]s placed in the world frame. They are different types because writing a
//! `center` into an obstacle shape is read differently by commonroad-io 2024.3 (applies it) and
//! 2026.1 (ignores it).

use crate::error::{finite, positive, Error};

/// A point in metres; `z` is optional (written only when present).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: Option<f64>,
}

impl Point {
    /// A 2-D point.
    pub fn new(x: f64, y: f64) -> Self {
        Self { x, y, z: None }
    }
    /// A 3-D point.
    pub fn with_z(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z: Some(z) }
    }
    /// Whether every coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && !matches!(self.z, Some(z) if !z.is_finite())
    }
}

/// Length (along the heading) and width of a box, both > 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rectangle {
    length: f64,
    width: f64,
}

impl Rectangle {
    /// Fails unless both are finite and > 0.
    pub fn new(length: f64, width: f64) -> Result<Self, Error> {
        Ok(Self { length: positive("rectangle length", length)?, width: positive("rectangle width", width)? })
    }
    pub fn length(&self) -> f64 {
        self.length
    }
    pub fn width(&self) -> f64 {
        self.width
    }
}

/// A circle of radius > 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    radius: f64,
}

impl Circle {
    /// Fails unless the radius is finite and > 0.
    pub fn new(radius: f64) -> Result<Self, Error> {
        Ok(Self { radius: positive("circle radius", radius)? })
    }
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// A polygon of at least three finite points.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    points: Vec<Point>,
}

impl Polygon {
    /// Fails with fewer than 3 points or a non-finite coordinate.
    pub fn new(points: Vec<Point>) -> Result<Self, Error> {
        if points.len() < 3 {
            return Err(Error::TooFewPolygonPoints { got: points.len() });
        }
        for p in &points {
            finite("polygon x", p.x)?;
            finite("polygon y", p.y)?;
            if let Some(z) = p.z {
                finite("polygon z", z)?;
            }
        }
        Ok(Self { points })
    }
    pub fn points(&self) -> &[Point] {
        &self.points
    }
}

/// The shape of an obstacle, in its own frame (no centre, no orientation).
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Rectangle(Rectangle),
    Circle(Circle),
    Polygon(Polygon),
}

impl Shape {
    /// A `length` × `width` box (fails unless both > 0).
    pub fn rectangle(length: f64, width: f64) -> Result<Self, Error> {
        Rectangle::new(length, width).map(Shape::Rectangle)
    }
    /// A circle (fails unless `radius` > 0).
    pub fn circle(radius: f64) -> Result<Self, Error> {
        Circle::new(radius).map(Shape::Circle)
    }
}

/// A rectangle placed in the world: centre and orientation (rad, CCW from +x).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedRectangle {
    pub rectangle: Rectangle,
    pub center: Point,
    pub orientation: f64,
}

/// A circle placed in the world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedCircle {
    pub circle: Circle,
    pub center: Point,
}

/// A shape in world coordinates (environment obstacles).
#[derive(Debug, Clone, PartialEq)]
pub enum AbsoluteShape {
    Rectangle(PlacedRectangle),
    Circle(PlacedCircle),
    Polygon(Polygon),
}
