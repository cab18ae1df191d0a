//! Paints a display list into an RGBA pixmap with tiny-skia (anti-aliased, CPU only).

use tiny_skia::{Color, FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Rect, Stroke as SkStroke, StrokeDash, Transform};

use crate::error::Error;
use crate::font;
use crate::scene::prim::{Prim, Rgba, Stroke};

fn paint(c: Rgba) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(Color::from_rgba8(c.r, c.g, c.b, c.a));
    p.anti_alias = true;
    p
}

fn sk_stroke(s: &Stroke) -> SkStroke {
    SkStroke {
        width: s.width as f32,
        line_cap: LineCap::Butt,
        line_join: LineJoin::Round,
        dash: s.dash.and_then(|(on, off)| StrokeDash::new(vec![on as f32, off as f32], 0.0)),
        ..SkStroke::default()
    }
}

/// A blank pixmap of the background colour.
pub(crate) fn canvas(width: u32, height: u32, background: Rgba) -> Result<Pixmap, Error> {
    let mut pm = Pixmap::new(width, height).ok_or_else(|| Error::View(format!("cannot allocate a {width} × {height} picture")))?;
    pm.fill(Color::from_rgba8(background.r, background.g, background.b, background.a));
    Ok(pm)
}

/// Points far outside the picture are clamped: tiny-skia rejects paths with huge coordinates
/// and the lines that matter are near the picture anyway.
fn clamp(v: f64) -> f32 {
    v.clamp(-1.0e6, 1.0e6) as f32
}

fn fill_and_stroke(pm: &mut Pixmap, path: &tiny_skia::Path, fill: Option<Rgba>, stroke: Option<&Stroke>) {
    if let Some(c) = fill {
        pm.fill_path(path, &paint(c), FillRule::Winding, Transform::identity(), None);
    }
    if let Some(s) = stroke {
        if s.width > 0.0 {
            pm.stroke_path(path, &paint(s.color), &sk_stroke(s), Transform::identity(), None);
        }
    }
}

fn text(pm: &mut Pixmap, x: f64, y: f64, size: f64, color: Rgba, background: Option<Rgba>, s: &str) {
    // whole pixels, no anti-aliasing: a bitmap font is sharpest on the pixel grid
    let dot = font::dot_size(size);
    let pad = (1.5 * dot).round();
    let (x, y) = (x.round(), y.round());
    let flat = |c: Rgba| {
        let mut p = paint(c);
        p.anti_alias = false;
        p
    };
    if let Some(bg) = background {
        let (w, h) = font::text_box(s, size);
        if let Some(r) = Rect::from_xywh(x as f32, y as f32, w as f32, h as f32) {
            pm.fill_rect(r, &flat(bg), Transform::identity(), None);
        }
    }
    let p = flat(color);
    for (col, row) in font::dots(s) {
        let (dx, dy) = (x + pad + col as f64 * dot, y + pad + row as f64 * dot);
        if let Some(r) = Rect::from_xywh(dx as f32, dy as f32, dot as f32, dot as f32) {
            pm.fill_rect(r, &p, Transform::identity(), None);
        }
    }
}

/// Draws `prims` in order onto `pm`.
pub(crate) fn paint_prims(pm: &mut Pixmap, prims: &[Prim]) {
    for prim in prims {
        match prim {
            Prim::Path { points, closed, fill, stroke } => {
                let mut pb = PathBuilder::new();
                let mut it = points.iter();
                let Some(&(x0, y0)) = it.next() else { continue };
                pb.move_to(clamp(x0), clamp(y0));
                for &(x, y) in it {
                    pb.line_to(clamp(x), clamp(y));
                }
                if *closed {
                    pb.close();
                }
                if let Some(path) = pb.finish() {
                    let fill = if *closed { *fill } else { None };
                    fill_and_stroke(pm, &path, fill, stroke.as_ref());
                }
            }
            Prim::Circle { center, radius, fill, stroke } => {
                if let Some(path) = PathBuilder::from_circle(clamp(center.0), clamp(center.1), clamp(*radius)) {
                    fill_and_stroke(pm, &path, *fill, stroke.as_ref());
                }
            }
            Prim::Text { x, y, size, color, background, text: s } => text(pm, *x, *y, *size, *color, *background, s),
        }
    }
}
