//! The work of a batch, in its fixed order, handed out one conversion at a time: every scenario
//! file is one conversion, every distribution file as many as it has variations (up to
//! `--max-variations`), a distribution that cannot be loaded one failure. Variations are not
//! listed up front — variation k's parameters are computed when it is converted — and names are
//! decided as the order reaches them ([`crate::naming`]), so a sweep of 100,000 variations is a
//! counter, not a list. Every position is named, also those of other shards, so that names are
//! the whole batch's.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use openscenario::{Content, Distribution, LoadOptions};

use crate::discover::{FileKind, Found};
use crate::naming::Namer;
use crate::options::{ConvertOptions, OutputFormat};
use crate::report::{Failure, ScenarioReport, Skipped, Stage, StageWarning, Status};
use crate::shard::Shard;
use crate::single::batch_name;

/// A file of the batch and its conversions.
enum Unit {
    Scenario(Found),
    Distribution {
        found: Found,
        dist: Arc<Distribution>,
        /// Variations converted: the distribution's, capped by `--max-variations`.
        count: u64,
        /// Warnings every variation reports (a capped distribution, lenient problems).
        notes: Arc<[StageWarning]>,
    },
    /// A distribution that cannot be loaded or sampled: one failure.
    Failed(Found, String),
}

impl Unit {
    fn conversions(&self) -> u64 {
        match self {
            Unit::Distribution { count, .. } => *count,
            _ => 1,
        }
    }
}

/// One conversion to run.
#[derive(Debug, Clone)]
pub(crate) struct Job {
    /// The file given or found (scenario or distribution).
    pub input: PathBuf,
    pub folder: String,
    /// The scenario file converted.
    pub scenario: PathBuf,
    /// The name in the benchmark id.
    pub name: String,
    /// The output name: output folder joined with the name, no extension.
    pub stem: PathBuf,
    /// Variation k (1-based) of this distribution.
    pub variation: Option<(u64, Arc<Distribution>)>,
    pub notes: Arc<[StageWarning]>,
}

/// What a position of the batch holds.
pub(crate) enum Work {
    Convert(Job),
    /// A distribution that failed to load, reported at its position.
    Failed(Box<ScenarioReport>),
}

/// The batch's work.
pub(crate) struct Plan {
    units: Vec<Unit>,
    pub skipped: Vec<Skipped>,
    /// Conversions of the whole batch (all shards).
    pub planned: usize,
}

impl Plan {
    /// Loads the distributions among `found` (their variations stay uncomputed).
    pub(crate) fn new(found: Vec<Found>, options: &ConvertOptions) -> Plan {
        let mut units = Vec::new();
        let mut skipped = Vec::new();
        for f in found {
            match &f.kind {
                FileKind::Skip(reason) => skipped.push(Skipped { path: f.path.clone(), reason: reason.clone() }),
                FileKind::Scenario => units.push(Unit::Scenario(f)),
                FileKind::Distribution => units.push(distribution(f, options)),
            }
        }
        let planned = units.iter().map(Unit::conversions).sum::<u64>();
        Plan { units, skipped, planned: usize::try_from(planned).unwrap_or(usize::MAX) }
    }

    /// Conversions of `shard` (all of them without one).
    pub(crate) fn in_shard(&self, shard: Option<Shard>) -> usize {
        match shard {
            None => self.planned,
            Some(s) => {
                let (n, k) = (s.count() as usize, s.index() as usize);
                (self.planned + n - k) / n
            }
        }
    }

    /// The work of `shard`, in batch order, with each position's name.
    pub(crate) fn work(self, out_dir: &Path, format: OutputFormat, shard: Option<Shard>) -> impl Iterator<Item = (usize, Work)> {
        WorkIter { units: self.units.into_iter(), current: None, namer: Namer::new(out_dir, format == OutputFormat::Protobuf2024), shard, position: 0 }
    }
}

fn distribution(f: Found, options: &ConvertOptions) -> Unit {
    let load = LoadOptions { parameters: options.parameters.clone(), seed: options.seed, ..Default::default() };
    let (dist, problems) = match openscenario::load(&f.path, &load) {
        Ok(l) if !l.problems.is_empty() && !options.lenient => {
            let list: Vec<String> = l.problems.iter().map(ToString::to_string).collect();
            let message = format!("the distribution cannot be sampled (--lenient samples it anyway):\n{}", list.join("\n"));
            return Unit::Failed(f, message);
        }
        Ok(l) => match l.content {
            Content::Distribution(d) => (d, l.problems),
            _ => return Unit::Failed(f, "expected a ParameterValueDistribution".into()),
        },
        Err(e) => return Unit::Failed(f, e.to_string()),
    };
    let total = dist.len();
    let count = total.min(options.max_variations);
    let mut notes: Vec<StageWarning> = problems.iter().map(|p| StageWarning { stage: Stage::Load, message: p.to_string() }).collect();
    if total > count {
        notes.push(StageWarning {
            stage: Stage::Load,
            message: format!("the distribution has {total} parameter sets; the first {count} are converted (--max-variations)"),
        });
    }
    Unit::Distribution { found: f, dist: Arc::new(dist), count, notes: notes.into() }
}

fn failed_early(f: &Found, message: &str) -> ScenarioReport {
    let failure = Failure { stage: Stage::Load, message: message.to_string() };
    ScenarioReport { failure: Some(failure), ..ScenarioReport::new(f.path.clone(), f.folder.clone(), None, Status::Failed) }
}

struct WorkIter {
    units: std::vec::IntoIter<Unit>,
    /// The unit being walked and its next variation (1-based).
    current: Option<(Unit, u64)>,
    namer: Namer,
    shard: Option<Shard>,
    position: usize,
}

impl Iterator for WorkIter {
    type Item = (usize, Work);

    fn next(&mut self) -> Option<(usize, Work)> {
        loop {
            let (unit, k) = match self.current.take() {
                Some(c) => c,
                None => (self.units.next()?, 1),
            };
            let position = self.position;
            let mine = !matches!(self.shard, Some(s) if !s.contains(position));
            let work = match &unit {
                Unit::Scenario(f) => {
                    self.position += 1;
                    let stem = self.namer.scenario(&f.output_stem);
                    mine.then(|| {
                        Work::Convert(Job {
                            input: f.path.clone(),
                            folder: f.folder.clone(),
                            scenario: f.path.clone(),
                            name: batch_name(&f.path),
                            stem,
                            variation: None,
                            notes: Arc::from(Vec::new()),
                        })
                    })
                }
                Unit::Failed(f, message) => {
                    self.position += 1;
                    mine.then(|| Work::Failed(Box::new(failed_early(f, message))))
                }
                Unit::Distribution { found, dist, count, notes } => {
                    if k > *count {
                        self.namer.end_distribution(&found.output_stem, *count);
                        continue;
                    }
                    self.position += 1;
                    let stem = self.namer.variation(&found.output_stem, k);
                    let work = mine.then(|| {
                        Work::Convert(Job {
                            input: found.path.clone(),
                            folder: found.folder.clone(),
                            scenario: dist.scenario_file.clone(),
                            name: batch_name(&found.path),
                            stem,
                            variation: Some((k, dist.clone())),
                            notes: notes.clone(),
                        })
                    });
                    self.current = Some((unit, k + 1));
                    match work {
                        Some(w) => return Some((position, w)),
                        None => continue,
                    }
                }
            };
            if let Some(w) = work {
                return Some((position, w));
            }
        }
    }
}
