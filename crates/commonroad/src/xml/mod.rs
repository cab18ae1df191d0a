//! The CommonRoad 2020a XML writer: fixed-notation decimals, escaped text, XSD element order,
//! deterministic bytes, and atomic file output.

mod atomic;
mod emitter;
mod escape;
mod number;
mod read;
mod write;

pub use atomic::{is_special_file, remove_stale_temporaries, write_atomic};
pub use escape::escape;
pub use number::{format_decimal, is_written_positive, DECIMALS};
pub use read::{read_planning_problem_str, read_scenario_file, read_scenario_str, ReadPlanningProblem, ReadScenario, MAX_FILE_BYTES};
pub use write::{write_map, write_planning_problem, write_scenario, PLANNING_PROBLEM_ROOT};
