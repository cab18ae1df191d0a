//! The header strip: the time, and the storyboard events that have happened by then — those of
//! one time step together, each group with its start time (also those starting at the header's
//! time), the newest on the right (cut short if it alone is too long), highlighted for
//! [`style::MARK_HIGHLIGHT_S`] after it happens.

use super::prim::{Prim, Rgba, Stroke};
use super::time_label;
use crate::font;
use crate::options::Mark;
use crate::style;
use crate::timeline::step_of;

/// Space around and between the strip's texts, in font dots.
const PAD_DOTS: f64 = 3.0;

/// Height of the header of a picture `width` pixels wide.
pub fn height(width: u32) -> f64 {
    let size = style::text_size(width);
    font::text_box("t", size).1 + 2.0 * PAD_DOTS * style::text_dot(width)
}

/// `4.6 s CutIn`: a mark at the resolution of the time step.
pub fn mark_text(m: &Mark, dt: f64) -> String {
    let step = step_of(m.time, dt);
    let t = time_label(step, dt);
    format!("{} {}", t.trim_start_matches("t = "), m.text)
}

/// A plain strip across a picture `width` wide, its top at row `y`, `h` high (the header, the
/// time bar and the footer stand on one).
pub fn strip(y: f64, width: u32, h: f64, out: &mut Vec<Prim>) {
    let w = f64::from(width);
    out.push(Prim::Path { points: vec![(0.0, y), (w, y), (w, y + h), (0.0, y + h)], closed: true, fill: Some(style::STRIP), stroke: None });
}

fn rule(y: f64, width: u32, out: &mut Vec<Prim>) {
    out.push(Prim::Path { points: vec![(0.0, y), (f64::from(width), y)], closed: false, fill: None, stroke: Some(Stroke::solid(style::STRIP_LINE, 1.0)) });
}

fn text(x: f64, y: f64, size: f64, color: Rgba, background: Option<Rgba>, s: String) -> Prim {
    Prim::Text { x, y, size, color, background, text: s }
}

/// The header of the picture at `step`: time on the left, then the marks up to `step`
/// (as many of the newest as fit).
pub fn header(width: u32, step: u64, dt: f64, marks: &[Mark], out: &mut Vec<Prim>) {
    let h = height(width);
    strip(0.0, width, h, out);
    rule(h - 0.5, width, out);
    let size = style::text_size(width);
    let pad = PAD_DOTS * style::text_dot(width);
    let stamp = time_label(step, dt);
    let stamp_w = font::text_box(&stamp, size).0;
    out.push(text(pad, pad, size, style::TEXT, None, stamp));

    let now = step as f64 * dt;
    // the marks so far, those of one step together: (step, "A, B")
    let mut groups: Vec<(u64, String)> = Vec::new();
    for m in marks.iter().filter(|m| step_of(m.time, dt) <= step) {
        let k = step_of(m.time, dt);
        match groups.iter_mut().find(|(g, _)| *g == k) {
            Some((_, text)) => {
                text.push_str(", ");
                text.push_str(&m.text);
            }
            None => groups.push((k, m.text.clone())),
        }
    }
    groups.sort_by_key(|(k, _)| *k);
    let x_first = pad + stamp_w + 2.0 * pad;
    let room = f64::from(width) - pad - x_first;
    let dot = style::text_dot(width);
    // the newest that fit, kept in time order; the newest cut short if it alone is too long
    let mut shown: Vec<(String, bool, f64)> = Vec::new();
    let mut used = 0.0;
    for (i, (k, text)) in groups.iter().rev().enumerate() {
        // each with its start time, the events of this very step too
        let mut s = mark_text(&Mark { time: *k as f64 * dt, text: text.clone() }, dt);
        let mut w = font::text_box(&s, size).0;
        if i == 0 && w > room {
            let chars = ((room - 3.0 * dot) / (font::ADVANCE as f64 * dot)).floor().max(0.0) as usize;
            s = font::truncate(&s, chars);
            w = font::text_box(&s, size).0;
        }
        if used + w > room {
            break;
        }
        used += w + pad;
        let fresh = now - *k as f64 * dt < style::MARK_HIGHLIGHT_S - 1e-9;
        shown.push((s, fresh, w));
    }
    let mut x = x_first;
    for (s, fresh, w) in shown.into_iter().rev() {
        let (color, bg) = if fresh { (style::TEXT, Some(style::MARK_NEW)) } else { (style::MUTED, None) };
        out.push(text(x, pad, size, color, bg, s));
        x += w + pad;
    }
}
