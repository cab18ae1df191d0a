//! One scenario end to end (the paper's algorithm): load the OpenSCENARIO file, load its
//! OpenDRIVE file and convert it to lanelets, run the storyboard, build obstacles and the
//! planning problem, check, and serialise (2020a XML, or the three files of the 2024 format).
//! Every stage's warnings are kept as data, every stage is timed, and a failure names its
//! stage. The road network and its lanelets come from a [`Caches`], so the conversions of one
//! batch that name the same OpenDRIVE file read and convert it once.

use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

use commonroad::protobuf::MapFile;
use commonroad::{Header, LaneletNetwork};
use openscenario::{Content, LoadOptions, Scenario};

use crate::assemble::assemble;
use crate::cache::Caches;
use crate::declared_cycles::{apply_declared_cycles, declared_cycles};
use crate::header::{benchmark_id, date_prefix, fallback_date};
use crate::light_cycles::apply_signal_states;
use crate::options::{ConvertOptions, OutputFormat};
use crate::report::{Facts, Failure, Stage, StageWarning, Timings};
use crate::stages::run_engine;

/// What a conversion serialised, in the format of its options.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// A CommonRoad 2020a XML file.
    Xml(Vec<u8>),
    /// The three files of the CommonRoad 2024 format.
    Protobuf(Protobuf2024),
}

impl Output {
    /// The XML bytes of a 2020a conversion.
    pub fn xml(&self) -> Option<&[u8]> {
        match self {
            Output::Xml(b) => Some(b),
            Output::Protobuf(_) => None,
        }
    }
    /// The files of a 2024 conversion.
    pub fn protobuf(&self) -> Option<&Protobuf2024> {
        match self {
            Output::Xml(_) => None,
            Output::Protobuf(p) => Some(p),
        }
    }
}

/// A scenario in the 2024 format: its map (named by its content, shared with every scenario of
/// the batch on the same lanelet network), its scenario file and its dynamic file.
#[derive(Debug, Clone, PartialEq)]
pub struct Protobuf2024 {
    pub map: Arc<MapFile>,
    pub scenario: Vec<u8>,
    pub dynamic: Vec<u8>,
}

/// The result of converting one scenario: the file's bytes or why not, and what happened.
#[derive(Debug, Clone)]
pub struct Conversion {
    pub result: Result<Output, Failure>,
    pub warnings: Vec<StageWarning>,
    pub timings: Timings,
    pub facts: Facts,
}

/// Which scenario to convert, how to name it, and what to keep: the one way in to a
/// conversion ([`convert`]). [`Request::file`] names a file as `osc2cr convert` does.
#[derive(Clone)]
pub struct Request<'a> {
    /// The OpenSCENARIO scenario file.
    pub path: &'a Path,
    /// The name in the benchmark id (reduced to letters and digits there).
    pub name: String,
    /// Configuration id of the benchmark id: the variation index, 1 without variations.
    pub config: u64,
    /// Parameter values of a variation, applied after `ConvertOptions::parameters`.
    pub parameters: &'a [(String, String)],
    /// Source text for the header when `ConvertOptions::source` is not set.
    pub source: String,
    /// Also return the model a successful conversion serialised (e.g. to draw it); off by
    /// default: a batch of large maps should not hold every model.
    pub keep_model: bool,
    /// The road networks shared with other conversions (a batch passes the one its workers
    /// share); `None`: a cache of this conversion's own.
    pub caches: Option<&'a Caches>,
}

impl<'a> Request<'a> {
    /// The scenario file `path` under the benchmark name `name`: configuration 1, no
    /// parameters, an empty header source (the default of [`ConvertOptions::source`] applies),
    /// no model kept, a cache of its own. [`Request::file`] names it as a batch does.
    pub fn named(path: &'a Path, name: &str) -> Request<'a> {
        Request { path, name: name.to_string(), config: 1, parameters: &[], source: String::new(), keep_model: false, caches: None }
    }

    /// This request, keeping the model ([`Request::keep_model`]).
    pub fn keeping_model(self) -> Request<'a> {
        Request { keep_model: true, ..self }
    }

