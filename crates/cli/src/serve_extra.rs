//! `serve`'s options for what a driver model sees and what the run is written as: the OSI
//! GroundTruth per frame sent to an OSI receiver (`--osi-receiver`, esmini's framing and port)
//! and written as a trace file (`--osi-file`), the CommonRoad format (`--format 2024`), and
//! Ctrl-C, which ends the run after the current step and writes what has run.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use convert::{MapFiles, OutputFormat, OutputPaths};
use udp::{Listening, Observer, Outcome, Rejection};

use crate::failure::Failure;

#[derive(clap::Args)]
pub(crate) struct ServeOsiArgs {
    /// Send each frame's ASAM OSI GroundTruth over UDP to HOST[:PORT] (default port 48198), split
    /// as esmini's --osi_receiver_ip splits it, so esmini's OSI clients read it unchanged.
    #[arg(long, value_name = "HOST[:PORT]")]
    pub osi_receiver: Option<String>,
    /// Write the run as an OSI trace file (each GroundTruth message preceded by its 4-byte
    /// little-endian length, as esmini's --osi_file writes it).
    #[arg(long, value_name = "FILE")]
    pub osi_file: Option<PathBuf>,
    /// CommonRoad format of the run: 2020a (one XML file) or 2024 (map, scenario and dynamic
    /// protobuf files).
    #[arg(long, default_value = "2020a", value_name = "2020a|2024")]
    pub format: OutputFormat,
}

/// Set by Ctrl-C: the served run ends after the current step.
pub(crate) fn interrupt_flag() -> Result<Arc<AtomicBool>, Failure> {
    let flag = Arc::new(AtomicBool::new(false));
    let f = flag.clone();
    ctrlc::set_handler(move || f.store(true, Ordering::SeqCst)).map_err(|e| Failure { message: format!("cannot handle Ctrl-C: {e}"), status: 1 })?;
    Ok(flag)
}

/// An observer that also writes the OSI messages to a trace file.
pub(crate) struct WithTrace<'a> {
    pub inner: &'a mut dyn Observer,
    pub trace: Option<osi::TraceWriter>,
    pub error: Option<String>,
}

impl Observer for WithTrace<'_> {
    fn listening(&mut self, l: &Listening) {
        self.inner.listening(l);
    }
    fn rejected(&mut self, r: &Rejection) {
        self.inner.rejected(r);
    }
    fn stepped(&mut self, time: f64) {
        self.inner.stepped(time);
    }
    fn osi_frame(&mut self, message: &[u8]) {
        if let (Some(t), None) = (&mut self.trace, &self.error) {
            if let Err(e) = t.write(message) {
                self.error = Some(e);
            }
        }
    }
}

/// Puts the OSI trace file in place.
pub(crate) fn finish_trace(w: WithTrace<'_>) -> Result<Option<PathBuf>, Failure> {
    let io = |message: String| Failure { message, status: 1 };
    if let Some(e) = w.error {
        return Err(io(e));
    }
    w.trace.map(osi::TraceWriter::finish).transpose().map_err(io)
}

/// Writes the run's CommonRoad files into `dir` in `format`; the main file's path.
pub(crate) fn write_commonroad(outcome: &Outcome, dir: &Path, format: OutputFormat) -> Result<PathBuf, Failure> {
    let io = |message: String| Failure { message, status: 1 };
    let Ok(output) = &outcome.conversion.result else {
        let why = outcome.failure.as_ref().map_or_else(String::new, |f| format!("{:?} stage: {}", f.stage, f.message));
        return Err(io(format!("{}: the run was not converted: {why}", outcome.scenario.display())));
    };
    std::fs::create_dir_all(dir).map_err(|e| io(format!("cannot create output folder {}: {e}", dir.display())))?;
    let stem = dir.join(outcome.output_name.with_extension(""));
    let written = convert::write_output(&OutputPaths::of(&stem, format, false), output, &MapFiles::new(dir)).map_err(io)?;
    written.main.ok_or_else(|| io("nothing written".into()))
}
