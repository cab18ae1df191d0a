//! The animated GIF: frame count and delays match the scenario's time; the size cap thins it.

use crate::common::*;
use render::{render_gif, render_layout, RenderOptions};

/// (frame count, delays in centiseconds, width, height).
fn frames(bytes: &[u8]) -> (usize, Vec<u16>, u16, u16) {
    let mut opts = gif::DecodeOptions::new();
    opts.set_color_output(gif::ColorOutput::Indexed);
    let mut d = opts.read_info(bytes).unwrap();
    let (w, h) = (d.width(), d.height());
    let mut delays = Vec::new();
    while let Some(f) = d.read_next_frame().unwrap() {
        delays.push(f.delay);
    }
    (delays.len(), delays, w, h)
}

#[test]
fn every_step_is_a_frame_lasting_one_step() {
    let (s, p) = straight(50); // steps 0..=50, dt 0.1 s
    let (n, delays, w, h) = frames(&render_gif(&s, Some(&p), &whole(0.0)).unwrap());
    let still = render_layout(&s, Some(&p), &whole(0.0)).unwrap();
    assert_eq!((u32::from(w), u32::from(h)), (still.width, still.height));
    assert_eq!(n, 51);
    assert!(delays.iter().all(|&d| d == 10), "{delays:?}");
}

#[test]
fn max_frames_sets_the_stride_and_time_is_kept() {
    let (s, p) = straight(50);
    let o = RenderOptions { gif_max_frames: 11, ..Default::default() };
    let (n, delays, _, _) = frames(&render_gif(&s, Some(&p), &o).unwrap());
    // stride ceil(50 / 10) = 5 steps = 0.5 s: steps 0, 5, …, 50
    assert_eq!(n, 11);
    assert!(delays.iter().all(|&d| d == 50), "{delays:?}");
}

#[test]
fn the_size_cap_thins_frames() {
    let (s, p) = straight(50);
    let full = render_gif(&s, Some(&p), &RenderOptions::default()).unwrap();
    let capped = RenderOptions { gif_max_bytes: full.len() / 3, ..Default::default() };
    let bytes = render_gif(&s, Some(&p), &capped).unwrap();
    let (n, delays, _, _) = frames(&bytes);
    assert!(n > 1 && n < 51, "{n}");
    // the frames still span the whole scenario: 5.0 s plus the last frame's own stride
    let total: u32 = delays.iter().map(|&d| u32::from(d)).sum();
    // the stride doubles from 1 step: the first frame lasts 2^k steps of 10 cs
    let stride = u32::from(delays[0]) / 10;
    assert!(stride >= 2 && stride.is_power_of_two(), "{delays:?}");
    assert_eq!(total, 500 + 10 * stride);
}