    /// This request, reading road networks through `caches` ([`Request::caches`]).
    pub fn with_caches(self, caches: &'a Caches) -> Request<'a> {
        Request { caches: Some(caches), ..self }
    }
}

impl std::fmt::Debug for Request<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Request")
            .field("path", &self.path)
            .field("name", &self.name)
            .field("config", &self.config)
            .field("parameters", &self.parameters)
            .field("source", &self.source)
            .field("keep_model", &self.keep_model)
            .field("shared_caches", &self.caches.is_some())
            .finish()
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The CommonRoad model a conversion serialised, kept on request (e.g. to draw it).
#[derive(Debug, Clone)]
pub struct Model {
    pub scenario: commonroad::Scenario,
    pub problems: commonroad::PlanningProblemSet,
    /// The OpenSCENARIO entity of each obstacle: (obstacle id, entity name).
    pub names: Vec<(u64, String)>,
    /// When each storyboard Event started: (time s, event name), in time order.
    pub events: Vec<(f64, String)>,
}

/// Converts one scenario file into CommonRoad bytes in the options' format (nothing is
/// written); with [`Request::keep_model`], a successful conversion also returns the model it
/// serialised.
pub fn convert(request: &Request<'_>, options: &ConvertOptions) -> (Conversion, Option<Model>) {
    let own;
    let caches = match request.caches {
        Some(c) => c,
        None => {
            own = Caches::with_capacity(1);
            &own
        }
    };
    let start = Instant::now();
    let mut c = Conversion {
        result: Err(Failure { stage: Stage::Load, message: String::new() }),
        warnings: Vec::new(),
        timings: Timings::default(),
        facts: Facts::default(),
    };
    let mut model = None;
    c.result = run(request, options, caches, &mut c.warnings, &mut c.timings, &mut c.facts).map(|(output, m)| {
        model = request.keep_model.then_some(m);
        output
    });
    c.timings.total_ms = ms(start);
    (c, model)
}

fn fail(stage: Stage, message: impl Into<String>) -> Failure {
    Failure { stage, message: message.into() }
}

fn warn<T: ToString>(out: &mut Vec<StageWarning>, stage: Stage, list: &[T]) {
    out.extend(list.iter().map(|w| StageWarning { stage, message: w.to_string() }));
}

/// Which kind of problems a strict reading rejects, for the error's first line.
#[derive(Clone, Copy)]
enum Problems {
    /// The file against the schema of its declared version (`openscenario::validate`).
    Schema,
    /// References to what does not exist, distributions that cannot be sampled.
    References,
}

/// Problems a strict reading rejects: an error listing every one (file:line:col each) by
/// default, warnings with `--lenient`.
fn strict<T: ToString>(problems: &[T], what: Problems, stage: Stage, options: &ConvertOptions, warnings: &mut Vec<StageWarning>) -> Result<(), Failure> {
    if problems.is_empty() {
        return Ok(());
    }
    if options.lenient {
        warn(warnings, stage, problems);
        return Ok(());
    }
    let list: Vec<String> = problems.iter().map(ToString::to_string).collect();
    let n = list.len();
    let s = if n == 1 { "" } else { "s" };
    let header = match what {
        Problems::Schema => format!("{n} error{s} against the OpenSCENARIO schema"),
        Problems::References => {
            format!("{n} reference{s} to what does not exist or value{s} that cannot be used")
        }
    };
    Err(fail(stage, format!("{header} (--lenient reads them as warnings):\n{}", list.join("\n"))))
}

fn run(
    request: &Request<'_>,
    options: &ConvertOptions,
    caches: &Caches,
    warnings: &mut Vec<StageWarning>,
    timings: &mut Timings,
    facts: &mut Facts,
) -> Result<(Output, Model), Failure> {
    let mut prepared = prepare(request, options, caches, warnings, timings)?;

    // 3. the run
    let t = Instant::now();
    let run = run_engine(&prepared.scenario, prepared.road(), options).map_err(|e| match e {
        // the batch's --timeout reached the engine first: the same failure as the batch's own
        engine::Error::Deadline(t) => fail(Stage::Timeout, format!("not converted within the time limit (--timeout); the engine stopped at {t:.2} s")),
        other => fail(Stage::Engine, other.to_string()),
    })?;
    warn(warnings, Stage::Engine, &run.warnings);
    let lanelets = prepared.lanelets.take();
    finish(&prepared, lanelets, request, options, &run.trace, t, warnings, timings, facts)
}

/// A scenario loaded and checked, with its road network and lanelets: what a run needs and
/// what its conversion adds the run to. `prepare` makes it; the batch pipeline runs the engine
/// on it, a closed-loop session steps it (`closed_loop.rs`); `finish` turns a run into
/// CommonRoad.
pub struct Prepared {
    pub scenario: Scenario,
    /// The road network and its converted map, shared through the batch's caches.
    cached: Option<Arc<crate::cache::Road>>,
    /// This scenario's copy of the lanelets (the light cycles are written into it).
    pub lanelets: Option<LaneletNetwork>,
    map_tags: std::collections::BTreeSet<commonroad::Tag>,
    light_of_signal: std::collections::BTreeMap<String, commonroad::TrafficLightId>,
}

impl Prepared {
    /// The road network (`None`: the scenario names none).
    pub fn road(&self) -> Option<&opendrive::RoadNetwork> {
        self.cached.as_deref().map(|r| &r.network)
    }
}

/// Stages 1 and 2: the scenario (schema pass, load, references) and its road network and
/// lanelets (read and converted once per batch through `caches`), each with its warnings and
/// time.
pub(crate) fn prepare(
    request: &Request<'_>,
    options: &ConvertOptions,
    caches: &Caches,
    warnings: &mut Vec<StageWarning>,
    timings: &mut Timings,
) -> Result<Prepared, Failure> {
    options.check().map_err(|m| fail(Stage::Load, m))?;

    // 1. the scenario
    let t = Instant::now();
    let mut parameters = options.parameters.clone();
    parameters.extend(request.parameters.iter().cloned());
    let load_options = LoadOptions { parameters, seed: options.seed, ..Default::default() };
    // The schema pass first (the same as `osc2cr check`): what is wrong with the file itself,
    // all of it. Its warnings (deprecations, version mixtures) are `check`'s to list.
    // A file that is missing, empty or not well-formed XML stops here as what it is: it is not a
    // schema error `--lenient` could read past.
    let schema_errors: Vec<String> = openscenario::validate::validate_readable_file(request.path, &load_options.parameters)
        .map_err(|e| fail(Stage::Load, e.to_string()))?
        .into_iter()
        .filter(|f| f.severity == openscenario::validate::Severity::Error)
        .map(|f| format!("{}: {}", f.location, f.message))
        .collect();
    if !schema_errors.is_empty() {
        // a file that cannot be read, or an override that does not fit its parameter, is said
        // as what it is: --lenient changes nothing about it
        let causes = crate::preflight::cause(request.path, &options.parameters, request.parameters);
        if !causes.is_empty() {
            return Err(fail(Stage::Load, causes.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n")));
        }
    }
    strict(&schema_errors, Problems::Schema, Stage::Load, options, warnings)?;
    let loaded = openscenario::load(request.path, &load_options).map_err(|e| fail(Stage::Load, e.to_string()))?;
    warn(warnings, Stage::Load, &loaded.warnings);
    strict(&loaded.problems, Problems::References, Stage::Load, options, warnings)?;
    let scenario: Scenario = match loaded.content {
        Content::Scenario(s) => *s,
        Content::Distribution(_) => {
            return Err(fail(Stage::Load, "a parameter value distribution names another scenario file; a distribution cannot vary a distribution"))
        }
        Content::Catalog(_) => return Err(fail(Stage::Load, "a catalog file is not a scenario")),
    };
    timings.load_ms = ms(t);

    // 2. the road network and its lanelets (read and converted once per batch)
    let t = Instant::now();
    let cached = match &scenario.road_network.logic_file {
        Some(path) => {
            let (road, fresh) = caches.road(path, options);
            let road = road.map_err(|e| fail(Stage::RoadNetwork, crate::preflight::road_failure(&scenario, path, &e).to_string()))?;
            warn(warnings, Stage::RoadNetwork, &road.warnings);
            if fresh {
                timings.road_network_ms = road.load_ms;
                timings.map_ms = road.map_ms;
            } else {
                timings.road_network_ms = ms(t);
            }
            Some(road)
        }
        None => {
            warnings.push(StageWarning { stage: Stage::RoadNetwork, message: "the scenario names no road network (RoadNetwork/LogicFile)".into() });
            timings.road_network_ms = ms(t);
            None
        }
    };
    let road = cached.as_deref().map(|r| &r.network);
    strict(&engine::road_references(&scenario, road), Problems::References, Stage::RoadNetwork, options, warnings)?;
    let (lanelets, map_tags, light_of_signal): (Option<LaneletNetwork>, _, _) = match &cached {
        Some(r) => {
            warn(warnings, Stage::Map, &r.map.warnings);
            (Some(r.map.network.clone()), r.map.tags.clone(), r.map.light_of_signal.clone())
        }
        None => (None, Default::default(), Default::default()),
    };
    Ok(Prepared { scenario, cached, lanelets, map_tags, light_of_signal })
}

/// Stages 3 (the audit of the run's trace; `engine_start`: when the run began, for its time)
/// to 5: traffic-light cycles, obstacles and planning problem, checks, the output in the
/// options' format. `lanelets` are `prepared`'s, taken (or copied) because the light cycles
/// are written into them.
#[allow(clippy::too_many_arguments)]
pub(crate) fn finish(
    prepared: &Prepared,
    mut lanelets: Option<LaneletNetwork>,
    request: &Request<'_>,
    options: &ConvertOptions,
    trace: &engine::Trace,
    engine_start: Instant,
    warnings: &mut Vec<StageWarning>,
    timings: &mut Timings,
    facts: &mut Facts,
) -> Result<(Output, Model), Failure> {
    let scenario = &prepared.scenario;
    let audit = crate::audit::audit(trace, scenario, lanelets.as_ref()).map_err(|m| fail(Stage::Engine, format!("{}: {m}", scenario.path.display())))?;
    warn(warnings, Stage::Engine, &audit);
    timings.engine_ms = ms(engine_start);
    facts.duration_s = Some(trace.end_time().max(0.0));
    if let Some(network) = lanelets.as_mut() {
        let states = &trace.signal_states;
        let w = apply_signal_states(network, &prepared.light_of_signal, states, trace.end_time(), options.dt);
        warn(warnings, Stage::Build, &w);
        // lights the run never set take the cycle their (unrun) controller declares
        let controllers = &scenario.road_network.traffic_signal_controllers;
        let mut w = Vec::new();
        let declared = declared_cycles(controllers, options.dt, &mut w);
        let set_by_run = states.iter().map(|s| s.signal.as_str()).collect();
        w.extend(apply_declared_cycles(network, &prepared.light_of_signal, &declared, &set_by_run, controllers));
        warn(warnings, Stage::Build, &w);
    }

    // 4. obstacles, planning problem, checks
    let t = Instant::now();
    let header = header(request, scenario, options).map_err(|e| fail(Stage::Build, e))?;
    facts.benchmark_id = Some(header.benchmark_id.to_string());
    let built = assemble(header, lanelets, &prepared.map_tags, trace, &scenario.entities, options)
        .map_err(|e| fail(Stage::Build, format!("{}: {e}", scenario.path.display())))?;
    warn(warnings, Stage::Build, &built.warnings);
    facts.ego = Some(built.ego.clone());
    facts.lanelets = built.lanelets;
    facts.obstacles = built.obstacles;
    facts.tags = built.scenario.tags.iter().map(|t| t.as_str().to_string()).collect();
    timings.build_ms = ms(t);

    // 5. the output
    let t = Instant::now();
    let output = match options.format {
        OutputFormat::Xml2020a => {
            Output::Xml(commonroad::xml::write_scenario(&built.scenario, &built.problems).map_err(|e| fail(Stage::Write, e.to_string()))?)
        }
        OutputFormat::Protobuf2024 => {
            let write_error = |e: commonroad::Error| fail(Stage::Write, e.to_string());
            // the map of a cached road is encoded once for all its scenarios
            let map = match &prepared.cached {
                Some(road) => road.map_file(&built.scenario).map_err(write_error)?,
                None => Arc::new(commonroad::protobuf::encode_map(&built.scenario).map_err(write_error)?),
            };
            let files = commonroad::protobuf::encode_scenario(&built.scenario, &built.problems, &map.id).map_err(write_error)?;
            warn(warnings, Stage::Write, &map.warnings);
            warn(warnings, Stage::Write, &files.warnings);
            Output::Protobuf(Protobuf2024 { map, scenario: files.scenario, dynamic: files.dynamic })
        }
    };
    timings.write_ms = ms(t);
    let model =
        Model { scenario: built.scenario, problems: built.problems, names: built.names, events: crate::story_marks::event_marks(scenario, &trace.events) };
    Ok((output, model))
}

fn header(request: &Request<'_>, scenario: &Scenario, options: &ConvertOptions) -> Result<Header, String> {
    let benchmark_id = benchmark_id(&options.country, &request.name, request.config).map_err(|e| e.to_string())?;
    let date = options.date.or_else(|| date_prefix(&scenario.header.date)).unwrap_or_else(fallback_date);
    let author = match &options.author {
        Some(a) => a.clone(),
        None if !scenario.header.author.trim().is_empty() => scenario.header.author.trim().to_string(),
        None => "osc2cr".to_string(),
    };
    Ok(Header {
        benchmark_id,
        date,
        author,
        affiliation: options.affiliation.clone(),
        source: options.source.clone().unwrap_or_else(|| request.source.clone()),
        time_step_size: options.dt,
    })
}
