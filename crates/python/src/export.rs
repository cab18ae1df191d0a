//! `osc2cr.export` from Python: one CommonRoad scenario file (2018b/2020a XML, or a 2024
//! `NAME-SC.pb`) exported into a folder as `osc2cr export FILE -o DIR` does; the Python side
//! writes a commonroad-io `Scenario` to 2020a XML first.

use std::path::PathBuf;

use pyo3::prelude::*;

use crate::errors;

/// (the `.xosc` written, the map written or already there (None: no map), warnings).
type Written = (PathBuf, Option<PathBuf>, Vec<String>);

/// Exports `path` into `out_dir` (`osc`: "1.3" or "1.0"; `ego_controller`: "default" or
/// "external"; `play_to_end`: the goal does not end the run). Raises `ConversionError` with
/// the reason when nothing could be written, `ValueError` for a bad option.
#[pyfunction]
#[pyo3(signature = (path, out_dir, osc = "1.3", ego_controller = "default", play_to_end = false))]
pub(crate) fn export_file(py: Python<'_>, path: PathBuf, out_dir: PathBuf, osc: &str, ego_controller: &str, play_to_end: bool) -> PyResult<Written> {
    let options = export::ExportOptions {
        osc: osc.parse().map_err(pyo3::exceptions::PyValueError::new_err)?,
        ego_controller: ego_controller.parse().map_err(pyo3::exceptions::PyValueError::new_err)?,
        play_to_end,
    };
    let report = py.detach(|| export::export_file(&path, &out_dir, &options));
    match (report.output, report.failure) {
        (Some(xosc), None) => Ok((xosc, report.map.map(|m| out_dir.join(m)), report.warnings)),
        (_, failure) => {
            let message = failure.map_or_else(|| "not exported".to_string(), |f| f.message);
            Err(errors::message_error(py, message, &path))
        }
    }
}
