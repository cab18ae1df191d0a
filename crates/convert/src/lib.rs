//! `convert`: OpenSCENARIO in, CommonRoad out — the paper's algorithm end to end. It loads a
//! scenario and its OpenDRIVE road network, has `map` convert the roads to lanelets and
//! `engine` run the storyboard, turns the trace into CommonRoad obstacles (Table I types,
//! bounding-box centres, headings wrapped and resampled to the CommonRoad step) and the ego's
//! planning problem, checks and serialises the result (CommonRoad 2020a XML, or the 2024
//! format's map, scenario and dynamic files); and it runs batches of scenario files and
//! parameter variations in parallel — streaming, so a sweep of 100,000 variations runs in flat
//! memory, each OpenDRIVE map read once — with a report per scenario, whole, as one shard, or
//! resumed after an interruption.
//!
//! It glues the other crates together and owns the OpenSCENARIO → CommonRoad mapping; it does
//! not parse files itself, simulate, convert roads, draw (`render` draws the pictures of
//! `--render`), or print anything (warnings, failures and timings are returned as data; the
//! `osc2cr` binary presents them).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod angle;
mod assemble;
mod audit;
mod batch;
mod bbox;
mod cache;
mod carried;
mod closed_loop;
mod country;
mod declared_cycles;
mod discover;
mod ego;
mod goal;
mod header;
mod held_input;
mod light_cycles;
mod naming;
mod obstacle_type;
mod obstacles;
mod options;
mod outputs;
mod picture;
mod pipeline;
mod plan;
pub mod preflight;
mod report;
mod report_files;
mod resample;
mod shard;
mod single;
mod stages;
mod story_marks;
mod summary;
mod tags;
mod trace_of;
mod tracks;

pub use angle::{lerp_angle, wrap_angle};
pub use assemble::{assemble, Assembled};
pub use audit::audit as audit_trace;
pub use batch::{run_batch, run_batch_streaming, BatchOptions, BatchSummary, Progress, Silent};
pub use bbox::{box_center, reference_point};
pub use cache::{Caches, Road};
pub use carried::{carried_problems, retarget, Carried, PLANNING_PROBLEM_PROPERTY};
pub use closed_loop::ClosedLoop;
pub use discover::{classify, discover, FileKind, Found};
pub use ego::NO_EGO;
pub use ego::{choose_ego, EgoChoice};
pub use goal::{planning_problem, GoalOptions};
pub use header::{benchmark_id, check_country, date_prefix, fallback_date, parse_date};
pub use obstacle_type::{cr_type, CrType};
pub use obstacles::{obstacles, Obstacles};
pub use options::{ConvertOptions, OutputFormat};
pub use outputs::{write_output, MapFiles, OutputPaths, Written};
pub use picture::{picture_path, write_picture};
pub use pipeline::{convert, Conversion, Model, Output, Prepared, Protobuf2024, Request};
pub use report::{BatchReport, Facts, Failure, FolderSummary, ScenarioReport, Skipped, Stage, StageWarning, Status, Timings, Variation};
pub use report_files::{JsonReport, Table, TABLE_COLUMNS};
pub use resample::{cr_step_count, resample, whole_multiple, Pose};
pub use shard::Shard;
pub use single::{batch_name, batch_source, convert_variation, convert_variation_with, load_distribution, output_file_name, output_name};
pub use stages::map_options;
pub use story_marks::event_marks;
pub use summary::{render as render_summary, render_table, summarise, Summary};
pub use tags::scenario_tags;
pub use trace_of::trace_of;
pub use tracks::{tracks, Placement, Track, MIN_BOX_SIDE};

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
