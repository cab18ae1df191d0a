//! The display list: what to draw, in pixel coordinates, independent of the output format.
//! Both painters (raster and SVG) draw the same list, so a PNG and an SVG show the same thing.

/// A straight (not premultiplied) colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Rgba {
    pub r: u8,
    pub g: u8,
    pub b: u8,
    pub a: u8,
}

impl Rgba {
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b, a: 255 }
    }
    pub const fn with_alpha(self, a: u8) -> Self {
        Self { a, ..self }
    }
    /// `#rrggbb` (alpha separately, as SVG wants it).
    pub fn hex(&self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }
}

/// A line style: width and dash pattern in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    pub color: Rgba,
    pub width: f64,
    /// (on, off) lengths; `None` = solid.
    pub dash: Option<(f64, f64)>,
}

impl Stroke {
    pub fn solid(color: Rgba, width: f64) -> Self {
        Self { color, width, dash: None }
    }
    pub fn dashed(color: Rgba, width: f64, on: f64, off: f64) -> Self {
        Self { color, width, dash: Some((on, off)) }
    }
}

/// One thing to draw.
#[derive(Debug, Clone, PartialEq)]
pub enum Prim {
    /// A polyline, or a polygon when `closed`.
    Path {
        points: Vec<(f64, f64)>,
        closed: bool,
        fill: Option<Rgba>,
        stroke: Option<Stroke>,
    },
    Circle {
        center: (f64, f64),
        radius: f64,
        fill: Option<Rgba>,
        stroke: Option<Stroke>,
    },
    /// Text whose top-left corner is at (x, y); `size` is the height of a capital in pixels.
    Text {
        x: f64,
        y: f64,
        size: f64,
        color: Rgba,
        background: Option<Rgba>,
        text: String,
    },
}

/// A picture: its size, background and two layers. `still` does not change with time (the
/// map, static obstacles, goal regions), `moving` does; an animation draws `still` once.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub width: u32,
    pub height: u32,
    pub background: Rgba,
    pub still: Vec<Prim>,
    pub moving: Vec<Prim>,
}
