//! `<signals>`: signals and signal references.

/// Which driving direction a signal is valid for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum SignalOrientation {
    /// `+`: valid in +s direction.
    Plus,
    /// `-`: valid in −s direction.
    Minus,
    /// `none`: both directions.
    Both,
}

impl SignalOrientation {
    /// Parse `+`, `-`, `none` (anything else → Both).
    pub fn parse(raw: &str) -> SignalOrientation {
        match raw.trim() {
            "+" => SignalOrientation::Plus,
            "-" => SignalOrientation::Minus,
            _ => SignalOrientation::Both,
        }
    }
}

/// `<validity fromLane toLane>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LaneValidity {
    pub from_lane: i32,
    pub to_lane: i32,
}

/// A signal (sign, traffic light, ...).
#[derive(Debug, Clone, PartialEq)]
pub struct Signal {
    pub id: String,
    pub name: Option<String>,
    pub s: f64,
    pub t: f64,
    pub z_offset: f64,
    pub h_offset: f64,
    pub pitch: f64,
    pub roll: f64,
    pub country: Option<String>,
    pub country_revision: Option<String>,
    pub type_raw: String,
    pub subtype: Option<String>,
    pub value: Option<f64>,
    pub unit: Option<String>,
    pub text: Option<String>,
    pub dynamic: bool,
    pub orientation: SignalOrientation,
    pub height: Option<f64>,
    pub width: Option<f64>,
    pub validity: Vec<LaneValidity>,
}

/// `<signalReference>`: a signal of another road placed on this one.
#[derive(Debug, Clone, PartialEq)]
pub struct SignalReference {
    pub id: String,
    pub s: f64,
    pub t: f64,
    pub orientation: SignalOrientation,
    pub validity: Vec<LaneValidity>,
}
