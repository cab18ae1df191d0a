//! `osc2cr`: the command-line front end. It parses arguments, calls the library crates and maps
//! their results to files, messages and exit codes. No conversion logic lives here.
//!
//! Exit status: 0 success, 1 some files of a batch failed, 2 bad usage or bad input.

mod commands;
mod failure;
mod grouped;
mod osi_file;
mod scenario_input;
mod serve_extra;
mod shared_options;

use clap::{Parser, Subcommand};
use commands::{check, convert, export, inspect, map, render, serve, simulate};
use std::process::ExitCode;

/// Convert OpenSCENARIO scenarios (with their OpenDRIVE maps) into CommonRoad scenarios.
#[derive(Parser)]
#[command(name = "osc2cr", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Convert OpenSCENARIO scenarios (files, folders, parameter distributions) into
    /// CommonRoad scenarios: lanelet network, obstacles, the ego's planning problem. 2020a XML by
    /// default; --format 2024 for parameter sweeps (one shared map file per lanelet network).
    /// Large batches stream in flat memory; --resume continues an interrupted one.
    Convert(Box<convert::ConvertArgs>),
    /// Convert an OpenDRIVE road network (.xodr) into a CommonRoad lanelet network (.xml).
    Map(map::MapArgs),
    /// The way back: CommonRoad scenarios (2018b/2020a XML, 2024 protobuf) as OpenSCENARIO
    /// (1.3, or 1.0) and OpenDRIVE, for OpenSCENARIO simulators to replay.
    #[command(long_about = export::ABOUT)]
    Export(Box<export::ExportArgs>),
    /// Load an OpenSCENARIO file and show what it resolves to: entities, storyboard,
    /// parameters, warnings.
    Inspect(inspect::InspectArgs),
    /// Run a scenario with the engine and write its trace as CSV: one row per entity and engine
    /// step with its position, heading, speed, bounding box and lane (the columns are in
    /// --trace's help).
    Simulate(simulate::SimulateArgs),
    /// Draw a scenario (.xml, or .xosc converted first) as PNG/SVG stills, an animated GIF or a
    /// sheet of stills at the storyboard events: road users labelled, the events marked.
    Render(render::RenderArgs),
    /// Report what is wrong with OpenSCENARIO files without converting them: every finding with
    /// severity and file:line:col (exit 2 when there is an error).
    Check(check::CheckArgs),
    /// Run a scenario whose UDPDriverController entities are driven over UDP by esmini clients
    /// (--udp), then write the run as CommonRoad.
    #[command(long_about = serve::ABOUT)]
    Serve(Box<serve::ServeArgs>),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Convert(args) => convert::run(args),
        Command::Map(args) => map::run(args),
        Command::Export(args) => export::run(args),
        Command::Inspect(args) => inspect::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Render(args) => render::run(args),
        Command::Check(args) => check::run(args),
        Command::Serve(args) => serve::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.status)
        }
    }
}
