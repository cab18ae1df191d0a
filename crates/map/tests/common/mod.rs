//! Helpers shared by the map tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The workspace's example road (shipped, always present).
pub(crate) fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(name)
}

/// A corpus map by its path under `shared/corpus`, or `None` (test returns early) when the
/// shared directory is missing and CI is not set.
pub(crate) fn corpus(rel: &str) -> Option<PathBuf> {
    testkit::shared_dir().map(|s| s.join("corpus").join(rel))
}

pub(crate) fn load(path: &Path) -> opendrive::RoadNetwork {
    match opendrive::load(path) {
        Ok(l) => l.network,
        Err(e) => panic!("{e}"),
    }
}

pub(crate) fn convert(net: &opendrive::RoadNetwork) -> map::MapResult {
    map::convert(net, &map::MapOptions::default())
}

/// Distance from (x, y) to a polyline.
pub(crate) fn dist_to_polyline(x: f64, y: f64, pts: &[commonroad::Point]) -> f64 {
    let mut best = f64::INFINITY;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let l2 = dx * dx + dy * dy;
        let u = if l2 > 0.0 { (((x - a.x) * dx + (y - a.y) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
        best = best.min((x - a.x - u * dx).hypot(y - a.y - u * dy));
    }
    best
}
