//! A closed-loop run for Python: `Session` holds a `convert::ClosedLoop` and maps its API to
//! plain Python values (`osc2cr.Simulation` in `osc2cr/_simulation.py` is its face). One
//! `step` is one CommonRoad time step (`dt`), the input held over its engine steps
//! (`ClosedLoop::step_held`); the fast path (`step_array`, `states`) takes and gives flat
//! arrays of floats as bytes. Positions are CommonRoad positions (the centre of the entity's
//! bounding box) both ways; headings in the states are wrapped to (−π, π] as in CommonRoad
//! files. Steps run with the GIL released.

use std::path::PathBuf;
use std::sync::Mutex;

use convert::{ClosedLoop, Failure, Model, Stage};
use engine::{Chosen, External, ExternalEntity, Input, ScriptedMotion};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyDict};

use crate::errors::{conversion_error, warnings_of};
use crate::inputs::{from_parts, from_row, DRIVER_WIDTH, STATE_WIDTHS};
use crate::options::from_kwargs;
use crate::options::pythonic;

/// Numbers per entity in `states()`: x, y, heading, speed, acceleration, yaw rate, z, present.
pub(crate) const STATE_COLUMNS: usize = 8;

/// (stage, message) pairs, as the conversion functions return warnings.
type Warnings = Vec<(&'static str, String)>;
/// (obstacle id, entity name) of each obstacle.
type Names = Vec<(u64, String)>;
/// (xml, warnings, obstacle names, (time, event) marks) of the run so far.
type Finished = (String, Warnings, Names, Vec<(f64, String)>);
/// (xml, warnings, obstacle names, ego entity) of the open-loop conversion.
type OpenLoop = (String, Warnings, Names, String);

/// A scenario running in closed loop (see `osc2cr.Simulation`).
#[pyclass(module = "osc2cr._osc2cr")]
pub struct Session {
    /// A `Mutex` only to make the session `Sync` for Python; `&mut self` methods reach it
    /// with `get_mut`, without locking.
    run: Mutex<ClosedLoop>,
    path: PathBuf,
    names: Vec<String>,
    /// Each entity's bounding box: centre offset from its reference point (x forward, y
    /// left), length, width.
    boxes: Vec<[f64; 4]>,
    /// The entities driven from outside or waiting for their controller.
    external: Vec<ExternalEntity>,
    /// Controllers choose the external entities: the list can grow during the run.
    controllers: bool,
    /// Engine steps per CommonRoad step.
    substeps: usize,
    dt: f64,
    step: f64,
    /// The inputs of a step, reused.
    inputs: Vec<(usize, Input)>,
    /// The numbers of `step_array`, reused.
    numbers: Vec<f64>,
    /// The OSI reporter, made at the first `osi_ground_truth`.
    osi: Option<osi::Reporter>,
}

fn motion(text: &str) -> PyResult<ScriptedMotion> {
    match text {
        "overridden" => Ok(ScriptedMotion::Overridden),
        "replaced" => Ok(ScriptedMotion::Replaced),
        other => Err(PyValueError::new_err(format!("motion must be \"overridden\" (esmini's rule) or \"replaced\", got {other:?}"))),
    }
}

/// A failed step: the engine's message (a wrong input) as `ValueError`.
fn step_error(f: Failure) -> PyErr {
    PyValueError::new_err(pythonic(&f.message))
}

impl Session {
    fn run(&mut self) -> &mut ClosedLoop {
        self.run.get_mut().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn view(&self) -> std::sync::MutexGuard<'_, ClosedLoop> {
        self.run.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn offset(&self, e: usize) -> (f64, f64) {
        self.boxes.get(e).map_or((0.0, 0.0), |b| (b[0], b[1]))
    }

    fn index_of(&self, name: &str) -> PyResult<usize> {
        self.names
            .iter()
            .position(|n| n == name)
            .ok_or_else(|| PyValueError::new_err(format!("no entity named `{name}`; the scenario has {}", self.names.join(", "))))
    }

    /// Runs one CommonRoad step with `self.inputs`, the GIL released.
    fn advance(&mut self, py: Python<'_>) -> PyResult<bool> {
        let n = self.substeps;
        let mut inputs = std::mem::take(&mut self.inputs);
        let run = self.run();
        let result = py.detach(|| run.step_held(&inputs, n));
        inputs.clear();
        self.inputs = inputs;
        if self.controllers {
            let external = self.run().external();
            self.external = external;
        }
        result.map_err(step_error)
    }

    /// The states of `states()` into `out` (exactly their size).
    fn fill_states(&self, out: &mut [u8]) {
        let run = self.view();
        for (e, chunk) in out.chunks_exact_mut(STATE_COLUMNS * 8).enumerate() {
            let row = match run.state(e) {
                Some(s) => {
                    let (cx, cy) = self.offset(e);
                    let (x, y) = convert::box_center(s.x, s.y, s.h, cx, cy);
                    [x, y, convert::wrap_angle(s.h), s.speed, s.acceleration, s.yaw_rate, s.z, 1.0]
                }
                None => [0.0; STATE_COLUMNS],
            };
            for (v, bytes) in row.iter().zip(chunk.chunks_exact_mut(8)) {
                bytes.copy_from_slice(&v.to_ne_bytes());
            }
        }
    }

    /// `self.inputs` from the rows of `step_array`.
    fn array_inputs(&mut self, numbers: &[f64], driver: bool) -> PyResult<()> {
        let rows = self.external.len();
        let width = numbers.len().checked_div(rows).unwrap_or(0);
        let fits = if driver { width == DRIVER_WIDTH } else { STATE_WIDTHS.contains(&width) };
        if !(rows == 0 && numbers.is_empty() || fits && width * rows == numbers.len()) {
            let expected =
                if driver { "3 (throttle, brake, steering)".to_string() } else { "4 (x, y, heading, speed) or 8 (and z, pitch, roll, yaw_rate)".to_string() };
            return Err(PyValueError::new_err(format!("{} numbers for {rows} external entities: expected {expected} per entity", numbers.len())));
        }
        self.inputs.clear();
        for (k, x) in self.external.iter().enumerate() {
            let row = &numbers[k * width..(k + 1) * width];
            let offset = self.boxes.get(x.index).map_or((0.0, 0.0), |b| (b[0], b[1]));
            self.inputs.push((x.index, from_row(row, driver, offset)));
        }
        Ok(())
    }

    /// The conversion of the run so far, or `ConversionError`.
    fn converted(&self, py: Python<'_>) -> PyResult<(Vec<u8>, Warnings, Model)> {
        let (conversion, model) = py.detach(|| self.view().finish());
        let warnings = warnings_of(&conversion.warnings);
        match (conversion.result.and_then(xml_bytes), model) {
            (Ok(bytes), Some(model)) => Ok((bytes, warnings, model)),
            (Err(f), _) => Err(conversion_error(py, &f, &self.path, None)),
            (Ok(_), None) => Err(conversion_error(py, &Failure { stage: Stage::Build, message: "the conversion kept no model".into() }, &self.path, None)),
        }
    }
}

/// The XML of a session's conversion (`Session::new` keeps the format 2020a).
fn xml_bytes(output: convert::Output) -> Result<Vec<u8>, Failure> {
    match output {
        convert::Output::Xml(bytes) => Ok(bytes),
        convert::Output::Protobuf(_) => Err(Failure { stage: Stage::Write, message: "a closed-loop session writes CommonRoad 2020a XML".into() }),
    }
}

/// Reads a flat array of f64 from bytes (native byte order, as numpy's `tobytes()`), a
/// bytearray, or any sequence of numbers.
fn floats(values: &Bound<'_, PyAny>, out: &mut Vec<f64>) -> PyResult<()> {
    out.clear();
    let from_bytes = |b: &[u8], out: &mut Vec<f64>| -> PyResult<()> {
        if !b.len().is_multiple_of(8) {
            return Err(PyValueError::new_err(format!("{} bytes are not a whole number of float64 values", b.len())));
        }
        out.extend(b.chunks_exact(8).map(|c| f64::from_ne_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]])));
        Ok(())
    };
    if let Ok(b) = values.cast::<PyBytes>() {
        return from_bytes(b.as_bytes(), out);
    }
    if let Ok(b) = values.cast::<PyByteArray>() {
        return from_bytes(&b.to_vec(), out);
    }
    *out = values.extract::<Vec<f64>>().map_err(|_| PyTypeError::new_err("the array must be float64 bytes or a flat sequence of numbers"))?;
    Ok(())
}

