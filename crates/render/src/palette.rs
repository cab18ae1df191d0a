//! A 256-colour palette for GIF frames: every colour of the style first (so obstacle, ego and
//! road colours are exact), then the most frequent other colours of sample frames (the
//! anti-aliased shades), and a nearest-colour lookup with a cache.

use std::collections::{BTreeMap, HashMap};

use crate::scene::prim::Rgba;
use crate::style;

/// Opaque colours of the style (alpha blends are found by sampling).
fn style_colors() -> Vec<[u8; 3]> {
    use commonroad::{DynamicObstacleType as D, EnvironmentObstacleType as E, StaticObstacleType as S, TrafficLightColor as L};
    let mut v: Vec<Rgba> = vec![
        style::BACKGROUND,
        style::ROAD,
        style::BORDER,
        style::MARKING,
        style::CURB,
        style::OUTLINE,
        style::EGO,
        style::GOAL,
        style::SIGN,
        style::TEXT,
        style::STRIP,
        style::STRIP_LINE,
        style::MARK_NEW,
        style::MUTED,
        style::EGO_LABEL_BACKGROUND,
    ];
    v.extend(D::ALL.iter().map(|t| style::dynamic_color(*t)));
    v.extend(S::ALL.iter().map(|t| style::static_color(*t)));
    v.extend(E::ALL.iter().map(|t| style::environment_color(*t)));
    v.extend(L::ALL.iter().map(|t| style::light_color(*t)));
    let mut out: Vec<[u8; 3]> = Vec::new();
    for c in v {
        let rgb = [c.r, c.g, c.b];
        if !out.contains(&rgb) {
            out.push(rgb);
        }
    }
    out
}

/// The palette and a cache of lookups.
pub(crate) struct Palette {
    colors: Vec<[u8; 3]>,
    cache: HashMap<[u8; 3], u8>,
}

impl Palette {
    /// Style colours, then the most frequent colours of `samples` (RGBA pixel data).
    pub(crate) fn from_samples(samples: &[&[u8]]) -> Self {
        let mut colors = style_colors();
        // BTreeMap: a deterministic order among colours of equal count
        let mut counts: BTreeMap<[u8; 3], u64> = BTreeMap::new();
        for data in samples {
            for px in data.chunks_exact(4) {
                *counts.entry([px[0], px[1], px[2]]).or_insert(0) += 1;
            }
        }
        let mut by_count: Vec<([u8; 3], u64)> = counts.into_iter().collect();
        by_count.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        for (c, _) in by_count {
            if colors.len() >= 256 {
                break;
            }
            if !colors.contains(&c) {
                colors.push(c);
            }
        }
        Self { colors, cache: HashMap::new() }
    }

    /// `r g b r g b …`, padded to 256 entries.
    pub(crate) fn bytes(&self) -> Vec<u8> {
        let mut out: Vec<u8> = self.colors.iter().flatten().copied().collect();
        out.resize(256 * 3, 0);
        out
    }

    /// Index of the nearest palette colour (squared RGB distance; first on ties).
    pub(crate) fn index(&mut self, rgb: [u8; 3]) -> u8 {
        if let Some(&i) = self.cache.get(&rgb) {
            return i;
        }
        let d = |c: &[u8; 3]| -> i32 {
            (0..3)
                .map(|k| {
                    let e = i32::from(c[k]) - i32::from(rgb[k]);
                    e * e
                })
                .sum()
        };
        let mut best = (i32::MAX, 0usize);
        for (i, c) in self.colors.iter().enumerate() {
            let di = d(c);
            if di < best.0 {
                best = (di, i);
            }
        }
        let i = u8::try_from(best.1).unwrap_or(0);
        self.cache.insert(rgb, i);
        i
    }
}
