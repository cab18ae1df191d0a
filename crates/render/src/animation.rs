//! The animated GIF: every k-th time step over the whole scenario, the map painted once (per
//! frame when the view follows a road user), each frame stored as the rectangle that changed,
//! delays matching the scenario's time.

use std::borrow::Cow;

use gif::{DisposalMethod, Encoder, Frame, Repeat};
use tiny_skia::Pixmap;

use crate::error::Error;
use crate::palette::Palette;
use crate::raster::{canvas, paint_prims};
use crate::scene::Prepared;
use crate::style;
use crate::timeline::{first_step, last_step};

/// GIF delays are centiseconds and viewers show delays below 2 cs as 10 cs, so a frame lasts
/// at least this long (the stride grows for very small time steps).
const MIN_DELAY_S: f64 = 0.02;

fn encode_error(e: impl std::fmt::Display) -> Error {
    Error::Encode { format: "GIF", message: e.to_string() }
}

/// The smallest rectangle (x, y, w, h) in which `a` and `b` differ, or `None`.
fn changed_rect(a: &[u8], b: &[u8], width: usize) -> Option<(usize, usize, usize, usize)> {
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    for (i, (p, q)) in a.chunks_exact(4).zip(b.chunks_exact(4)).enumerate() {
        if p != q {
            let (x, y) = (i % width, i / width);
            x0 = x0.min(x);
            y0 = y0.min(y);
            x1 = x1.max(x);
            y1 = y1.max(y);
        }
    }
    (x0 != usize::MAX).then(|| (x0, y0, x1 - x0 + 1, y1 - y0 + 1))
}

struct Frames<'p, 'a> {
    prepared: &'p Prepared<'a>,
    /// The map painted once when the view does not move.
    base: Pixmap,
}

impl Frames<'_, '_> {
    fn at(&self, step: u64) -> Pixmap {
        let mut pm = self.base.clone();
        if !self.prepared.is_fixed() {
            paint_prims(&mut pm, &self.prepared.base(step));
        }
        paint_prims(&mut pm, &self.prepared.moving(step));
        pm
    }
}

fn to_u16(v: usize) -> Result<u16, Error> {
    u16::try_from(v).map_err(|_| encode_error(format!("{v} pixels is too large for a GIF")))
}

fn encode(frames: &Frames, steps: &[u64], stride: u64, dt: f64, palette: &mut Palette) -> Result<Vec<u8>, Error> {
    let (w, h) = (frames.base.width() as usize, frames.base.height() as usize);
    let mut out = Vec::new();
    {
        let mut enc = Encoder::new(&mut out, to_u16(w)?, to_u16(h)?, &palette.bytes()).map_err(encode_error)?;
        enc.set_repeat(Repeat::Infinite).map_err(encode_error)?;
        let centis = |s: u64| (s as f64 * dt * 100.0).round() as i64;
        let mut previous: Option<Pixmap> = None;
        for (i, &step) in steps.iter().enumerate() {
            let pm = frames.at(step);
            let next = steps.get(i + 1).copied().unwrap_or(step.saturating_add(stride));
            let delay = (centis(next) - centis(step)).clamp(2, i64::from(u16::MAX)) as u16;
            let rect = match &previous {
                None => Some((0, 0, w, h)),
                Some(prev) => changed_rect(prev.data(), pm.data(), w),
            };
            // an unchanged frame still needs its delay: store one pixel
            let (x, y, fw, fh) = rect.unwrap_or((0, 0, 1, 1));
            let data = pm.data();
            let mut buffer = Vec::with_capacity(fw * fh);
            for row in y..y + fh {
                let start = (row * w + x) * 4;
                for px in data[start..start + fw * 4].chunks_exact(4) {
                    buffer.push(palette.index([px[0], px[1], px[2]]));
                }
            }
            let frame = Frame {
                delay,
                dispose: DisposalMethod::Keep,
                left: to_u16(x)?,
                top: to_u16(y)?,
                width: to_u16(fw)?,
                height: to_u16(fh)?,
                buffer: Cow::Owned(buffer),
                ..Frame::default()
            };
            enc.write_frame(&frame).map_err(encode_error)?;
            previous = Some(pm);
        }
    }
    Ok(out)
}

/// Encodes the animation, doubling the stride until the file is at most `max_bytes` (or only
/// two frames are left).
pub(crate) fn animate(prepared: &Prepared, max_frames: usize, max_bytes: usize) -> Result<Vec<u8>, Error> {
    let scenario = prepared.scenario;
    let dt = scenario.header.time_step_size;
    let (first, last) = (first_step(scenario), last_step(scenario));
    let span = last - first;
    let mut base = canvas(prepared.width, prepared.height, style::BACKGROUND)?;
    if prepared.is_fixed() {
        paint_prims(&mut base, &prepared.base(first));
    }
    let frames = Frames { prepared, base };
    let samples: Vec<Pixmap> = [first, first + span / 2, last].iter().map(|&s| frames.at(s)).collect();
    let sample_data: Vec<&[u8]> = samples.iter().map(|p| p.data()).collect();
    let mut palette = Palette::from_samples(&sample_data);

    let min_stride = (MIN_DELAY_S / dt).ceil().max(1.0) as u64;
    let max_frames = max_frames.max(2) as u64;
    let mut stride = (span / (max_frames - 1) + u64::from(span % (max_frames - 1) != 0)).max(min_stride);
    loop {
        let mut steps: Vec<u64> = (first..=last).step_by(stride.try_into().unwrap_or(usize::MAX)).collect();
        if steps.last() != Some(&last) {
            steps.push(last);
        }
        let bytes = encode(&frames, &steps, stride, dt, &mut palette)?;
        if bytes.len() <= max_bytes || steps.len() <= 2 {
            return Ok(bytes);
        }
        stride = stride.saturating_mul(2);
    }
}
