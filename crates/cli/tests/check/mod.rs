//! `osc2cr check`: findings with severity and position, against the ASAM OpenSCENARIO API's own
//! expectations, and the same verdict as `convert` on every failing input.

mod agrees_with_convert;
mod checker_suite;
mod findings;
mod lenient_fallbacks;
mod mutations;
mod reference_positions;
mod second_checker_rules;
mod valid_inputs;
