//! `osc2cr map`: an OpenDRIVE file in, a CommonRoad lanelet network out (written atomically).
//! `--country` and `--date` mean what they mean to `convert`: the scenario's country (benchmark
//! id and the sign catalogue of signals that name none) and the header's date.

use crate::failure::Failure;
use std::path::PathBuf;

#[derive(clap::Args)]
pub(crate) struct MapArgs {
    /// The OpenDRIVE file (.xodr).
    pub file: PathBuf,
    /// Where to write the CommonRoad XML.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Country code of the benchmark id, ZAM or an ISO 3166 alpha-3 code (e.g. DEU, SWE); also
    /// the country of signals that name none (ZAM: the German catalogue of the OpenDRIVE annex),
    /// as for convert.
    #[arg(long, default_value = "ZAM", value_name = "CODE")]
    pub country: String,
    /// Largest distance (m) between a lanelet bound and the exact lane border.
    #[arg(long, default_value_t = 0.005, allow_negative_numbers = true)]
    pub tolerance: f64,
    /// Date attribute, YYYY-MM-DD (default: the OpenDRIVE header's date, else 1970-01-01 — never
    /// today, so the same input gives the same bytes), as for convert.
    #[arg(long, value_parser = convert::parse_date)]
    pub date: Option<commonroad::Date>,
    /// Print the conversion warnings on stderr.
    #[arg(short, long)]
    pub verbose: bool,
    /// CommonRoad format: 2020a (XML) or 2024 (the protobuf map file commonroad-io 2026's
    /// three-file reader takes; its map id is printed).
    #[arg(long, default_value = "2020a", value_name = "2020a|2024")]
    pub format: convert::OutputFormat,
}

pub(crate) fn run(args: &MapArgs) -> Result<(), Failure> {
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        return Err(Failure::input(format!("--tolerance {} must be a positive number of metres", args.tolerance)));
    }
    convert::check_country(&args.country).map_err(|e| Failure::input(format!("--country: {e}")))?;
    if !args.file.exists() {
        return Err(Failure::input(format!("{}: no such file", args.file.display())));
    }
    let loaded = opendrive::load(&args.file).map_err(|e| Failure::input(e.to_string()))?;
    let date = args.date.or_else(|| loaded.network.header.date.as_deref().and_then(convert::date_prefix)).unwrap_or_else(convert::fallback_date);
    let opts = convert::map_options(&args.country, Some(args.tolerance));
    let result = map::convert(&loaded.network, &opts);
    let n_warn = loaded.warnings.len() + result.warnings.len();
    if args.verbose {
        for w in loaded.warnings.iter().chain(&result.warnings) {
            eprintln!("{}", w.labelled("warning"));
        }
    }
    let stem = args.file.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let n_lanelets = result.network.lanelets.len();
    let invalid = |e: commonroad::Error| Failure::input(format!("{}: {e}", args.file.display()));
    let mut scenario = map::map_scenario(&loaded.network, result, &stem, date).map_err(invalid)?;
    scenario.header.benchmark_id = map::map_scenario_id_in(&args.country, &stem).map_err(invalid)?;
    let problems = scenario.validate(None);
    if let Some(p) = problems.first() {
        return Err(Failure { message: format!("{}: converted map is invalid ({} problems), first: {p}", args.file.display(), problems.len()), status: 1 });
    }
    let write_error = |e: &dyn std::fmt::Display| Failure { message: format!("{}: {e}", args.output.display()), status: 1 };
    let (bytes, map_id) = match args.format {
        convert::OutputFormat::Xml2020a => (commonroad::xml::write_map(&scenario).map_err(|e| write_error(&e))?, None),
        convert::OutputFormat::Protobuf2024 => {
            let map = commonroad::protobuf::encode_map(&scenario).map_err(|e| write_error(&e))?;
            if args.verbose {
                for w in &map.warnings {
                    eprintln!("{w}");
                }
            }
            (map.bytes, Some(map.id))
        }
    };
    commonroad::xml::write_atomic(&args.output, &bytes).map_err(|e| Failure { message: format!("{}: {e}", args.output.display()), status: 1 })?;
    if let Some(id) = map_id {
        println!("{id}");
    }
    eprintln!(
        "{}: {} lanelets, {} warnings{} -> {}",
        args.file.display(),
        n_lanelets,
        n_warn,
        if args.verbose || n_warn == 0 { "" } else { " (-v lists them)" },
        args.output.display()
    );
    Ok(())
}
