//! A closed-loop conversion: the scenario loaded and its map converted as `convert` does, then
//! run one step at a time while the caller drives the external entities (`engine::External`),
//! and at any point the run so far turned into CommonRoad with the same stages, names and
//! checks as a conversion of the file (`finish`), the ego's trajectory being the one driven
//! (the ego is the first external entity when it moves, unless the options name another).
//! The session owns the scenario and road network its run borrows (self_cell), so a Python
//! object or a server can hold it. `step_held` holds one input over several engine steps (a
//! CommonRoad time step, `held_input.rs`); `open_loop` converts the same scenario as the batch
//! does, for what a closed-loop client compares with (its planning problem, its obstacle ids).

use std::path::{Path, PathBuf};
use std::time::Instant;

use engine::{External, ExternalEntity, Input, RunControl, Sample, Settings, Simulation, StoryboardEvent};

use crate::cache::Caches;
use crate::ego::EgoChoice;
use crate::held_input::substep;
use crate::options::ConvertOptions;
use crate::pipeline::{finish, prepare, Conversion, Model, Prepared, Request};
use crate::report::Facts;
use crate::report::{Failure, Stage, StageWarning, Timings};
use crate::stages::run_engine;

self_cell::self_cell!(
    struct Session {
        owner: Prepared,
        #[not_covariant]
        dependent: Simulation,
    }
);

/// A scenario running in closed loop.
pub struct ClosedLoop {
    session: Session,
    path: PathBuf,
    options: ConvertOptions,
    /// What loading and map conversion said, and how long they took.
    warnings: Vec<StageWarning>,
    timings: Timings,
    started: Instant,
}

fn engine_failure(e: engine::Error) -> Failure {
    Failure { stage: Stage::Engine, message: e.to_string() }
}

impl ClosedLoop {
    /// Loads the scenario file `path` (strictly, as `convert` does), converts its map and runs
    /// frame 0 with `external` driven from outside.
    pub fn start(path: &Path, options: &ConvertOptions, external: &External) -> Result<ClosedLoop, Failure> {
        let mut warnings = Vec::new();
        let mut timings = Timings::default();
        let request = Request::file(path);
        let prepared = prepare(&request, options, &Caches::with_capacity(1), &mut warnings, &mut timings)?;
        let started = Instant::now();
        let settings = Settings { step: options.step, max_time: options.max_time };
        let control = RunControl { seed: options.engine_seed, deadline: None };
        let session = Session::try_new(prepared, |p| Simulation::new(&p.scenario, p.road(), &settings, &control, external)).map_err(engine_failure)?;
        let mut options = options.clone();
        // the ego of the CommonRoad output is the entity driven, unless the caller chose one
        if let EgoChoice::Pattern(pattern) = &options.ego {
            if let Some(first) = session.with_dependent(|_, sim| sim.external()).into_iter().next() {
                options.ego = EgoChoice::Preferred { name: first.name, pattern: pattern.clone() };
            }
        }
        Ok(ClosedLoop { session, path: path.to_path_buf(), options, warnings, timings, started })
    }

    /// Runs the next step with the external entities' inputs; `Ok(false)` once the run is over.
    /// A wrong input is an `Engine` failure naming it, and the step is not run.
    pub fn step_with(&mut self, inputs: &[(usize, Input)]) -> Result<bool, Failure> {
        self.session.with_dependent_mut(|_, sim| sim.step_with(inputs)).map_err(engine_failure)
    }

    /// Runs `steps` engine steps with each input held over them (`held_input.rs`): driver
    /// input, hold and dead reckoning at every step, a state reached at the last one through
    /// interpolated poses. An entity whose controller makes it external during these steps
    /// dead-reckons (holds, without a state given) until the caller's next call. Inputs are
    /// checked at the first step: a wrong one is an `Engine` failure naming it and no step is
    /// run. `Ok(false)` once the run is over (it may end before the last of the steps).
    pub fn step_held(&mut self, inputs: &[(usize, Input)], steps: usize) -> Result<bool, Failure> {
        let n = steps.max(1);
        if n == 1 {
            return self.step_with(inputs);
        }
        let span = n as f64 * self.options.step;
        let from: Vec<Option<Sample>> = inputs.iter().map(|(e, _)| self.state(*e)).collect();
        let mut now = Vec::with_capacity(inputs.len());
        for j in 1..=n {
            now.clear();
            now.extend(inputs.iter().zip(&from).map(|((e, input), s)| (*e, substep(input, s.as_ref(), j, n, span))));
            let stepped = match self.step_with(&now) {
                Err(_) if j > 1 => {
                    // an entity became external after the first step: it dead-reckons
                    for x in self.external() {
                        if x.active && !now.iter().any(|(e, _)| *e == x.index) {
                            now.push((x.index, Input::DeadReckon));
                        }
                    }
                    self.step_with(&now)?
                }
                other => other?,
            };
            if !stepped {
                return Ok(false);
            }
        }
        Ok(!self.is_over())
    }

