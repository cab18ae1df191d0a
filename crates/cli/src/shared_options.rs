//! The options several commands share, each defined once and flattened into the commands'
//! arguments (`#[command(flatten)]`), so that it is named, parsed and explained the same way
//! everywhere: `--param` (convert, simulate, serve, inspect, check), the options of the
//! commands that run a scenario, `--step`, `--max-time`, `--engine-seed`, `--lenient` (convert,
//! simulate, serve), and those of the commands that write the run as CommonRoad, `--dt`,
//! `--drop-ego`, `--date` (convert, serve).

/// `--param NAME=VALUE`, repeatable.
#[derive(clap::Args)]
pub(crate) struct ParamArgs {
    /// Give global parameter NAME the value VALUE instead of its declared one (repeatable; the
    /// value must fit the parameter's declared type).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = parse_param)]
    pub(crate) values: Vec<(String, String)>,
}

/// How a scenario is run.
#[derive(clap::Args)]
pub(crate) struct RunArgs {
    /// Engine step, s.
    #[arg(long, default_value_t = 0.01)]
    pub(crate) step: f64,
    /// Simulated time after which a run stops, s.
    #[arg(long, default_value_t = 60.0)]
    pub(crate) max_time: f64,
    #[command(flatten)]
    pub(crate) params: ParamArgs,
    /// Seed of esmini's random generator in the engine (esmini's --seed; 0 as in the reference
    /// traces). It decides what esmini leaves to chance, e.g. which of two equally turning
    /// junction arms an entity takes.
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub(crate) engine_seed: u32,
    /// Read references to what does not exist (an undeclared entity, storyboard element,
    /// parameter or variable; a road or lane the map does not have; a parameter override the
    /// scenario does not declare) and distributions that cannot be sampled (negative variance,
    /// empty range, …) as warnings and go on, as esmini does. By default each is an error naming
    /// file:line:col, and nothing is written.
    #[arg(long)]
    pub(crate) lenient: bool,
}

/// The CommonRoad file a run becomes.
#[derive(clap::Args)]
pub(crate) struct CommonRoadArgs {
    /// CommonRoad time step, s.
    #[arg(long, default_value_t = 0.1)]
    pub(crate) dt: f64,
    /// Leave the ego out of the obstacles (for motion-planning benchmarks).
    #[arg(long)]
    pub(crate) drop_ego: bool,
    /// Date attribute, YYYY-MM-DD (default: the FileHeader's date, else 1970-01-01 — never
    /// today, so the same input gives the same bytes).
    #[arg(long, value_parser = convert::parse_date)]
    pub(crate) date: Option<commonroad::Date>,
}

/// `NAME=VALUE`, the name trimmed and without a leading `$` (a parameter is declared and
/// referred to as `$NAME` too).
fn parse_param(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((n, v)) if !n.trim().trim_start_matches('$').is_empty() => Ok((n.trim().trim_start_matches('$').to_string(), v.to_string())),
        _ => Err(format!("expected NAME=VALUE, got {s:?}")),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_param;

    #[test]
    fn a_parameter_is_a_name_and_a_value() {
        assert_eq!(parse_param("EgoSpeed=72"), Ok(("EgoSpeed".into(), "72".into())));
        assert_eq!(parse_param(" $EgoSpeed =7=2"), Ok(("EgoSpeed".into(), "7=2".into())));
        assert_eq!(parse_param("Name="), Ok(("Name".into(), String::new())));
        for bad in ["novalue", "=1", " =1", "$=1"] {
            assert!(parse_param(bad).is_err(), "{bad}");
        }
    }
}
