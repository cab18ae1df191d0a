//! One scenario end to end (the paper's algorithm): load the OpenSCENARIO file, load its
//! OpenDRIVE file and convert it to lanelets, run the storyboard, build obstacles and the
//! planning problem, check, and serialise. Every stage's warnings are kept as data, every
//! stage is timed, and a failure names its stage.

use std::path::Path;
use std::time::Instant;

use commonroad::{Header, LaneletNetwork};
use openscenario::{Content, LoadOptions, Scenario};

use crate::assemble::assemble;
use crate::header::{benchmark_id, date_prefix, fallback_date};
use crate::light_cycles::apply_signal_states;
use crate::options::ConvertOptions;
use crate::report::{Failure, Stage, StageWarning, Timings};
use crate::stages::{run_engine, run_map};

/// Facts about a converted scenario, for the report.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Facts {
    pub benchmark_id: Option<String>,
    pub ego: Option<String>,
    pub lanelets: usize,
    pub obstacles: usize,
    /// Simulated duration, s.
    pub duration_s: Option<f64>,
    pub tags: Vec<String>,
}

/// The result of converting one scenario: the file's bytes or why not, and what happened.
#[derive(Debug, Clone)]
pub struct Conversion {
    pub result: Result<Vec<u8>, Failure>,
    pub warnings: Vec<StageWarning>,
    pub timings: Timings,
    pub facts: Facts,
}

/// Which scenario to convert and how to name it.
#[derive(Debug, Clone, PartialEq)]
pub struct Request<'a> {
    /// The OpenSCENARIO scenario file.
    pub path: &'a Path,
    /// The name in the benchmark id (reduced to letters and digits there).
    pub name: &'a str,
    /// Configuration id of the benchmark id: the variation index, 1 without variations.
    pub config: u64,
    /// Parameter values of a variation, applied after `ConvertOptions::parameters`.
    pub parameters: &'a [(String, String)],
    /// Source text for the header when `ConvertOptions::source` is not set.
    pub source: String,
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

/// Converts one scenario file into CommonRoad XML bytes (nothing is written).
pub fn convert_scenario(request: &Request<'_>, options: &ConvertOptions) -> Conversion {
    convert_scenario_keeping(request, options, false).0
}

/// Like [`convert_scenario`]; with `keep`, a successful conversion also returns the model it
/// serialised (not kept otherwise: a batch of large maps should not hold every model).
pub fn convert_scenario_keeping(
    request: &Request<'_>,
    options: &ConvertOptions,
    keep: bool,
) -> (Conversion, Option<Model>) {
    let start = Instant::now();
    let mut c = Conversion {
        result: Err(Failure {
            stage: Stage::Load,
            message: String::new(),
        }),
        warnings: Vec::new(),
        timings: Timings::default(),
        facts: Facts::default(),
    };
    let mut model = None;
    c.result = run(request, options, &mut c.warnings, &mut c.timings, &mut c.facts)
        .map(|(bytes, m)| {
            model = keep.then_some(m);
            bytes
        });
    c.timings.total_ms = ms(start);
    (c, model)
}

fn fail(stage: Stage, message: impl Into<String>) -> Failure {
    Failure {
        stage,
        message: message.into(),
    }
}

