//! The engine's speed on a scenario, measured in Rust, for the closed-loop benchmark
//! (`crates/python/benches/closed_loop.py`) to compare stepping from Python with: the
//! scenario is loaded once per run and run to the end, nobody driving from outside (the loop
//! `engine::simulate_with` runs: the batch engine), or with the ego driven from outside in
//! Rust with its own open-loop states (what a Python caller replaying them makes the engine
//! do, without Python). The GIL is released.

use std::path::PathBuf;
use std::time::Instant;

use convert::{ClosedLoop, ConvertOptions, Failure};
use engine::{External, ExternalState, Input, ScriptedMotion};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::conversion_error;
use crate::options::from_kwargs;

/// The ego's inputs that replay its open-loop run, one per engine step.
fn recorded_ego(path: &std::path::Path, opts: &ConvertOptions) -> Result<(String, usize, Vec<Input>), Failure> {
    let mut open = ClosedLoop::start(path, opts, &External::none())?;
    let ego = open.open_loop().0.facts.ego.unwrap_or_default();
    let index = open.entity_names().iter().position(|n| *n == ego).unwrap_or(0);
    let mut inputs = Vec::new();
    while open.step_with(&[])? {
        inputs.push(open.state(index).map_or(Input::Hold, |s| Input::State(ExternalState::new(s.x, s.y, s.h, s.speed))));
    }
    inputs.push(open.state(index).map_or(Input::Hold, |s| Input::State(ExternalState::new(s.x, s.y, s.h, s.speed))));
    Ok((ego, index, inputs))
}

/// Runs `path` to the end `runs` times, one engine step at a time; with `replay`, the ego
/// (the conversion's) driven from outside with its open-loop states, the outside replacing
/// the script. Returns (engine steps of a run, seconds of each run); loading, the map and
/// frame 0 are not timed.
#[pyfunction]
#[pyo3(signature = (path, runs=5, replay=false, **options))]
pub(crate) fn engine_timing(py: Python<'_>, path: PathBuf, runs: usize, replay: bool, options: Option<&Bound<'_, PyDict>>) -> PyResult<(usize, Vec<f64>)> {
    if runs == 0 {
        return Err(PyValueError::new_err("runs must be at least 1"));
    }
    let (opts, _) = from_kwargs(options)?;
    let timed = py.detach(|| -> Result<(usize, Vec<f64>), Failure> {
        let (external, index, inputs) = if replay {
            let (ego, index, inputs) = recorded_ego(&path, &opts)?;
            (External { motion: ScriptedMotion::Replaced, ..External::named([ego]) }, index, inputs)
        } else {
            (External::none(), 0, Vec::new())
        };
        let mut seconds = Vec::with_capacity(runs);
        let mut steps = 0;
        for _ in 0..runs {
            let mut run = ClosedLoop::start(&path, &opts, &external)?;
            steps = 0;
            let t = Instant::now();
            loop {
                let going = match inputs.get(steps) {
                    Some(input) if replay => run.step_with(&[(index, *input)])?,
                    _ => run.step_with(&[])?,
                };
                steps += 1;
                if !going {
                    break;
                }
            }
            seconds.push(t.elapsed().as_secs_f64());
        }
        Ok((steps, seconds))
    });
    timed.map_err(|f| conversion_error(py, &f, &path, None))
}
