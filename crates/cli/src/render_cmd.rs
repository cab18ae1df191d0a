//! `osc2cr render`: a CommonRoad file (or an OpenSCENARIO file, converted first) drawn as PNG
//! or SVG stills or an animated GIF.

use std::path::{Path, PathBuf};

use crate::Failure;

#[derive(clap::Args)]
pub struct RenderArgs {
    /// The scenario: CommonRoad XML (.xml) or OpenSCENARIO (.xosc, converted with defaults).
    pub file: PathBuf,
    /// The picture: .png or .svg (a still) or .gif (an animation of the whole scenario).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Time of a still, s (repeatable: several stills are written as OUT_t<T>.png).
    #[arg(long = "time", value_name = "T")]
    pub times: Vec<f64>,
    /// Picture width in pixels; the height follows from the content.
    #[arg(long, default_value_t = 1200)]
    pub width: u32,
    /// Id of the dynamic obstacle to highlight as the ego (default: the one starting at the
    /// planning problem's initial state).
    #[arg(long)]
    pub ego: Option<u64>,
    /// Print the reader's and converter's warnings on stderr.
    #[arg(short, long)]
    pub verbose: bool,
}

#[derive(Clone, Copy, PartialEq)]
enum Format {
    Png,
    Svg,
    Gif,
}

fn format_of(path: &Path) -> Option<Format> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "png" => Some(Format::Png),
        "svg" => Some(Format::Svg),
        "gif" => Some(Format::Gif),
        _ => None,
    }
}

/// `OUT_t5.5.png` for the still at 5.5 s of several.
pub fn still_path(output: &Path, time: f64) -> PathBuf {
    let stem = output.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = output.extension().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let mut t = format!("{time:.3}");
    while t.ends_with('0') && !t.ends_with(".0") {
        t.pop();
    }
    output.with_file_name(format!("{stem}_t{t}.{ext}"))
}

/// The scenario from a CommonRoad file, or from an OpenSCENARIO file converted with defaults.
fn load(path: &Path, verbose: bool) -> Result<commonroad::xml::ReadScenario, Failure> {
    let is_xosc = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xosc"));
    let read = if is_xosc {
        let name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        let request = convert::Request {
            path,
            name: &name,
            config: 1,
            parameters: &[],
            source: String::new(),
        };
        let conversion = convert::convert_scenario(&request, &convert::ConvertOptions::default());
        if verbose {
            for w in &conversion.warnings {
                eprintln!("{}: warning: {}", path.display(), w.message);
            }
        }
        let bytes = conversion
            .result
            .map_err(|f| Failure::input(format!("{}: conversion failed: {}", path.display(), f.message)))?;
        let text = String::from_utf8(bytes)
            .map_err(|e| Failure { message: format!("{}: converted file is not UTF-8: {e}", path.display()), status: 1 })?;
        commonroad::xml::read_scenario_str(&text, path)
    } else {
        commonroad::xml::read_scenario_file(path)
    };
    let read = read.map_err(|e| Failure::input(e.to_string()))?;
    if verbose {
        for w in &read.warnings {
            eprintln!("{w}");
        }
    }
    Ok(read)
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    commonroad::xml::write_atomic(path, bytes).map_err(|e| Failure { message: e.to_string(), status: 1 })
}

pub fn run(args: &RenderArgs) -> Result<(), Failure> {
    let format = format_of(&args.output).ok_or_else(|| {
        Failure::input(format!("{}: the output must end in .png, .svg or .gif", args.output.display()))
    })?;
    if format == Format::Gif && !args.times.is_empty() {
        return Err(Failure::input("--time selects stills; a .gif shows the whole scenario"));
    }
    let read = load(&args.file, args.verbose)?;
    let problems = (!read.problems.problems.is_empty()).then_some(&read.problems);
    let options = render::RenderOptions { width: args.width, ego: args.ego, ..Default::default() };
    let fail = |e: render::RenderError| Failure::input(format!("{}: {e}", args.file.display()));
    let mut written = Vec::new();
    match format {
        Format::Gif => {
            let bytes = render::render_gif(&read.scenario, problems, &options).map_err(fail)?;
            write(&args.output, &bytes)?;
            written.push(args.output.clone());
        }
        Format::Png | Format::Svg => {
            let times = if args.times.is_empty() { vec![0.0] } else { args.times.clone() };
            for &time in &times {
                let path = if times.len() == 1 { args.output.clone() } else { still_path(&args.output, time) };
                let o = render::RenderOptions { time, ..options.clone() };
                let bytes = match format {
                    Format::Png => render::render_png(&read.scenario, problems, &o).map_err(fail)?,
                    _ => render::render_svg(&read.scenario, problems, &o).map_err(fail)?.into_bytes(),
                };
                write(&path, &bytes)?;
                written.push(path);
            }
        }
    }
    for p in &written {
        eprintln!("{} -> {}", args.file.display(), p.display());
    }
    Ok(())
}
