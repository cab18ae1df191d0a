//! What a served run hands back: the CommonRoad conversion of the run (bytes, warnings), and per
//! served entity its port, how its datagrams fared and where it went; the datagrams turned away,
//! each with its reason; notes on what was not served. Plain data: the caller presents it.

use std::path::PathBuf;

use convert::{Conversion, Failure, StageWarning};
use engine::Sample;
use serde::Serialize;

use crate::controller_properties::ExecMode;
use crate::rejection::Rejection;

/// Most rejections kept in an outcome (an observer is told of every one).
pub const MAX_KEPT_REJECTIONS: usize = 10_000;

/// One entity driven over UDP.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EntityReport {
    pub name: String,
    /// esmini's object id: the `objectId` its messages must carry.
    pub object_id: u32,
    /// Where it listened (`None`: its controller was never activated).
    pub address: Option<String>,
    pub exec: ExecMode,
    /// Datagrams read.
    pub datagrams: usize,
    /// Messages that drove a step (or were read with the Init frame).
    pub accepted: usize,
    /// Good messages a newer one of the same step replaced (asynchronous mode).
    pub superseded: usize,
    pub rejected: usize,
    /// Good messages whose driver input was outside esmini's documented ranges (a negative
    /// throttle, …) and was clamped as esmini's vehicle takes it (`validate::clamp`).
    pub clamped: usize,
    /// Steps it was driven from outside without a new message.
    pub steps_without_message: usize,
    /// Its state after each frame from the one that activated its controller on (the Init
    /// frame, or a step): (time s, state).
    #[serde(skip)]
    pub states: Vec<(f64, Sample)>,
}

/// A served run.
#[derive(Debug, Clone, Serialize)]
pub struct Outcome {
    pub scenario: PathBuf,
    /// The name `osc2cr convert` gives the scenario's CommonRoad file (`<stem>.xml`).
    pub output_name: PathBuf,
    /// Frames after the Init frame, and the simulated time reached, s.
    pub steps: usize,
    pub time: f64,
    /// "real time ×F" or "as fast as possible".
    pub pace: String,
    pub entities: Vec<EntityReport>,
    /// Datagrams turned away (the first `MAX_KEPT_REJECTIONS`), and how many more there were.
    pub rejections: Vec<Rejection>,
    pub rejections_not_kept: usize,
    /// What the server could not do as asked (an outside driver it does not serve, a property
    /// read only in part).
    pub notes: Vec<String>,
    /// The run was ended from outside (Ctrl-C) before its stop trigger or time cap: what is
    /// converted is the run so far.
    pub interrupted: bool,
    /// OSI GroundTruth messages composed (one per frame when asked for).
    pub osi_frames: usize,
    /// The conversion's warnings, and why it failed if it did.
    pub warnings: Vec<StageWarning>,
    pub failure: Option<Failure>,
    /// The run as `osc2cr convert` would have written it.
    #[serde(skip)]
    pub conversion: Conversion,
}

impl Outcome {
    /// The CommonRoad bytes, when the conversion succeeded.
    pub fn bytes(&self) -> Option<&[u8]> {
        self.conversion.result.as_ref().ok().and_then(convert::Output::xml)
    }

    /// The report of entity `name`.
    pub fn entity(&self, name: &str) -> Option<&EntityReport> {
        self.entities.iter().find(|e| e.name == name)
    }
}
