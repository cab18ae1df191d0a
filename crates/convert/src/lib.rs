//! `convert`: OpenSCENARIO in, CommonRoad out — the paper's algorithm end to end. It loads a
//! scenario and its OpenDRIVE road network, has `map` convert the roads to lanelets and
//! `engine` run the storyboard, turns the trace into CommonRoad obstacles (Table I types,
//! bounding-box centres, headings wrapped and resampled to the CommonRoad step) and the ego's
//! planning problem, checks and serialises the result; and it runs batches of scenario files
//! and parameter variations in parallel with a report per scenario, whole or as one shard.
//!
//! It glues the other crates together and owns the OpenSCENARIO → CommonRoad mapping; it does
//! not parse files itself, simulate, convert roads, draw (`render` draws the pictures of
//! `--render`), or print anything (warnings, failures and timings are returned as data; the
//! `osc2cr` binary presents them).

mod angle;
mod assemble;
mod audit;
mod batch;
mod bbox;
mod closed_loop;
mod country;
mod discover;
mod ego;
mod goal;
mod header;
mod held_input;
mod light_cycles;
mod obstacle_type;
mod obstacles;
mod options;
mod picture;
mod pipeline;
mod report;
mod resample;
mod shard;
mod story_marks;
mod single;
mod stages;
mod summary;
mod tags;
mod tracks;

pub use angle::{lerp_angle, wrap_angle};
pub use assemble::{assemble, Assembled};
pub use audit::audit as audit_trace;
pub use batch::{run_batch, BatchOptions, Progress, Silent};
pub use bbox::{box_center, reference_point};
pub use closed_loop::ClosedLoop;
pub use discover::{classify, discover, FileKind, Found};
pub use ego::{choose_ego, EgoChoice};
pub use goal::{planning_problem, GoalOptions};
pub use header::{benchmark_id, check_country, date_prefix, fallback_date, parse_date};
pub use obstacle_type::{cr_type, CrType};
pub use obstacles::{obstacles, Obstacles};
pub use options::ConvertOptions;
pub use picture::{picture_path, write_picture};
pub use pipeline::{convert_scenario, convert_scenario_keeping, Conversion, Facts, Model, Prepared, Request};
pub use report::{
    BatchReport, Failure, FolderSummary, ScenarioReport, Skipped, Stage, StageWarning, Status,
    Timings, Variation,
};
pub use resample::{cr_step_count, resample, whole_multiple, Pose};
pub use shard::Shard;
pub use story_marks::event_marks;
pub use single::{
    batch_name, batch_source, convert_file, convert_variation, load_distribution, output_file_name,
};
pub use summary::{render as render_summary, summarise};
pub use tags::scenario_tags;
pub use tracks::{tracks, Placement, Track, MIN_BOX_SIDE};