#[pymethods]
impl Session {
    /// Loads `path`, converts its map and runs frame 0 (and a ghost's head start, holding the
    /// external entities, so that the session starts at CommonRoad time 0). `external`: names
    /// (`None`: the entities whose controller needs an outside driver); `motion`:
    /// `"overridden"` or `"replaced"`.
    #[new]
    #[pyo3(signature = (path, external=None, motion="overridden", **options))]
    fn new(py: Python<'_>, path: PathBuf, external: Option<Vec<String>>, motion: &str, options: Option<&Bound<'_, PyDict>>) -> PyResult<Session> {
        let (opts, _) = from_kwargs(options)?;
        if opts.format != convert::OutputFormat::Xml2020a {
            return Err(PyValueError::new_err(
                "a closed-loop session gives its run as CommonRoad 2020a XML (to_xml, to_commonroad); format=\"2024\" is for osc2cr.convert",
            ));
        }
        let motion = self::motion(motion)?;
        let substeps = convert::whole_multiple(opts.step, opts.dt)
            .ok_or_else(|| PyValueError::new_err(format!("dt ({} s) must be a whole multiple of step ({} s) in a closed-loop run", opts.dt, opts.step)))?;
        let controllers = external.is_none();
        let entities = match external {
            None => Chosen::Controllers,
            Some(names) => Chosen::Named(names),
        };
        let choice = External { entities, motion };
        let started = py.detach(|| ClosedLoop::start(&path, &opts, &choice));
        let mut run = started.map_err(|f| match f.stage {
            // the external choice or the settings the engine refused: the caller's mistake
            Stage::Engine => PyValueError::new_err(pythonic(&f.message)),
            _ => conversion_error(py, &f, &path, None),
        })?;
        // a ghost's head start runs before CommonRoad time 0
        while run.time() < -1e-9 && !run.is_over() {
            let hold: Vec<(usize, Input)> = run.external().iter().filter(|x| x.active).map(|x| (x.index, Input::Hold)).collect();
            run.step_held(&hold, 1).map_err(step_error)?;
        }
        let boxes = engine::bounding_boxes(run.scenario()).iter().map(|b| [b[0], b[1], b[3], b[4]]).collect();
        Ok(Session {
            names: run.entity_names(),
            external: run.external(),
            run: Mutex::new(run),
            path,
            boxes,
            controllers,
            substeps,
            dt: opts.dt,
            step: opts.step,
            inputs: Vec::new(),
            numbers: Vec::new(),
            osi: None,
        })
    }

