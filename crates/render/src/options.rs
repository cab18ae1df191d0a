//! What a picture shows and how big it is.

use crate::error::RenderError;

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
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            width: 1200,
            time: 0.0,
            ego: None,
            gif_max_bytes: 10_000_000,
            gif_max_frames: 300,
        }
    }
}

/// Narrowest and widest picture accepted (the GIF format stores 16-bit sizes).
pub const MIN_WIDTH: u32 = 64;
pub const MAX_WIDTH: u32 = 8192;

impl RenderOptions {
    /// Checks values no picture could use; the message names the option.
    pub fn check(&self) -> Result<(), RenderError> {
        if !(MIN_WIDTH..=MAX_WIDTH).contains(&self.width) {
            return Err(RenderError::Option(format!(
                "--width must be between {MIN_WIDTH} and {MAX_WIDTH} pixels, got {}",
                self.width
            )));
        }
        if !(self.time.is_finite() && self.time >= 0.0) {
            return Err(RenderError::Option(format!(
                "--time must be a finite number of seconds >= 0, got {}",
                self.time
            )));
        }
        if self.gif_max_frames < 2 {
            return Err(RenderError::Option(
                "an animation needs at least 2 frames".to_string(),
            ));
        }
        Ok(())
    }
}
