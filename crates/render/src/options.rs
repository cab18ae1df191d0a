//! What a picture shows and how big it is.

use std::collections::BTreeMap;

use crate::error::Error;

/// Which part of the world a picture shows.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Frame {
    /// The region the road users (dynamic obstacles) occupy, with a margin: at the still's
    /// time (and its trails), or over the whole run for an animation. A scenario without road
    /// users shows the whole map.
    #[default]
    Action,
    /// Every lanelet, obstacle and goal region.
    WholeMap,
    /// A world rectangle (min x, min y, max x, max y), metres.
    Region([f64; 4]),
    /// A window of [`FOLLOW_SPAN_M`] metres centred on this dynamic obstacle at every time.
    Follow(u64),
}

/// Width of the window a followed obstacle is centred in, m.
pub const FOLLOW_SPAN_M: f64 = 100.0;

/// A storyboard event to mark: when it happened (s) and what to call it.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub time: f64,
    pub text: String,
}

/// Options of one picture (or animation).
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Picture width in pixels (default 1200); the height follows from the content's aspect.
    pub width: u32,
    /// Time shown by a still, in seconds (default 0); rounded to the nearest time step.
    pub time: f64,
    /// Id of the dynamic obstacle drawn as the ego. `None`: the obstacle that starts where the
    /// first planning problem starts (if any).
    pub ego: Option<u64>,
    /// Animations: largest file size to aim for, bytes (default 10 MB); the frame stride grows
    /// until the file fits.
    pub gif_max_bytes: usize,
    /// Animations: most frames (default 300); every k-th time step is drawn.
    pub gif_max_frames: usize,
    /// Which part of the world is shown (default: where the road users are).
    pub frame: Frame,
    /// Names of obstacles by id, shown in their labels as `name (id)`.
    pub names: BTreeMap<u64, String>,
    /// Storyboard events, shown in the header from the time they happen.
    pub marks: Vec<Mark>,
    /// Length of the trail of past positions behind each road user, s (default 3; 0: none).
    pub trail: f64,
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            width: 1200,
            time: 0.0,
            ego: None,
            gif_max_bytes: 10_000_000,
            gif_max_frames: 300,
            frame: Frame::Action,
            names: BTreeMap::new(),
            marks: Vec::new(),
            trail: 3.0,
        }
    }
}

/// Narrowest and widest picture accepted (the GIF format stores 16-bit sizes).
pub const MIN_WIDTH: u32 = 64;
pub const MAX_WIDTH: u32 = 8192;

impl RenderOptions {
    /// Checks values no picture could use; the message names the option.
    pub fn check(&self) -> Result<(), Error> {
        if !(MIN_WIDTH..=MAX_WIDTH).contains(&self.width) {
            return Err(Error::Option(format!("--width must be between {MIN_WIDTH} and {MAX_WIDTH} pixels, got {}", self.width)));
        }
        if !(self.time.is_finite() && self.time >= 0.0) {
            return Err(Error::Option(format!("--time must be a finite number of seconds >= 0, got {}", self.time)));
        }
        if self.gif_max_frames < 2 {
            return Err(Error::Option("an animation needs at least 2 frames".to_string()));
        }
        if !(self.trail.is_finite() && self.trail >= 0.0) {
            return Err(Error::Option(format!("--trail must be a finite number of seconds >= 0, got {}", self.trail)));
        }
        if let Frame::Region([x0, y0, x1, y1]) = self.frame {
            let finite = [x0, y0, x1, y1].iter().all(|v| v.is_finite());
            if !(finite && x1 > x0 && y1 > y0) {
                return Err(Error::Option(format!("--region must be X0,Y0,X1,Y1 with X0 < X1 and Y0 < Y1 (metres), got {x0},{y0},{x1},{y1}")));
            }
        }
        Ok(())
    }
}