    /// The batch conversion of the same scenario with the same options (the ego the entity
    /// this session's conversion makes the ego), run on the scenario and map already loaded:
    /// what the run would have been with nobody driving from outside.
    pub fn open_loop(&self) -> (Conversion, Option<Model>) {
        let prepared = self.session.borrow_owner();
        let started = Instant::now();
        match run_engine(&prepared.scenario, prepared.road(), &self.options) {
            Ok(run) => self.convert_run(&run.trace, run.warnings, started),
            Err(e) => {
                let conversion = Conversion { result: Err(engine_failure(e)), warnings: self.warnings.clone(), timings: self.timings, facts: Facts::default() };
                (conversion, None)
            }
        }
    }

    /// What loading the scenario and converting its map said.
    pub fn warnings(&self) -> &[StageWarning] {
        &self.warnings
    }

    /// Simulated time of the newest state, s.
    pub fn time(&self) -> f64 {
        self.session.with_dependent(|_, sim| sim.time())
    }

    /// The storyboard stopped or the time cap was reached.
    pub fn is_over(&self) -> bool {
        self.session.with_dependent(|_, sim| sim.is_over())
    }

    /// The entities driven from outside, or waiting for their controller.
    pub fn external(&self) -> Vec<ExternalEntity> {
        self.session.with_dependent(|_, sim| sim.external())
    }

    /// The entities' names, in the order of their indices.
    pub fn entity_names(&self) -> Vec<String> {
        self.session.with_dependent(|_, sim| sim.trace().entities.iter().map(|e| e.name.clone()).collect())
    }

    /// Entity `index`'s state now (`None` while it does not exist).
    pub fn state(&self, index: usize) -> Option<Sample> {
        self.session.with_dependent(|_, sim| sim.state(index))
    }

    /// Storyboard state transitions so far.
    pub fn events(&self) -> Vec<StoryboardEvent> {
        self.session.with_dependent(|_, sim| sim.events().to_vec())
    }

    /// The scenario as loaded.
    pub fn scenario(&self) -> &openscenario::Scenario {
        &self.session.borrow_owner().scenario
    }

    /// The scenario's road network (`None` without one).
    pub fn road(&self) -> Option<&opendrive::RoadNetwork> {
        self.session.borrow_owner().road()
    }

    /// The lanelet network of the scenario's map (`None` without a road network).
    pub fn lanelets(&self) -> Option<&commonroad::LaneletNetwork> {
        self.session.borrow_owner().lanelets.as_ref()
    }

    /// The run so far as a conversion of the file: the bytes `osc2cr convert` would write had
    /// the run gone this way, and the model they serialise.
    pub fn finish(&self) -> (Conversion, Option<Model>) {
        let run = self.session.with_dependent(|_, sim| sim.run_so_far());
        let warnings = run.warnings.iter().map(ToString::to_string).collect();
        self.convert_run(&run.trace, warnings, self.started)
    }

    /// `trace` (with the engine's `engine_warnings`; begun at `started`) converted as
    /// `convert` converts a run of this file.
    fn convert_run(&self, trace: &engine::Trace, engine_warnings: Vec<String>, started: Instant) -> (Conversion, Option<Model>) {
        let mut warnings = self.warnings.clone();
        let mut timings = self.timings;
        let mut facts = Facts::default();
        warnings.extend(engine_warnings.into_iter().map(|message| StageWarning { stage: Stage::Engine, message }));
        let prepared = self.session.borrow_owner();
        let request = Request::file(&self.path);
        let built = finish(prepared, prepared.lanelets.clone(), &request, &self.options, trace, started, &mut warnings, &mut timings, &mut facts);
        let mut model = None;
        let result = built.map(|(output, m)| {
            model = Some(m);
            output
        });
        (Conversion { result, warnings, timings, facts }, model)
    }
}
