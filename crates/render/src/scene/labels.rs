//! Labels of road users: `name (id)` (or `id N` without a name), the ego's marked, each put
//! beside its box where it covers the fewest other labels and boxes, inside the map area.

use super::prim::{Prim, Stroke};
use crate::font;
use crate::layout::{Label, PxRect};
use crate::style;

/// The text of a label.
pub(super) fn text(id: u64, name: Option<&str>, ego: bool) -> String {
    let base = match name {
        Some(n) if !n.trim().is_empty() => format!("{} ({id})", n.trim()),
        _ => format!("id {id}"),
    };
    let says_ego = name.is_some_and(|n| n.to_ascii_lowercase().contains("ego"));
    if ego && !says_ego {
        format!("{base} ego")
    } else {
        base
    }
}

/// Gap between a box and its label, pixels.
const GAP: f64 = 3.0;
/// How many rings of places further out a label may take when the places beside its box are
/// taken.
const RINGS: usize = 3;

/// Where each label goes: `boxes` are the road users' boxes, `texts` their labels (same
/// order); the labels stay inside `area`.
pub(super) fn place(boxes: &[PxRect], texts: &[String], size: f64, area: &PxRect) -> Vec<PxRect> {
    let mut placed: Vec<PxRect> = Vec::new();
    for (b, t) in boxes.iter().zip(texts) {
        let (w, h) = font::text_box(t, size);
        let (cx, cy) = b.center();
        // beside the box first, then further out (a line then leads to the box)
        let mut candidates = vec![
            (cx - 0.5 * w, b.y0 - GAP - h),
            (cx - 0.5 * w, b.y1 + GAP),
            (b.x1 + GAP, cy - 0.5 * h),
            (b.x0 - GAP - w, cy - 0.5 * h),
            (b.x1 + GAP, b.y0 - GAP - h),
            (b.x0 - GAP - w, b.y0 - GAP - h),
            (b.x1 + GAP, b.y1 + GAP),
            (b.x0 - GAP - w, b.y1 + GAP),
        ];
        for ring in 1..=RINGS {
            let dy = ring as f64 * (h + GAP);
            let dx = ring as f64 * 0.5 * w;
            candidates.extend([
                (cx - 0.5 * w, b.y0 - GAP - h - dy),
                (cx - 0.5 * w, b.y1 + GAP + dy),
                (b.x1 + GAP + dx, cy - 0.5 * h),
                (b.x0 - GAP - w - dx, cy - 0.5 * h),
            ]);
        }
        let mut best: Option<(f64, PxRect)> = None;
        for (k, (x, y)) in candidates.into_iter().enumerate() {
            let r = PxRect::new(x, y, w, h).pushed_into(area);
            let cost: f64 = placed.iter().chain(boxes).map(|o| o.overlap(&r)).sum::<f64>()
                // a label pushed away from its box reads as someone else's
                + 0.05 * (r.x0 - x).abs().max((r.y0 - y).abs()) * h
                // nearer places first when both are free
                + 0.01 * (k / 4) as f64;
            if best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, r));
            }
        }
        if let Some((_, r)) = best {
            placed.push(r);
        }
    }
    placed
}

/// The point of `r` nearest to (x, y).
fn nearest(r: &PxRect, (x, y): (f64, f64)) -> (f64, f64) {
    (x.clamp(r.x0, r.x1), y.clamp(r.y0, r.y1))
}

/// The label prims: each label, and a thin line to its road user's box when it had to sit
/// away from it.
pub(super) fn prims(labels: &[(Label, bool, PxRect)], size: f64, out: &mut Vec<Prim>) {
    for (l, _, b) in labels {
        let from = nearest(&l.rect, b.center());
        let to = nearest(b, from);
        if (from.0 - to.0).hypot(from.1 - to.1) > 2.0 * GAP {
            out.push(Prim::Path { points: vec![from, to], closed: false, fill: None, stroke: Some(Stroke::solid(style::MUTED, 1.0)) });
        }
    }
    for (l, ego, _) in labels {
        out.push(Prim::Text {
            x: l.rect.x0,
            y: l.rect.y0,
            size,
            color: style::TEXT,
            background: Some(if *ego { style::EGO_LABEL_BACKGROUND } else { style::LABEL_BACKGROUND }),
            text: l.text.clone(),
        });
    }
}
