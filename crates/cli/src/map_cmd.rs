//! `osc2cr map`: an OpenDRIVE file in, a CommonRoad lanelet network out.

use crate::Failure;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct MapArgs {
    /// The OpenDRIVE file (.xodr).
    pub file: PathBuf,
    /// Where to write the CommonRoad XML.
    #[arg(short, long)]
    pub output: PathBuf,
}

pub fn run(args: &MapArgs) -> Result<(), Failure> {
    Err(Failure::input(format!("{}: map is not implemented yet", args.file.display())))
}
