//! `osc2cr render`: a CommonRoad file (or an OpenSCENARIO file, converted first) drawn as PNG
//! or SVG stills, an animated GIF, or a sheet of stills at the storyboard events' times. An
//! OpenSCENARIO file's entity names label the road users and its run's events are marked.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::failure::Failure;
use crate::shared_options::RunArgs;

#[derive(clap::Args)]
pub(crate) struct RenderArgs {
    /// The scenario: CommonRoad XML (.xml) or OpenSCENARIO (.xosc, converted with defaults).
    pub file: PathBuf,
    /// The picture: .png or .svg (a still) or .gif (an animation of the whole scenario, each
    /// storyboard Event highlighted from the frame it starts in).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Time of a still, s (repeatable: several stills are written as OUT_t<T>.png).
    #[arg(long = "time", value_name = "T", allow_negative_numbers = true)]
    pub times: Vec<f64>,
    /// Picture width in pixels; the height follows from the content.
    #[arg(long, default_value_t = 1200, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u32>)]
    pub width: u32,
    /// Id of the dynamic obstacle to highlight as the ego (default: the one starting at the
    /// planning problem's initial state).
    #[arg(long, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u64>)]
    pub ego: Option<u64>,
    /// Keep this road user in the centre (a window 100 m wide): its OpenSCENARIO name or its
    /// CommonRoad obstacle id. By default a still shows where the road users are at its time,
    /// and an animation where they are over the run, or a camera that pans and zooms with them
    /// when that shows them larger.
    #[arg(long, value_name = "NAME", conflicts_with_all = ["region", "whole_map"])]
    pub follow: Option<String>,
    /// Show this world rectangle (metres, the map's coordinates), widened to an aspect
    /// between 1:4 and 2:1.
    #[arg(long, value_name = "X0,Y0,X1,Y1", allow_hyphen_values = true, conflicts_with = "whole_map")]
    pub region: Option<String>,
    /// Show the whole map (every lanelet, obstacle and goal region) instead of where the road
    /// users are.
    #[arg(long)]
    pub whole_map: bool,
    /// One PNG with a panel per storyboard event time (the start, each time an Event starts,
    /// the end), each framed at its time: the scenario's story at a glance.
    #[arg(long, conflicts_with = "times")]
    pub sheet: bool,
    /// Seconds of past positions drawn behind each road user (0: none).
    #[arg(long, default_value_t = 3.0, value_name = "S", allow_negative_numbers = true)]
    pub trail: f64,
    /// Also write where each road user and its label are on the still, in pixels, as JSON
    /// (one still only).
    #[arg(long, value_name = "FILE.json")]
    pub layout: Option<PathBuf>,
    /// How an OpenSCENARIO file is run before it is drawn (ignored for a CommonRoad file).
    #[command(flatten)]
    pub run: RunArgs,
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
pub(crate) fn still_path(output: &Path, time: f64) -> PathBuf {
    let stem = output.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = output.extension().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let mut t = format!("{time:.3}");
    while t.ends_with('0') && !t.ends_with(".0") {
        t.pop();
    }
    output.with_file_name(format!("{stem}_t{t}.{ext}"))
}

/// What a picture is drawn from: the CommonRoad scenario and, from an OpenSCENARIO file, the
/// entity names of the obstacles and the storyboard events of the run.
struct Input {
    scenario: commonroad::Scenario,
    problems: commonroad::PlanningProblemSet,
    names: BTreeMap<u64, String>,
    marks: Vec<render::Mark>,
}

/// The scenario from a CommonRoad file, or from an OpenSCENARIO file converted with `run`'s
/// options (the other options of `convert` at their defaults).
fn load(path: &Path, run: &RunArgs, verbose: bool) -> Result<Input, Failure> {
    if !path.exists() {
        return Err(Failure::input(format!("{}: no such file", path.display())));
    }
    let is_xosc = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xosc"));
    if is_xosc {
        let request = convert::Request::named(path, &convert::batch_name(path)).keeping_model();
        let options = run.convert_options();
        options.check().map_err(Failure::input)?;
        let (conversion, model) = convert::convert(&request, &options);
        if verbose {
            for w in &conversion.warnings {
                eprintln!("{}: warning: {}", path.display(), w.message);
            }
        }
        conversion
            .result
            .map_err(|f| Failure::input(format!("{} cannot be drawn: {} stage: {}", path.display(), super::convert::stage_name(f.stage), f.message)))?;
        let model = model.ok_or_else(|| Failure { message: format!("{}: the conversion kept no model", path.display()), status: 1 })?;
        return Ok(Input {
            scenario: model.scenario,
            problems: model.problems,
            names: model.names.into_iter().collect(),
            marks: model.events.into_iter().map(|(time, text)| render::Mark { time, text }).collect(),
        });
    }
    let read = commonroad::xml::read_scenario_file(path).map_err(|e| Failure::input(e.to_string()))?;
    if verbose {
        for w in &read.warnings {
            eprintln!("{}", w.labelled("warning"));
        }
    }
    Ok(Input { scenario: read.scenario, problems: read.problems, names: BTreeMap::new(), marks: Vec::new() })
}

/// Writes a picture (or its layout) whole, making its folder if it is not there yet.
fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    let failed = |message: String| Failure { message, status: 1 };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| failed(format!("cannot create folder {}: {e}", dir.display())))?;
    }
    commonroad::xml::write_atomic(path, bytes).map_err(|e| failed(e.to_string()))
}

