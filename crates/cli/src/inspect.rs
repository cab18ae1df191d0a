//! `osc2cr inspect`: show what an OpenSCENARIO file resolves to.

use crate::Failure;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct InspectArgs {
    /// The OpenSCENARIO file (.xosc).
    pub file: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &InspectArgs) -> Result<(), Failure> {
    Err(Failure::input(format!("{}: inspect is not implemented yet", args.file.display())))
}
