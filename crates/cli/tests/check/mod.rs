//! `osc2cr check`: findings with severity and position, against the ASAM OpenSCENARIO API's own
//! expectations.

mod checker_suite;
mod findings;
