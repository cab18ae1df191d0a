//! The batch engine's speed on a scenario, measured in Rust, for the closed-loop benchmark
//! (`benches/closed_loop.py`) to compare stepping from Python with: the scenario is loaded
//! once and run to the end `runs` times, nobody driving from outside (the loop
//! `engine::simulate_with` runs), the GIL released.

use std::path::PathBuf;
use std::time::Instant;

use convert::ClosedLoop;
use engine::External;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::conversion_error;
use crate::options::from_kwargs;

/// Runs `path` to the end `runs` times; returns (engine steps of a run, seconds of each run).
/// Loading, the map and frame 0 are not timed.
#[pyfunction]
#[pyo3(signature = (path, runs=5, **options))]
pub fn batch_engine_timing(py: Python<'_>, path: PathBuf, runs: usize, options: Option<&Bound<'_, PyDict>>) -> PyResult<(usize, Vec<f64>)> {
    let (opts, _) = from_kwargs(options)?;
    let timed = py.detach(|| -> Result<(usize, Vec<f64>), convert::Failure> {
        let mut seconds = Vec::with_capacity(runs);
        let mut steps = 0;
        for _ in 0..runs {
            let mut run = ClosedLoop::start(&path, &opts, &External::none())?;
            steps = 0;
            let t = Instant::now();
            while run.step_with(&[])? {
                steps += 1;
            }
            seconds.push(t.elapsed().as_secs_f64());
        }
        Ok((steps, seconds))
    });
    timed.map_err(|f| if runs == 0 { PyValueError::new_err("runs must be at least 1") } else { conversion_error(py, &f, &path, None) })
}