    /// Entity names, in the order of `states()`'s rows.
    #[getter]
    fn entity_names(&self) -> Vec<String> {
        self.names.clone()
    }

    /// (centre x, centre y, length, width) of each entity's bounding box; the centre relative
    /// to its reference point, x forward, y left.
    #[getter]
    fn boxes(&self) -> Vec<(f64, f64, f64, f64)> {
        self.boxes.iter().map(|b| (b[0], b[1], b[2], b[3])).collect()
    }

    /// (name, index, driven now) of each entity driven from outside or waiting for its
    /// controller, in the order of `step_array`'s rows.
    #[getter]
    fn external(&self) -> Vec<(String, usize, bool)> {
        self.external.iter().map(|x| (x.name.clone(), x.index, x.active)).collect()
    }

    /// Simulated time, s.
    #[getter]
    fn time(&self) -> f64 {
        self.view().time()
    }

    /// The storyboard stopped or the time cap was reached.
    #[getter]
    fn is_over(&self) -> bool {
        self.view().is_over()
    }

    /// Engine steps per CommonRoad step.
    #[getter]
    fn substeps(&self) -> usize {
        self.substeps
    }

    /// CommonRoad time step, s.
    #[getter]
    fn dt(&self) -> f64 {
        self.dt
    }

    /// Engine step, s.
    #[getter]
    fn step_size(&self) -> f64 {
        self.step
    }

