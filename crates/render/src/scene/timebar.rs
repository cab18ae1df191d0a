//! The time bar under the map: the run from its first to its last step, a tick at each
//! storyboard event, the part already run darker and a knob at the picture's time, and under
//! it a time scale (ticks labelled in seconds every 1, 2 or 5 × 10^k s) — when the events
//! happen, at a glance.

use super::prim::{Prim, Stroke};
use crate::font;
use crate::options::Mark;
use crate::style;
use crate::timeline::step_of;

/// Height of the bar itself (the line, the event ticks, the knob), in font dots.
const BAR_DOTS: f64 = 7.0;

/// Pixels per font dot of the time scale's labels: the size of the header's text (one dot
/// smaller is too small for the 5×7 font's lower case).
fn label_dot(width: u32) -> f64 {
    style::text_dot(width)
}

fn label_size(width: u32) -> f64 {
    style::text_size(width)
}

/// Height of the bar's strip in a picture `width` wide.
pub(super) fn height(width: u32) -> f64 {
    BAR_DOTS * style::text_dot(width) + font::text_box("0", label_size(width)).1
}

/// The time between labelled ticks: the smallest of 1, 2, 5 × 10^k s that leaves at least
/// `min_gap` pixels between ticks on a bar `span_px` long for `seconds`.
fn tick_interval(seconds: f64, span_px: f64, min_gap: f64) -> f64 {
    let mut k = -2;
    while k <= 6 {
        for m in [1.0, 2.0, 5.0] {
            let t = m * 10f64.powi(k);
            if seconds <= 0.0 || t * span_px / seconds >= min_gap {
                return t;
            }
        }
        k += 1;
    }
    1e6
}

/// `5 s`, `2.5 s`, `0.1 s`: a tick's time without trailing zeros.
fn seconds_text(t: f64) -> String {
    let mut s = format!("{t:.2}");
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    format!("{s} s")
}

/// The bar with its strip's top at row `y`, for the picture at `step` of a run from `first`
/// to `last`.
#[allow(clippy::too_many_arguments)]
pub(super) fn bar(width: u32, y: f64, first: u64, last: u64, step: u64, dt: f64, marks: &[Mark], out: &mut Vec<Prim>) {
    let dot = style::text_dot(width);
    let h = height(width);
    let w = f64::from(width);
    super::header::strip(y, width, h, out);
    let (x0, x1) = (3.0 * dot, w - 3.0 * dot);
    let ym = y + 0.5 * BAR_DOTS * dot;
    let span = last.saturating_sub(first).max(1) as f64;
    let x_of = |k: u64| x0 + (x1 - x0) * (k.clamp(first, last) - first) as f64 / span;
    let line =
        |a: f64, b: f64, color, width| Prim::Path { points: vec![(a, ym), (b, ym)], closed: false, fill: None, stroke: Some(Stroke::solid(color, width)) };
    out.push(line(x0, x1, style::STRIP_LINE, dot));
    out.push(line(x0, x_of(step), style::MUTED, dot));
    scale(width, y + BAR_DOTS * dot, (x0, x1), (first as f64 * dt, span * dt), out);
    for m in marks {
        let x = x_of(step_of(m.time, dt));
        out.push(Prim::Path {
            points: vec![(x - dot, ym - 2.5 * dot), (x + dot, ym - 2.5 * dot), (x + dot, ym + 2.5 * dot), (x - dot, ym + 2.5 * dot)],
            closed: true,
            fill: Some(style::MARK_NEW),
            stroke: Some(Stroke::solid(style::MUTED, 1.0)),
        });
    }
    out.push(Prim::Circle { center: (x_of(step), ym), radius: 2.0 * dot, fill: Some(style::TEXT), stroke: Some(Stroke::solid(style::STRIP, 1.0)) });
}

/// The time scale under the bar, its top at row `top`: a short tick and its time every
/// interval from `start` s over `seconds`, between pixels `x0` and `x1`.
fn scale(width: u32, top: f64, (x0, x1): (f64, f64), (start, seconds): (f64, f64), out: &mut Vec<Prim>) {
    let size = label_size(width);
    let ldot = label_dot(width);
    // room for the widest label and a gap
    let widest = font::text_box(&seconds_text(start + seconds), size).0;
    let every = tick_interval(seconds, x1 - x0, widest + 4.0 * ldot);
    let first = (start / every).ceil() as i64;
    let last = ((start + seconds) / every + 1e-9).floor() as i64;
    for i in first..=last {
        let t = i as f64 * every;
        let x = x0 + (x1 - x0) * (t - start) / seconds.max(f64::MIN_POSITIVE);
        // the tick down the label's left, the label after it (a tick above a centred label
        // would read as an apostrophe)
        let (_, th) = font::text_box("0", size);
        out.push(Prim::Path {
            points: vec![(x, top - 1.5 * ldot), (x, top + th - 2.0 * ldot)],
            closed: false,
            fill: None,
            stroke: Some(Stroke::solid(style::MUTED, 1.0)),
        });
        let text = seconds_text(t);
        let tw = font::text_box(&text, size).0;
        let tx = (x - 0.5 * ldot).min(f64::from(width) - tw);
        out.push(Prim::Text { x: tx, y: top, size, color: style::MUTED, background: None, text });
    }
}

#[cfg(test)]
mod tests {
    use super::{seconds_text, tick_interval};

    #[test]
    fn ticks_are_one_two_or_five_times_a_power_of_ten_and_leave_room() {
        assert_eq!(tick_interval(20.0, 1000.0, 60.0), 2.0);
        assert_eq!(tick_interval(20.0, 300.0, 60.0), 5.0);
        assert_eq!(tick_interval(1.0, 1000.0, 60.0), 0.1);
        assert_eq!(seconds_text(5.0), "5 s");
        assert_eq!(seconds_text(2.5), "2.5 s");
        assert_eq!(seconds_text(0.0), "0 s");
    }
}
