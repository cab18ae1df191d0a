//! Reading back the pictures `osc2cr render` writes (tests only).

use std::collections::BTreeSet;
use std::path::Path;

/// A decoded PNG: its size and RGBA bytes.
pub(crate) struct Png {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
}

impl Png {
    pub(crate) fn read(path: &Path) -> Png {
        let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let (width, height, rgba) = render::decode_png(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        Png { width, height, rgba }
    }

    /// The colour of the pixel at (x, y).
    pub(crate) fn at(&self, x: f64, y: f64) -> [u8; 3] {
        let i = 4 * (y as usize * self.width as usize + x as usize);
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2]]
    }

    /// Every colour in the picture.
    pub(crate) fn colors(&self) -> BTreeSet<[u8; 3]> {
        self.rgba.chunks_exact(4).map(|p| [p[0], p[1], p[2]]).collect()
    }

    /// How many pixels have colour `c`.
    pub(crate) fn count(&self, c: render::scene::prim::Rgba) -> usize {
        self.rgba.chunks_exact(4).filter(|p| p[..3] == [c.r, c.g, c.b]).count()
    }

    /// How many pixels of colour `c` lie in the rectangle [x0, y0, x1, y1].
    pub(crate) fn count_in(&self, r: &[f64], c: render::scene::prim::Rgba) -> usize {
        let mut n = 0;
        for y in r[1].max(0.0) as u32..(r[3].min(f64::from(self.height))) as u32 {
            for x in r[0].max(0.0) as u32..(r[2].min(f64::from(self.width))) as u32 {
                if self.at(f64::from(x), f64::from(y)) == [c.r, c.g, c.b] {
                    n += 1;
                }
            }
        }
        n
    }
}
