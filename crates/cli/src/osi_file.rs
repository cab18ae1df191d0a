//! `--osi-file FILE`: the run as an OSI trace file (GroundTruth per frame, each message preceded
//! by its 4-byte little-endian length, as esmini's `--osi_file` writes it), written whole or not
//! at all. Shared by `simulate`, `convert` and `serve`.

use std::path::Path;

use crate::Failure;

/// Writes the run of `trace` (of `scenario` on `roads`) as the trace file `path`; the reporter's
/// warnings are returned.
pub fn write_trace(
    path: &Path,
    scenario: &openscenario::Scenario,
    roads: Option<&opendrive::RoadNetwork>,
    trace: &engine::Trace,
) -> Result<Vec<String>, Failure> {
    let (frames, warnings) = osi::trace_frames(scenario, roads, trace);
    osi::trace_file::write(path, &frames).map_err(|m| Failure { message: m, status: 1 })?;
    Ok(warnings)
}
