//! The stand-in's roads: a lanelet's centre line (the midpoints of its bound points, which the
//! CommonRoad model pairs one to one) as straight pieces, with the lanelet's width at each end
//! of a piece; and where a point lies along such a road (s, t), for signals.

use commonroad::{Lanelet, LaneletNetwork};

use crate::{Error, Warning};

/// Centre points closer than this are one point (a piece needs a positive length).
const MIN_PIECE: f64 = 1e-6;

/// One straight piece of a road's reference line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    pub s: f64,
    pub x: f64,
    pub y: f64,
    pub hdg: f64,
    pub length: f64,
    /// The lane's width at the start and at the end of the piece.
    pub w0: f64,
    pub w1: f64,
}

/// A lanelet as a road.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Road {
    pub lanelet: u64,
    pub pieces: Vec<Piece>,
}

impl Road {
    pub fn length(&self) -> f64 {
        self.pieces.last().map_or(0.0, |p| p.s + p.length)
    }

    /// The (s, t) of the point of the reference line nearest to (x, y).
    pub fn project(&self, x: f64, y: f64) -> (f64, f64) {
        let (_, s, t) = self.nearest(x, y);
        (s, t)
    }

    /// The distance from (x, y) to the reference line, and the (s, t) of its nearest point.
    pub fn nearest(&self, x: f64, y: f64) -> (f64, f64, f64) {
        let mut best = (f64::INFINITY, 0.0, 0.0);
        for p in &self.pieces {
            let (sin, cos) = p.hdg.sin_cos();
            let (dx, dy) = (x - p.x, y - p.y);
            let along = (dx * cos + dy * sin).clamp(0.0, p.length);
            let t = -dx * sin + dy * cos;
            let (ex, ey) = (dx - along * cos, dy - along * sin);
            let d = ex.hypot(ey);
            if d < best.0 {
                best = (d, p.s + along, t);
            }
        }
        best
    }
}

fn finite(what: impl Fn() -> String, v: f64) -> Result<f64, Error> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::NotFinite(what()))
    }
}

fn road(l: &Lanelet, warnings: &mut Vec<Warning>) -> Result<Option<Road>, Error> {
    let mut points: Vec<(f64, f64, f64)> = Vec::new();
    for (a, b) in l.bounds.left().iter().zip(l.bounds.right()) {
        let what = || format!("lanelet {} bound point", l.id);
        let (x, y) = (finite(what, 0.5 * (a.x + b.x))?, finite(what, 0.5 * (a.y + b.y))?);
        let w = (a.x - b.x).hypot(a.y - b.y);
        match points.last() {
            Some(&(px, py, _)) if (x - px).hypot(y - py) < MIN_PIECE => {}
            _ => points.push((x, y, w)),
        }
    }
    if points.len() < 2 {
        warnings.push(Warning { message: format!("lanelet {}: its centre line has no length; no road is written for it", l.id) });
        return Ok(None);
    }
    let mut pieces = Vec::with_capacity(points.len() - 1);
    let mut s = 0.0;
    for w in points.windows(2) {
        let ((x0, y0, w0), (x1, y1, w1)) = (w[0], w[1]);
        let length = (x1 - x0).hypot(y1 - y0);
        pieces.push(Piece { s, x: x0, y: y0, hdg: (y1 - y0).atan2(x1 - x0), length, w0, w1 });
        s += length;
    }
    Ok(Some(Road { lanelet: l.id.get(), pieces }))
}

/// A road per lanelet with a centre line of positive length, in the network's order.
pub(crate) fn roads(network: &LaneletNetwork, warnings: &mut Vec<Warning>) -> Result<Vec<Road>, Error> {
    let mut out = Vec::with_capacity(network.lanelets.len());
    for l in &network.lanelets {
        if let Some(r) = road(l, warnings)? {
            out.push(r);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(s: f64, x: f64, y: f64, hdg: f64, length: f64) -> Piece {
        Piece { s, x, y, hdg, length, w0: 3.0, w1: 3.0 }
    }

    #[test]
    fn projection_finds_the_nearest_piece() {
        // east 10 m, then north 10 m
        let r = Road { lanelet: 1, pieces: vec![piece(0.0, 0.0, 0.0, 0.0, 10.0), piece(10.0, 10.0, 0.0, std::f64::consts::FRAC_PI_2, 10.0)] };
        let (s, t) = r.project(4.0, -1.0);
        assert!((s - 4.0).abs() < 1e-12 && (t + 1.0).abs() < 1e-12, "{s} {t}");
        let (s, t) = r.project(11.0, 6.0);
        assert!((s - 16.0).abs() < 1e-12 && (t + 1.0).abs() < 1e-12, "{s} {t}");
        assert!((r.length() - 20.0).abs() < 1e-12);
    }
}
