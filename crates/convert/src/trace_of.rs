//! The engine's run of one conversion without the conversion: the scenario loaded (strictly,
//! with the variation's parameters) and run exactly as `convert` runs it, for outputs that are
//! made from the trace itself (the OSI trace file of `convert --osi-file`).

use engine::Trace;

use crate::cache::Caches;
use crate::options::ConvertOptions;
use crate::pipeline::{prepare, Prepared, Request};
use crate::report::{Failure, Stage, Timings};
use crate::stages::run_engine;

/// The loaded scenario and map of `request` and the engine's trace of it.
pub fn trace_of(request: &Request<'_>, options: &ConvertOptions) -> Result<(Prepared, Trace), Failure> {
    let prepared = prepare(request, options, &Caches::with_capacity(1), &mut Vec::new(), &mut Timings::default())?;
    let run = run_engine(&prepared.scenario, prepared.road(), options).map_err(|e| Failure { stage: Stage::Engine, message: e.to_string() })?;
    Ok((prepared, run.trace))
}
