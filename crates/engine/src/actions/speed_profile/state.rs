//! What a running SpeedProfileAction remembers: its planned segments of speed over time.

#[derive(Debug, Clone, Copy)]
pub(super) struct Segment {
    pub(super) t: f64,
    pub(super) v: f64,
    pub(super) k: f64,
    pub(super) j: f64,
}

#[derive(Debug, Clone)]
pub(crate) struct SpeedProfileRt {
    pub(super) segments: Vec<Segment>,
    pub(super) current: usize,
    pub(super) speed: f64,
    pub(super) entries: usize,
}
