//! `<objects><object>` with repeat records. Outlines are not modelled (flagged instead).

/// A value at the start and at the end of a `<repeat>` (its attributes `…Start`, `…End`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RepeatEnds {
    pub start: Option<f64>,
    pub end: Option<f64>,
}

/// `<repeat>` of an object: from `s` over `length` m, every `distance` m.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ObjectRepeat {
    pub s: f64,
    pub length: f64,
    pub distance: f64,
    pub t: RepeatEnds,
    pub width: RepeatEnds,
    pub height: RepeatEnds,
    pub z_offset: RepeatEnds,
    /// The object's length (`lengthStart`, `lengthEnd`), not the repeat's.
    pub object_length: RepeatEnds,
    pub radius: RepeatEnds,
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