    /// One CommonRoad step with inputs `[(name, kind, numbers)]` (`inputs.rs`); `False` once
    /// the run is over. A wrong input raises `ValueError` with the engine's message, and no
    /// step is run.
    fn step(&mut self, py: Python<'_>, inputs: Vec<(String, String, Vec<Option<f64>>)>) -> PyResult<bool> {
        let mut parsed = Vec::with_capacity(inputs.len());
        for (name, kind, numbers) in &inputs {
            let e = self.index_of(name)?;
            parsed.push((e, from_parts(name, kind, numbers, self.offset(e))?));
        }
        self.inputs = parsed;
        self.advance(py)
    }

    /// The fast path: one CommonRoad step with one row per entity of `external` (in its
    /// order) in a flat float64 array (`bytes` or a sequence): `kind` `"state"` rows of 4
    /// (x, y, heading, speed) or 8 (…, z, pitch, roll, yaw rate; NaN where not given),
    /// `"driver"` rows of 3 (throttle, brake, steering); a row starting with NaN holds.
    #[pyo3(signature = (values, kind="state"))]
    fn step_array(&mut self, py: Python<'_>, values: &Bound<'_, PyAny>, kind: &str) -> PyResult<bool> {
        let driver = match kind {
            "state" => false,
            "driver" => true,
            other => return Err(PyValueError::new_err(format!("kind must be \"state\" or \"driver\", got {other:?}"))),
        };
        let mut numbers = std::mem::take(&mut self.numbers);
        let read = floats(values, &mut numbers);
        let result = read.and_then(|()| self.array_inputs(&numbers, driver));
        self.numbers = numbers;
        result?;
        self.advance(py)
    }

