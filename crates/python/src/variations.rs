//! The variations of a parameter distribution file as a lazy Python iterator: variation `k`
//! is computed (parameter set, then conversion) only when asked for, so a caller can stream
//! 100,000 of them in constant memory. A failing variation raises `ConversionError` (with its
//! `variation` number); the iterator has moved past it, so `next()` goes on with the next one.

use std::path::PathBuf;

use convert::{Caches, ConvertOptions};
use openscenario::Distribution;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::conversion_error;
use crate::options::from_kwargs;

/// Lazy iterator over (index, parameters, (xml, files), warnings) of the variations `start <=
/// index < stop` of a distribution file (indices from 1, as in the output names
/// `<stem>_<index>.xml`); the road network is read and converted once for the whole stream.
#[pyclass(module = "osc2cr._osc2cr")]
pub struct Variations {
    path: PathBuf,
    dist: Distribution,
    options: ConvertOptions,
    /// The road network of the variations, read and converted once for the whole stream.
    caches: Caches,
    next: u64,
    /// Exclusive.
    stop: u64,
}

/// Opens the distribution file `path` (its parameter sets are not computed yet).
/// `stop` (exclusive) defaults to the end, capped by the `max_variations` option.
#[pyfunction]
#[pyo3(signature = (path, start=1, stop=None, **options))]
pub(crate) fn variations(py: Python<'_>, path: PathBuf, start: u64, stop: Option<u64>, options: Option<&Bound<'_, PyDict>>) -> PyResult<Variations> {
    if start == 0 {
        return Err(PyValueError::new_err("start counts from 1"));
    }
    let (opts, max) = from_kwargs(options)?;
    let dist = convert::load_distribution(&path, &opts).map_err(|f| conversion_error(py, &f, &path, None))?;
    let mut end = dist.len().saturating_add(1);
    if let Some(m) = max {
        end = end.min(m.saturating_add(1));
    }
    if let Some(s) = stop {
        end = end.min(s);
    }
    Ok(Variations { path, dist, options: opts, caches: Caches::with_capacity(2), next: start, stop: end.max(start) })
}

type Item<'py> = (u64, Vec<(String, String)>, crate::payload::Payload<'py>, Vec<(&'static str, String)>);

#[pymethods]
impl Variations {
    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__<'py>(mut slf: PyRefMut<'py, Self>, py: Python<'py>) -> PyResult<Option<Item<'py>>> {
        if slf.next >= slf.stop {
            return Ok(None);
        }
        let k = slf.next;
        slf.next += 1;
        let this = &*slf;
        let parameters = this.dist.get(k - 1).unwrap_or_default();
        let c = py.detach(|| convert::convert_variation_with(&this.path, &this.dist, k, &this.options, &this.caches));
        let warnings = crate::errors::warnings_of(&c.warnings);
        match c.result {
            Ok(output) => Ok(Some((k, parameters, crate::payload::payload(py, output), warnings))),
            Err(f) => Err(conversion_error(py, &f, &this.path, Some(k))),
        }
    }

    /// Variations left to yield.
    fn __len__(&self) -> usize {
        usize::try_from(self.stop.saturating_sub(self.next)).unwrap_or(usize::MAX)
    }

    /// Number of parameter sets in the distribution (whatever `start`, `stop`, `max_variations`).
    #[getter]
    fn total(&self) -> u64 {
        self.dist.len()
    }

    /// The scenario file the distribution varies.
    #[getter]
    fn scenario_file(&self) -> PathBuf {
        self.dist.scenario_file.clone()
    }

    /// The parameter values of variation `index` (1-based), without converting it.
    fn parameters(&self, index: u64) -> PyResult<Vec<(String, String)>> {
        index.checked_sub(1).and_then(|i| self.dist.get(i)).ok_or_else(|| PyValueError::new_err(format!("no variation {index}; there are {}", self.dist.len())))
    }
}
