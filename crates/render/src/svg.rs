//! Writes a display list as SVG text (written by hand: the format is simple and this keeps the
//! output deterministic and dependency-free).

use std::fmt::Write;

use crate::font;
use crate::scene::prim::{Prim, Rgba, Scene, Stroke};

/// A coordinate with at most 2 decimals (1/100 px is invisible), trailing zeros dropped.
fn n(v: f64) -> String {
    let v = if v.is_finite() { v.clamp(-1.0e6, 1.0e6) } else { 0.0 };
    let mut s = format!("{v:.2}");
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

fn opacity(c: Rgba) -> f64 {
    f64::from(c.a) / 255.0
}

fn paint_attrs(fill: Option<Rgba>, stroke: Option<&Stroke>) -> String {
    let mut a = String::new();
    match fill {
        Some(c) => {
            let _ = write!(a, " fill=\"{}\"", c.hex());
            if c.a < 255 {
                let _ = write!(a, " fill-opacity=\"{:.3}\"", opacity(c));
            }
        }
        None => a.push_str(" fill=\"none\""),
    }
    if let Some(s) = stroke {
        let _ = write!(a, " stroke=\"{}\" stroke-width=\"{}\"", s.color.hex(), n(s.width));
        if s.color.a < 255 {
            let _ = write!(a, " stroke-opacity=\"{:.3}\"", opacity(s.color));
        }
        if let Some((on, off)) = s.dash {
            let _ = write!(a, " stroke-dasharray=\"{} {}\"", n(on), n(off));
        }
        a.push_str(" stroke-linejoin=\"round\"");
    }
    a
}

fn prim(out: &mut String, p: &Prim) {
    match p {
        Prim::Path { points, closed, fill, stroke } => {
            if points.is_empty() {
                return;
            }
            let mut d = String::new();
            for (i, (x, y)) in points.iter().enumerate() {
                let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { " L" }, n(*x), n(*y));
            }
            if *closed {
                d.push_str(" Z");
            }
            let fill = if *closed { *fill } else { None };
            let _ = writeln!(out, "<path d=\"{d}\"{}/>", paint_attrs(fill, stroke.as_ref()));
        }
        Prim::Circle { center, radius, fill, stroke } => {
            let _ = writeln!(out, "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"{}/>", n(center.0), n(center.1), n(*radius), paint_attrs(*fill, stroke.as_ref()));
        }
        Prim::Text { x, y, size, color, background, text } => {
            // the same box as the bitmap font, so both formats place the stamp alike
            let dot = font::dot_size(*size);
            let pad = (1.5 * dot).round();
            let size = font::GLYPH_H as f64 * dot;
            if let Some(bg) = background {
                let (w, h) = font::text_box(text, size);
                let _ = writeln!(out, "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"{}/>", n(*x), n(*y), n(w), n(h), paint_attrs(Some(*bg), None));
            }
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\" font-family=\"monospace\" font-size=\"{}\" fill=\"{}\">{}</text>",
                n(x + pad),
                n(y + pad + size),
                n(size * 1.4),
                color.hex(),
                escape(text)
            );
        }
    }
}

/// The whole scene as an SVG document.
pub(crate) fn to_svg(scene: &Scene) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">",
        w = scene.width,
        h = scene.height
    );
    let _ = writeln!(out, "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"{}\"/>", scene.width, scene.height, scene.background.hex());
    for (id, layer) in [("still", &scene.still), ("moving", &scene.moving)] {
        let _ = writeln!(out, "<g id=\"{id}\">");
        layer.iter().for_each(|p| prim(&mut out, p));
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
}
