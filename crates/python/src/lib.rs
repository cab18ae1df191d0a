//! `osc2cr-python`: the native module `osc2cr._osc2cr` of the Python package `osc2cr`
//! (PyO3, built with maturin). It exposes the Rust converter to Python as plain values — XML
//! text, parameter dicts, warnings as (stage, message) pairs — and raises
//! `osc2cr.ConversionError` with file, line and column on failure. Conversions run with the
//! GIL released, so Python threads (a Dask worker's, for one) convert in parallel.
//! `closed_loop`: a scenario stepped from Python (`osc2cr.Simulation`), its inputs
//! (`inputs`), pictures of the run with `render`; `benchmark`: the engine's speed in Rust for
//! the closed-loop benchmark to compare with; `export`: the way back (`osc2cr.export`,
//! CommonRoad to OpenSCENARIO + OpenDRIVE through the `export` crate).
//!
//! It owns only the mapping between Python values and the API of `convert` (and `render`,
//! `export`):
//! it knows nothing of commonroad-io (the Python side reads the XML, or the 2024 files, and
//! builds observations with it) and does no conversion or simulation itself. A conversion
//! returns the 2020a XML text or the 2024 format's three files as `bytes`, by the `format`
//! option (`payload`, for one file and for each variation of a sweep alike).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod benchmark;
mod closed_loop;
mod errors;
mod export;
mod inputs;
mod options;
mod payload;
mod variations;

use std::path::PathBuf;

use convert::{Conversion, FileKind};
use pyo3::prelude::*;

use crate::payload::{payload, Payload};

pub use closed_loop::Session;
pub use variations::Variations;

/// (XML text or 2024 files, [(stage, warning message)]) of a successful conversion.
type Converted<'py> = (Payload<'py>, Vec<(&'static str, String)>);

fn finish<'py>(py: Python<'py>, c: Conversion, file: &std::path::Path, variation: Option<u64>) -> PyResult<Converted<'py>> {
    let warnings = errors::warnings_of(&c.warnings);
    match c.result {
        Ok(output) => Ok((payload(py, output), warnings)),
        Err(f) => Err(errors::conversion_error(py, &f, file, variation)),
    }
}

/// Converts the scenario file `path`; returns ((xml, files), warnings) — `xml` for the 2020a
/// format, `files` (map id, map, scenario, dynamic bytes) for 2024. The bytes are those
/// `osc2cr convert path` writes.
#[pyfunction]
#[pyo3(signature = (path, **options))]
fn convert_file<'py>(py: Python<'py>, path: PathBuf, options: Option<&Bound<'py, pyo3::types::PyDict>>) -> PyResult<Converted<'py>> {
    let (opts, _) = options::from_kwargs(options)?;
    let c = py.detach(|| convert::convert(&convert::Request::file(&path), &opts).0);
    if c.result.is_err() && convert::classify(&path) == FileKind::Distribution {
        return Err(errors::message_error(
            py,
            format!("{}: a parameter value distribution: convert its variations with osc2cr.variations()", path.display()),
            &path,
        ));
    }
    finish(py, c, &path, None)
}

/// Converts variation `index` (1-based) of the distribution file `path`; returns what
/// [`convert_file`] returns.
#[pyfunction]
#[pyo3(signature = (path, index, **options))]
fn convert_variation<'py>(py: Python<'py>, path: PathBuf, index: u64, options: Option<&Bound<'py, pyo3::types::PyDict>>) -> PyResult<Converted<'py>> {
    let (opts, _) = options::from_kwargs(options)?;
    let dist = convert::load_distribution(&path, &opts).map_err(|f| errors::conversion_error(py, &f, &path, None))?;
    let c = py.detach(|| convert::convert_variation(&path, &dist, index, &opts));
    finish(py, c, &path, Some(index))
}

/// The options the functions accept.
#[pyfunction]
fn option_names() -> Vec<&'static str> {
    options::NAMES.to_vec()
}

/// Native part of the `osc2cr` package; use the functions of `osc2cr` instead.
#[pymodule]
fn _osc2cr(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(convert_file, m)?)?;
    m.add_function(wrap_pyfunction!(convert_variation, m)?)?;
    m.add_function(wrap_pyfunction!(variations::variations, m)?)?;
    m.add_function(wrap_pyfunction!(option_names, m)?)?;
    m.add_function(wrap_pyfunction!(export::export_file, m)?)?;
    m.add_class::<Variations>()?;
    m.add_class::<Session>()?;
    m.add_function(wrap_pyfunction!(benchmark::engine_timing, m)?)?;
    m.add("STATE_COLUMNS", closed_loop::STATE_COLUMNS)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