/// `X0,Y0,X1,Y1` as four numbers.
fn parse_region(text: &str) -> Result<[f64; 4], Failure> {
    let bad = || Failure::input(format!("--region {text}: expected X0,Y0,X1,Y1 (four numbers, metres)"));
    let v: Vec<f64> = text.split(',').map(|p| p.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|_| bad())?;
    <[f64; 4]>::try_from(v).map_err(|_| bad())
}

/// The obstacle `--follow` names: an entity name (its first obstacle), else an obstacle id.
fn follow_id(text: &str, input: &Input) -> Result<u64, Failure> {
    if let Some((id, _)) = input.names.iter().find(|(_, n)| n.as_str() == text) {
        return Ok(*id);
    }
    if let Ok(id) = text.parse::<u64>() {
        return Ok(id);
    }
    let known: Vec<&str> = input.names.values().map(String::as_str).collect();
    Err(Failure::input(format!(
        "--follow {text}: no road user of this name or id{}",
        if known.is_empty() { String::new() } else { format!(" (names: {})", known.join(", ")) }
    )))
}

fn frame(args: &RenderArgs, input: &Input) -> Result<render::Frame, Failure> {
    Ok(if let Some(f) = &args.follow {
        render::Frame::Follow(follow_id(f, input)?)
    } else if let Some(r) = &args.region {
        render::Frame::Region(parse_region(r)?)
    } else if args.whole_map {
        render::Frame::WholeMap
    } else {
        render::Frame::Action
    })
}

/// The layout of a still as JSON: picture and map area, scale, each road user's box, centre,
/// length and label, in pixels.
fn layout_json(l: &render::Layout) -> serde_json::Value {
    let rect = |r: &render::PxRect| serde_json::json!([r.x0, r.y0, r.x1, r.y1]);
    serde_json::json!({
        "width": l.width,
        "height": l.height,
        "map": rect(&l.map),
        "world": [l.world.min_x, l.world.min_y, l.world.max_x, l.world.max_y],
        "pixels_per_metre": l.scale,
        "obstacles": l.obstacles.iter().map(|o| serde_json::json!({
            "id": o.id,
            "name": o.name,
            "ego": o.ego,
            "type": o.obstacle_type,
            "length_px": o.length_px,
            "box": rect(&o.bbox),
            "center": [o.center.0, o.center.1],
            "label": o.label.as_ref().map(|lb| serde_json::json!({"text": lb.text, "box": rect(&lb.rect)})),
        })).collect::<Vec<_>>(),
    })
}

pub(crate) fn run(args: &RenderArgs) -> Result<(), Failure> {
    let format = format_of(&args.output).ok_or_else(|| Failure::input(format!("{}: the output must end in .png, .svg or .gif", args.output.display())))?;
    if format == Format::Gif && !args.times.is_empty() {
        return Err(Failure::input("--time selects stills; a .gif shows the whole scenario"));
    }
    if args.sheet && format != Format::Png {
        return Err(Failure::input("--sheet writes one PNG: the output must end in .png"));
    }
    if args.layout.is_some() && (format == Format::Gif || args.sheet || args.times.len() > 1) {
        return Err(Failure::input("--layout describes one still: give at most one --time and a .png or .svg output"));
    }
    let input = load(&args.file, &args.run, args.verbose)?;
    let problems = (!input.problems.problems.is_empty()).then_some(&input.problems);
    let options = render::RenderOptions {
        width: args.width,
        ego: args.ego,
        frame: frame(args, &input)?,
        names: input.names.clone(),
        marks: input.marks.clone(),
        trail: args.trail,
        ..Default::default()
    };
    let scenario = &input.scenario;
    let fail = |e: render::Error| Failure::input(format!("{}: {e}", args.file.display()));
    let mut written = Vec::new();
    match format {
        Format::Gif => {
            let bytes = render::render_gif(scenario, problems, &options).map_err(fail)?;
            write(&args.output, &bytes)?;
            written.push(args.output.clone());
        }
        Format::Png if args.sheet => {
            let bytes = render::render_sheet_png(scenario, problems, &options).map_err(fail)?;
            write(&args.output, &bytes)?;
            written.push(args.output.clone());
        }
        Format::Png | Format::Svg => {
            let times = if args.times.is_empty() { vec![0.0] } else { args.times.clone() };
            for &time in &times {
                let path = if times.len() == 1 { args.output.clone() } else { still_path(&args.output, time) };
                let o = render::RenderOptions { time, ..options.clone() };
                let bytes = match format {
                    Format::Png => render::render_png(scenario, problems, &o).map_err(fail)?,
                    _ => render::render_svg(scenario, problems, &o).map_err(fail)?.into_bytes(),
                };
                write(&path, &bytes)?;
                written.push(path);
                if let Some(l) = &args.layout {
                    let layout = render::render_layout(scenario, problems, &o).map_err(fail)?;
                    let text = serde_json::to_string_pretty(&layout_json(&layout)).map_err(|e| Failure { message: e.to_string(), status: 1 })?;
                    write(l, text.as_bytes())?;
                    written.push(l.clone());
                }
            }
        }
    }
    for p in &written {
        eprintln!("{} -> {}", args.file.display(), p.display());
    }
    Ok(())
}
