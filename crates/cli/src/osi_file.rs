//! `--osi-file FILE`: the run as an OSI trace file (GroundTruth per frame, each message preceded
//! by its 4-byte little-endian length, as esmini's `--osi_file` writes it), written whole or not
//! at all. Shared by `simulate`, `convert` and `serve`.

use std::path::Path;

use crate::failure::Failure;

/// Writes the run of `trace` (of `scenario` on `roads`) as the trace file `path`; the reporter's
/// warnings are returned.
pub(crate) fn write_trace(
    path: &Path,
    scenario: &openscenario::Scenario,
    roads: Option<&opendrive::RoadNetwork>,
    trace: &engine::Trace,
) -> Result<Vec<String>, Failure> {
    let (frames, warnings) = osi::trace_frames(scenario, roads, trace);
    osi::trace_file::write(path, &frames).map_err(|m| Failure { message: m, status: 1 })?;
    Ok(warnings)
}

/// `convert --osi-file FILE`: the OSI trace of each conversion of a batch. One scenario file
/// (no variations) writes FILE; otherwise each conversion writes `<FILE stem>_<its output
/// name>.osi` beside FILE, one file per scenario or variation.
pub(crate) struct ConvertTraces<'a> {
    pub file: &'a Path,
    /// The batch is one scenario file.
    pub single: bool,
}

impl ConvertTraces<'_> {
    /// Where the trace of conversion `r` goes.
    pub(crate) fn path_of(&self, r: &convert::ScenarioReport) -> Option<std::path::PathBuf> {
        if self.single && r.variation.is_none() {
            return Some(self.file.to_path_buf());
        }
        let name = r.output.as_ref()?.file_name()?.to_string_lossy().into_owned();
        let name = name.trim_end_matches("-SC.pb").trim_end_matches(".xml");
        let stem = self.file.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        Some(self.file.with_file_name(format!("{stem}_{name}.osi")))
    }

    /// Writes the trace of successful conversion `r` (the engine run again as `convert` ran it).
    pub(crate) fn write(&self, r: &convert::ScenarioReport, options: &convert::ConvertOptions) -> Result<Option<std::path::PathBuf>, String> {
        let Some(path) = self.path_of(r) else { return Ok(None) };
        let scenario_file = r.variation.as_ref().map_or(r.input.as_path(), |v| v.scenario_file.as_path());
        let parameters = r.variation.as_ref().map_or(&[][..], |v| v.parameters.as_slice());
        let name = convert::batch_name(scenario_file);
        let request = convert::Request { path: scenario_file, name, config: 1, parameters, source: String::new(), keep_model: false, caches: None };
        let (prepared, trace) = convert::trace_of(&request, options).map_err(|f| f.message)?;
        let (frames, _) = osi::trace_frames(&prepared.scenario, prepared.road(), &trace);
        osi::trace_file::write(&path, &frames).map(Some)
    }
}