fn warn<T: ToString>(out: &mut Vec<StageWarning>, stage: Stage, list: &[T]) {
    out.extend(list.iter().map(|w| StageWarning {
        stage,
        message: w.to_string(),
    }));
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
fn strict<T: ToString>(
    problems: &[T],
    what: Problems,
    stage: Stage,
    options: &ConvertOptions,
    warnings: &mut Vec<StageWarning>,
) -> Result<(), Failure> {
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
    Err(fail(
        stage,
        format!("{header} (--lenient reads them as warnings):\n{}", list.join("\n")),
    ))
}

fn run(
    request: &Request<'_>,
    options: &ConvertOptions,
    warnings: &mut Vec<StageWarning>,
    timings: &mut Timings,
    facts: &mut Facts,
) -> Result<(Vec<u8>, Model), Failure> {
    let mut prepared = prepare(request, options, warnings, timings)?;

    // 3. the run
    let t = Instant::now();
    let run = run_engine(&prepared.scenario, prepared.road.as_ref(), options).map_err(|e| match e {
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
#[derive(Debug)]
pub struct Prepared {
    pub scenario: Scenario,
    pub road: Option<opendrive::RoadNetwork>,
    pub lanelets: Option<LaneletNetwork>,
    map_tags: std::collections::BTreeSet<commonroad::Tag>,
    light_of_signal: std::collections::BTreeMap<String, commonroad::TrafficLightId>,
}

/// Stages 1 and 2: the scenario (schema pass, load, references) and its road network and
/// lanelets, each with its warnings and time.
pub(crate) fn prepare(
    request: &Request<'_>,
    options: &ConvertOptions,
    warnings: &mut Vec<StageWarning>,
    timings: &mut Timings,
) -> Result<Prepared, Failure> {
    options.check().map_err(|m| fail(Stage::Load, m))?;

    // 1. the scenario
    let t = Instant::now();
    let mut parameters = options.parameters.clone();
    parameters.extend(request.parameters.iter().cloned());
    let load_options = LoadOptions {
        parameters,
        seed: options.seed,
        ..Default::default()
    };
    // The schema pass first (the same as `osc2cr check`): what is wrong with the file itself,
    // all of it. Its warnings (deprecations, version mixtures) are `check`'s to list.
    let schema_errors: Vec<String> = openscenario::validate::validate_file(request.path, &load_options.parameters)
        .into_iter()
        .filter(|f| f.severity == openscenario::validate::Severity::Error)
        .map(|f| format!("{}: {}", f.location, f.message))
        .collect();
    strict(&schema_errors, Problems::Schema, Stage::Load, options, warnings)?;
    let loaded = openscenario::load(request.path, &load_options)
        .map_err(|e| fail(Stage::Load, e.to_string()))?;
    warn(warnings, Stage::Load, &loaded.warnings);
    strict(&loaded.problems, Problems::References, Stage::Load, options, warnings)?;
    let scenario: Scenario = match loaded.content {
        Content::Scenario(s) => *s,
        Content::Distribution(_) => {
            return Err(fail(
                Stage::Load,
                "a parameter value distribution names another scenario file; a distribution cannot vary a distribution",
            ))
        }
        Content::Catalog(_) => {
            return Err(fail(Stage::Load, "a catalog file is not a scenario"))
        }
    };
    timings.load_ms = ms(t);

    // 2. the road network and its lanelets
    let t = Instant::now();
    let road = match &scenario.road_network.logic_file {
        Some(path) => {
            let loaded = opendrive::load(path).map_err(|e| fail(Stage::RoadNetwork, e.to_string()))?;
            warn(warnings, Stage::RoadNetwork, &loaded.warnings);
            Some(loaded.network)
        }
        None => {
            warnings.push(StageWarning {
                stage: Stage::RoadNetwork,
                message: "the scenario names no road network (RoadNetwork/LogicFile)".into(),
            });
            None
        }
    };
    timings.road_network_ms = ms(t);
    strict(&engine::road_references(&scenario, road.as_ref()), Problems::References, Stage::RoadNetwork, options, warnings)?;
    let t = Instant::now();
    let (lanelets, map_tags, light_of_signal) = match &road {
        Some(r) => {
            let m = run_map(r, options);
            warn(warnings, Stage::Map, &m.warnings);
            (Some(m.network), m.tags, m.light_of_signal)
        }
        None => (None, Default::default(), Default::default()),
    };
    timings.map_ms = ms(t);
    Ok(Prepared { scenario, road, lanelets, map_tags, light_of_signal })
}

/// Stages 3 (the audit of the run's trace; `engine_start`: when the run began, for its time)
/// to 5: traffic-light cycles, obstacles and planning problem, checks, bytes. `lanelets` are
/// `prepared`'s, taken (or copied) because the light cycles are written into them.
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
) -> Result<(Vec<u8>, Model), Failure> {
    let scenario = &prepared.scenario;
    let audit = crate::audit::audit(trace, scenario, lanelets.as_ref())
        .map_err(|m| fail(Stage::Engine, format!("{}: {m}", scenario.path.display())))?;
    warn(warnings, Stage::Engine, &audit);
    timings.engine_ms = ms(engine_start);
    facts.duration_s = Some(trace.end_time().max(0.0));
    if let Some(network) = lanelets.as_mut() {
        let states = &trace.signal_states;
        let w = apply_signal_states(network, &prepared.light_of_signal, states, trace.end_time(), options.dt);
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

    // 5. bytes
    let t = Instant::now();
    let bytes = commonroad::xml::write_scenario(&built.scenario, &built.problems)
        .map_err(|e| fail(Stage::Write, e.to_string()))?;
    timings.write_ms = ms(t);
    let model = Model {
        scenario: built.scenario,
        problems: built.problems,
        names: built.names,
        events: crate::story_marks::event_marks(scenario, &trace.events),
    };
    Ok((bytes, model))
}

fn header(request: &Request<'_>, scenario: &Scenario, options: &ConvertOptions) -> Result<Header, String> {
    let benchmark_id = benchmark_id(&options.country, request.name, request.config)
        .map_err(|e| e.to_string())?;
    let date = options
        .date
        .or_else(|| date_prefix(&scenario.header.date))
        .unwrap_or_else(fallback_date);
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
