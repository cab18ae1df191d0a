//! `<objects><object>` with repeat records. Outlines are not modelled (flagged instead).

/// `<repeat>` of an object.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ObjectRepeat {
    pub s: f64,
    pub length: f64,
    pub distance: f64,
    pub t_start: Option<f64>,
    pub t_end: Option<f64>,
    pub width_start: Option<f64>,
    pub width_end: Option<f64>,
    pub height_start: Option<f64>,
    pub height_end: Option<f64>,
    pub z_offset_start: Option<f64>,
    pub z_offset_end: Option<f64>,
    pub length_start: Option<f64>,
    pub length_end: Option<f64>,
    pub radius_start: Option<f64>,
    pub radius_end: Option<f64>,
}

/// A road object.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Object {
    pub id: String,
    pub name: Option<String>,
    pub type_raw: Option<String>,
    pub subtype: Option<String>,
    pub dynamic: Option<bool>,
    pub s: f64,
    pub t: f64,
    pub z_offset: f64,
    pub hdg: Option<f64>,
    pub pitch: Option<f64>,
    pub roll: Option<f64>,
    pub length: Option<f64>,
    pub width: Option<f64>,
    pub radius: Option<f64>,
    pub height: Option<f64>,
    pub valid_length: Option<f64>,
    /// `+`, `-` or `none`, as written.
    pub orientation: Option<String>,
    pub repeats: Vec<ObjectRepeat>,
    /// The object had `<outline>`/`<outlines>` (not modelled; a warning was issued).
    pub has_outline: bool,
}
