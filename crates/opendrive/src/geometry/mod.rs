//! Plan-view geometry in f64: one file per primitive, each evaluated in its own local frame
//! (start at the origin heading +x) and placed by [`Geometry::pose_at`].

pub mod arc;
pub mod arc_length_table;
pub mod gauss_legendre;
pub mod line;
pub mod param_poly3;
pub mod poly3;
pub mod pose;
pub mod spiral;

pub use param_poly3::{PRange, ParamPoly3};
pub use poly3::Poly3;
pub use pose::CurvePose;
pub use spiral::Spiral;

/// The shape of one plan-view record.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Line,
    Arc { curvature: f64 },
    Spiral(Spiral),
    Poly3(Poly3),
    ParamPoly3(ParamPoly3),
}

/// `<planView><geometry>`: a primitive placed at (x, y, hdg), valid for s ∈ [s, s + length].
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    pub s: f64,
    pub x: f64,
    pub y: f64,
    pub hdg: f64,
    pub length: f64,
    pub shape: Shape,
    /// `hdg.sin_cos()` and the bits of the `hdg` it was computed from: every world pose needs
    /// them, and `hdg` (a public field) is checked against the bits before the pair is used.
    hdg_trig: (u64, f64, f64),
}

fn trig_of(hdg: f64) -> (u64, f64, f64) {
    let (sin, cos) = hdg.sin_cos();
    (hdg.to_bits(), sin, cos)
}

impl Geometry {
    /// A primitive placed at (x, y, hdg) from `s` for `length`.
    pub fn new(s: f64, x: f64, y: f64, hdg: f64, length: f64, shape: Shape) -> Geometry {
        Geometry { s, x, y, hdg, length, shape, hdg_trig: trig_of(hdg) }
    }

    /// Turn the start heading to `hdg`.
    pub fn set_hdg(&mut self, hdg: f64) {
        self.hdg = hdg;
        self.hdg_trig = trig_of(hdg);
    }

    /// `self.hdg.sin_cos()`: the stored pair when `hdg` still has the bits it was computed
    /// from (the same call on the same value, so the same bits), else computed afresh.
    fn hdg_sin_cos(&self) -> (f64, f64) {
        let (bits, sin, cos) = self.hdg_trig;
        if bits == self.hdg.to_bits() {
            (sin, cos)
        } else {
            self.hdg.sin_cos()
        }
    }

    /// Local-frame pose `ds` past the geometry start.
    pub fn local_at(&self, ds: f64) -> CurvePose {
        match &self.shape {
            Shape::Line => line::line_local(ds),
            Shape::Arc { curvature } => arc::arc_local(*curvature, ds),
            Shape::Spiral(sp) => sp.local(ds),
            Shape::Poly3(p) => p.local(ds),
            Shape::ParamPoly3(p) => p.local(ds),
        }
    }

    /// World pose `ds` past the geometry start.
    pub fn pose_at(&self, ds: f64) -> CurvePose {
        let l = self.local_at(ds);
        let (sin, cos) = self.hdg_sin_cos();
        CurvePose { x: self.x + l.x * cos - l.y * sin, y: self.y + l.x * sin + l.y * cos, hdg: self.hdg + l.hdg, curvature: l.curvature }
    }

    /// Largest |curvature| of the primitive (sampled for the polynomial ones).
    pub fn max_abs_curvature(&self) -> f64 {
        match &self.shape {
            Shape::Line => 0.0,
            Shape::Arc { curvature } => curvature.abs(),
            Shape::Spiral(sp) => sp.curv_start.abs().max(sp.curv_end.abs()),
            Shape::Poly3(_) | Shape::ParamPoly3(_) => (0..=16).map(|i| self.local_at(self.length * f64::from(i) / 16.0).curvature.abs()).fold(0.0, f64::max),
        }
    }
}
