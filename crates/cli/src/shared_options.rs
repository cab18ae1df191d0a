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
    #[arg(long, default_value_t = 0.01, allow_negative_numbers = true)]
    pub(crate) step: f64,
    /// Simulated time after which a run stops, s.
    #[arg(long, default_value_t = 60.0, allow_negative_numbers = true)]
    pub(crate) max_time: f64,
    #[command(flatten)]
    pub(crate) params: ParamArgs,
    /// Seed of esmini's random generator in the engine (esmini's --seed; 0 as in the reference
    /// traces). It decides what esmini leaves to chance, e.g. which of two equally turning
    /// junction arms an entity takes.
    #[arg(long, default_value_t = 0, value_name = "N", allow_negative_numbers = true, value_parser = whole::<u32>)]
    pub(crate) engine_seed: u32,
    /// Read references to what does not exist (an undeclared entity, storyboard element,
    /// parameter or variable; a road or lane the map does not have; a parameter override the
    /// scenario does not declare) and distributions that cannot be sampled (negative variance,
    /// empty range, …) as warnings and go on, as esmini does. By default each is an error naming
    /// file:line:col, and nothing is written.
    #[arg(long)]
    pub(crate) lenient: bool,
}

impl RunArgs {
    /// `convert`'s options with these set, the others at their defaults.
    pub(crate) fn convert_options(&self) -> convert::ConvertOptions {
        convert::ConvertOptions {
            step: self.step,
            max_time: self.max_time,
            parameters: self.params.values.clone(),
            engine_seed: self.engine_seed,
            lenient: self.lenient,
            ..Default::default()
        }
    }
}

/// A whole number of at least 0, for the options that count (their type's own parser would
/// answer `-1` with "invalid digit found in string"). Numeric options take negative numbers as
/// values (`allow_negative_numbers`), so that `--dt -1` reaches the option's own check and
/// its message instead of being read as an unknown option `-1`.
pub(crate) fn whole<T: std::str::FromStr>(s: &str) -> Result<T, String> {
    s.trim().parse::<T>().map_err(|_| format!("expected a whole number of at least 0 (and not too large), got {s:?}"))
}

/// The CommonRoad file a run becomes.
#[derive(clap::Args)]
pub(crate) struct CommonRoadArgs {
    /// CommonRoad time step, s.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    pub(crate) dt: f64,
    /// Leave the ego out of the obstacles (for motion-planning benchmarks).
    #[arg(long)]
    pub(crate) drop_ego: bool,
    /// Date attribute, YYYY-MM-DD (default: the OpenSCENARIO FileHeader's date, else
    /// 1970-01-01 — never today, so the same input gives the same bytes), as for map.
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
    use super::{parse_param, whole};

    #[test]
    fn a_parameter_is_a_name_and_a_value() {
        assert_eq!(parse_param("EgoSpeed=72"), Ok(("EgoSpeed".into(), "72".into())));
        assert_eq!(parse_param(" $EgoSpeed =7=2"), Ok(("EgoSpeed".into(), "7=2".into())));
        assert_eq!(parse_param("Name="), Ok(("Name".into(), String::new())));
        for bad in ["novalue", "=1", " =1", "$=1"] {
            assert!(parse_param(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_count_is_a_whole_number_of_at_least_zero() {
        assert_eq!(whole::<u64>(" 12"), Ok(12));
        for bad in ["-1", "1.5", "", "x", "99999999999999999999999"] {
            let e = whole::<u64>(bad).expect_err(bad);
            assert!(e.contains("whole number of at least 0") && e.contains(&format!("{bad:?}")), "{e}");
        }
    }
}