    /// The ASAM OSI 3.5 GroundTruth of the run's current frame, serialized, as esmini 3.6.0
    /// would report it (osc2cr's `osi` crate), whole: the static part (version, host vehicle,
    /// lanes, lane boundaries) in every message. Velocities and accelerations are the changes
    /// since the previous call (the first call: the speed along the heading).
    fn osi_ground_truth<'py>(&mut self, py: Python<'py>) -> Bound<'py, PyBytes> {
        use prost::Message;
        let run = self.run.get_mut().unwrap_or_else(std::sync::PoisonError::into_inner);
        let reporter = self.osi.get_or_insert_with(|| osi::Reporter::new(run.scenario(), run.road(), &self.names));
        let states: Vec<_> = (0..self.names.len()).map(|i| run.state(i)).collect();
        let mut gt = reporter.frame(run.road(), run.time(), &states);
        if gt.version.is_none() {
            let s = reporter.static_part();
            gt.version = s.version;
            gt.host_vehicle_id = s.host_vehicle_id;
            gt.lane = s.lane.clone();
            gt.lane_boundary = s.lane_boundary.clone();
        }
        PyBytes::new(py, &gt.encode_to_vec())
    }

    /// Every entity's state now as float64 bytes, `STATE_COLUMNS` per entity in the order of
    /// `entity_names`: x, y (box centre), heading (wrapped), speed, acceleration, yaw rate, z,
    /// present (1.0, or 0.0 with the other numbers 0 while the entity does not exist).
    fn states<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        let mut out = vec![0u8; self.names.len() * STATE_COLUMNS * 8];
        self.fill_states(&mut out);
        PyBytes::new(py, &out)
    }

    /// `states()` written into `buffer` (a bytearray of exactly that size, e.g. under a numpy
    /// view that is then up to date without a copy).
    fn states_into(&self, buffer: &Bound<'_, PyByteArray>) -> PyResult<()> {
        let size = self.names.len() * STATE_COLUMNS * 8;
        if buffer.len() != size {
            return Err(PyValueError::new_err(format!("the buffer has {} bytes; the states take {size}", buffer.len())));
        }
        // SAFETY: the GIL is held and no other slice of the bytearray is alive while it is
        // written; its size was checked and nothing in between can resize it.
        let out = unsafe { buffer.as_bytes_mut() };
        self.fill_states(out);
        Ok(())
    }

    /// Storyboard state transitions from the `start`-th on: (time, element, from, transition, to).
    #[pyo3(signature = (start=0))]
    fn events(&self, start: usize) -> Vec<(f64, String, String, String, String)> {
        let events = self.view().events();
        events.into_iter().skip(start).map(|e| (e.time, e.element, e.from, e.transition, e.to)).collect()
    }

    /// What loading the scenario and converting its map said.
    fn load_warnings(&self) -> Warnings {
        warnings_of(self.view().warnings())
    }

    /// The run so far converted: (xml, warnings, [(obstacle id, entity)], [(time, event)]),
    /// the bytes `osc2cr convert` would write had the run gone this way.
    fn finish(&self, py: Python<'_>) -> PyResult<Finished> {
        let (bytes, warnings, model) = self.converted(py)?;
        Ok((String::from_utf8_lossy(&bytes).into_owned(), warnings, model.names, model.events))
    }

    /// The batch conversion of the scenario (nobody driving from outside), with the ego this
    /// session's conversion has: (xml, warnings, [(obstacle id, entity)], ego entity).
    fn open_loop(&self, py: Python<'_>) -> PyResult<OpenLoop> {
        let (conversion, model) = py.detach(|| self.view().open_loop());
        let warnings = warnings_of(&conversion.warnings);
        let bytes = conversion.result.and_then(xml_bytes).map_err(|f| conversion_error(py, &f, &self.path, None))?;
        let names = model.map(|m| m.names).unwrap_or_default();
        Ok((String::from_utf8_lossy(&bytes).into_owned(), warnings, names, conversion.facts.ego.unwrap_or_default()))
    }

    /// A picture of the run so far (`osc2cr render`'s renderer): `format` "gif" (the whole
    /// run), "png" or "svg" (a still at `time`, default now); entity names and storyboard
    /// events drawn as for an OpenSCENARIO file; `follow` an entity name to follow.
    #[pyo3(signature = (format, time=None, width=1200, follow=None))]
    fn picture<'py>(&self, py: Python<'py>, format: &str, time: Option<f64>, width: u32, follow: Option<String>) -> PyResult<Bound<'py, PyBytes>> {
        let (_, _, model) = self.converted(py)?;
        let options = picture_options(&model, time.unwrap_or_else(|| self.view().time().max(0.0)), width, follow.as_deref())?;
        let problems = Some(&model.problems).filter(|p| !p.problems.is_empty());
        let bytes = py
            .detach(|| match format {
                "gif" => render::render_gif(&model.scenario, problems, &options),
                "png" => render::render_png(&model.scenario, problems, &options),
                "svg" => render::render_svg(&model.scenario, problems, &options).map(String::into_bytes),
                other => Err(render::Error::Option(format!("format must be gif, png or svg, got {other:?}"))),
            })
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(PyBytes::new(py, &bytes))
    }

    /// A still of the run so far at `time` (default now) as RGBA pixels: (width, height, bytes).
    #[pyo3(signature = (time=None, width=640, follow=None))]
    fn rgba<'py>(&self, py: Python<'py>, time: Option<f64>, width: u32, follow: Option<String>) -> PyResult<(u32, u32, Bound<'py, PyBytes>)> {
        let (_, _, model) = self.converted(py)?;
        let options = picture_options(&model, time.unwrap_or_else(|| self.view().time().max(0.0)), width, follow.as_deref())?;
        let problems = Some(&model.problems).filter(|p| !p.problems.is_empty());
        let (w, h, pixels) = py.detach(|| render::render_rgba(&model.scenario, problems, &options)).map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok((w, h, PyBytes::new(py, &pixels)))
    }
}

fn picture_options(model: &Model, time: f64, width: u32, follow: Option<&str>) -> PyResult<render::RenderOptions> {
    let frame = match follow {
        None => render::Frame::Action,
        Some(name) => {
            let id = model.names.iter().find(|(_, n)| n == name).map(|(id, _)| *id);
            render::Frame::Follow(id.ok_or_else(|| PyValueError::new_err(format!("follow: no road user named `{name}`")))?)
        }
    };
    Ok(render::RenderOptions {
        width,
        time,
        frame,
        names: model.names.iter().cloned().collect(),
        marks: model.events.iter().map(|(time, text)| render::Mark { time: *time, text: text.clone() }).collect(),
        ..Default::default()
    })
}
