//! One conversion named exactly as a batch names it — the same benchmark id, header source
//! and output file name — so that callers outside a batch (the Python package, a distributed
//! scheduler) produce the bytes and files `osc2cr convert` produces.

use std::path::{Path, PathBuf};

use openscenario::{Content, Distribution, LoadOptions};

use crate::cache::Caches;
use crate::options::ConvertOptions;
use crate::pipeline::{convert, Conversion, Request};
use crate::report::{Failure, Stage};

/// Header source of a batch conversion: `input` is the file given (scenario or distribution),
/// `variation` the 1-based parameter set of a distribution.
pub fn batch_source(input: &Path, variation: Option<u64>) -> String {
    match variation {
        Some(k) => format!("OpenSCENARIO {} (parameter set {k}), converted by osc2cr", file_name(input)),
        None => format!("OpenSCENARIO {}, converted by osc2cr", file_name(input)),
    }
}

/// The scenario name of the benchmark id: the stem of the file given.
pub fn batch_name(input: &Path) -> String {
    input.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default()
}

/// The output file name of a file given directly: `<stem>.xml`, or `<stem>_<k>.xml` for
/// variation `k` (a batch adds `-2`, `-3`, … only when two inputs would share a name).
pub fn output_file_name(input: &Path, variation: Option<u64>) -> PathBuf {
    PathBuf::from(format!("{}.xml", output_name(input, variation)))
}

/// The output name (no extension) of a file given directly: `<stem>` or `<stem>_<k>`. The
/// 2020a file is `<name>.xml`; the 2024 files are `<name>-SC.pb` and `<name>.pb`.
pub fn output_name(input: &Path, variation: Option<u64>) -> String {
    let stem = input.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "scenario".into());
    match variation {
        Some(k) => format!("{stem}_{k}"),
        None => stem,
    }
}

fn file_name(p: &Path) -> String {
    p.file_name().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default()
}

impl<'a> Request<'a> {
    /// The scenario file `path` named as `osc2cr convert path` names it (benchmark name, header
    /// source): [`Request::named`] with [`batch_name`] and [`batch_source`].
    pub fn file(path: &'a Path) -> Request<'a> {
        Request { source: batch_source(path, None), ..Request::named(path, &batch_name(path)) }
    }
}

/// Loads the parameter distribution file `path` with the options' global parameters and seed,
/// as a batch does. `Err` when it cannot be loaded or is not a distribution, or (unless
/// `options.lenient`) when it cannot be sampled as written.
pub fn load_distribution(path: &Path, options: &ConvertOptions) -> Result<Distribution, Failure> {
    let load = LoadOptions { parameters: options.parameters.clone(), seed: options.seed, ..Default::default() };
    let fail = |message: String| Failure { stage: Stage::Load, message };
    match openscenario::load(path, &load) {
        Ok(l) if !l.problems.is_empty() && !options.lenient => {
            let list: Vec<String> = l.problems.iter().map(ToString::to_string).collect();
            Err(fail(format!("the distribution cannot be sampled (lenient reading samples it anyway):\n{}", list.join("\n"))))
        }
        Ok(l) => match l.content {
            Content::Distribution(d) => Ok(d),
            _ => Err(fail(format!("{}: expected a ParameterValueDistribution", path.display()))),
        },
        Err(e) => Err(fail(e.to_string())),
    }
}

/// Converts variation `index` (1-based) of the distribution `dist` loaded from `path`, as a
/// batch does; a failure when the distribution has no such run.
pub fn convert_variation(path: &Path, dist: &Distribution, index: u64, options: &ConvertOptions) -> Conversion {
    convert_variation_with(path, dist, index, options, &Caches::with_capacity(1))
}

/// Like [`convert_variation`], reading the road network through `caches` (a stream of
/// variations on one map reads and converts it once).
pub fn convert_variation_with(path: &Path, dist: &Distribution, index: u64, options: &ConvertOptions, caches: &Caches) -> Conversion {
    let Some(parameters) = index.checked_sub(1).and_then(|i| dist.get(i)) else {
        return Conversion {
            result: Err(Failure {
                stage: Stage::Load,
                message: format!("{}: no parameter set {index}; the distribution has {} (numbered from 1)", path.display(), dist.len()),
            }),
            warnings: Vec::new(),
            timings: Default::default(),
            facts: Default::default(),
        };
    };
    let request = Request {
        config: index,
        parameters: &parameters,
        source: batch_source(path, Some(index)),
        ..Request::named(&dist.scenario_file, &batch_name(path)).with_caches(caches)
    };
    convert(&request, options).0
}
