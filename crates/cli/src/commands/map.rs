//! `osc2cr map`: an OpenDRIVE file in, a CommonRoad lanelet network out (written atomically).

use crate::Failure;
use std::path::PathBuf;

#[derive(clap::Args)]
pub(crate) struct MapArgs {
    /// The OpenDRIVE file (.xodr).
    pub file: PathBuf,
    /// Where to write the CommonRoad XML.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Country of signals that name none (e.g. DE, SE); default Germany.
    #[arg(long)]
    pub country: Option<String>,
    /// Largest distance (m) between a lanelet bound and the exact lane border.
    #[arg(long, default_value_t = 0.005)]
    pub tolerance: f64,
    /// The scenario date written into the file (YYYY-MM-DD); fixed so output is reproducible.
    #[arg(long, default_value = "2026-01-01")]
    pub date: String,
    /// Print the conversion warnings on stderr.
    #[arg(short, long)]
    pub verbose: bool,
    /// CommonRoad format: 2020a (XML) or 2024 (the protobuf map file commonroad-io 2026's
    /// three-file reader takes; its map id is printed).
    #[arg(long, default_value = "2020a", value_name = "2020a|2024")]
    pub format: convert::OutputFormat,
}

fn parse_date(s: &str) -> Option<commonroad::Date> {
    let mut it = s.trim().splitn(3, '-');
    let y = it.next()?.parse().ok()?;
    let m = it.next()?.parse().ok()?;
    let d = it.next()?.parse().ok()?;
    commonroad::Date::new(y, m, d).ok()
}

pub(crate) fn run(args: &MapArgs) -> Result<(), Failure> {
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        return Err(Failure::input(format!("--tolerance {} must be a positive number of metres", args.tolerance)));
    }
    let date = parse_date(&args.date).ok_or_else(|| Failure::input(format!("--date `{}` is not a date YYYY-MM-DD", args.date)))?;
    let loaded = opendrive::load(&args.file).map_err(|e| Failure::input(e.to_string()))?;
    let opts = map::MapOptions { tolerance: args.tolerance, default_country: args.country.clone(), ..Default::default() };
    let result = map::convert(&loaded.network, &opts);
    let n_warn = loaded.warnings.len() + result.warnings.len();
    if args.verbose {
        for w in loaded.warnings.iter().chain(&result.warnings) {
            eprintln!("{}", w.labelled("warning"));
        }
    }
    let stem = args.file.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let n_lanelets = result.network.lanelets.len();
    let scenario = map::map_scenario(&loaded.network, result, &stem, date).map_err(|e| Failure::input(format!("{}: {e}", args.file.display())))?;
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
