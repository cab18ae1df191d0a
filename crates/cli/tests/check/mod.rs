//! `osc2cr check`: findings with severity and position, against the ASAM OpenSCENARIO API's own
//! expectations.

mod checker_suite;
mod findings;
mod lenient_fallbacks;
mod mutations;
mod reference_positions;
mod second_checker_rules;
mod valid_inputs;
