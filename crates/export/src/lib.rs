//! `export` — the way back: a CommonRoad scenario (2018b or 2020a XML, or the 2024 protobuf
//! files) becomes an OpenSCENARIO scenario (1.3, or 1.0 for simulators that read only 1.0) and
//! an OpenDRIVE road network that an OpenSCENARIO simulator replays.
//!
//! Each obstacle is an entity of its CommonRoad type and shape (Table I read backwards,
//! [`entity`](crate::entity)) whose reference point is its box centre; a dynamic one follows
//! its trajectory exactly (a polyline vertex per state, absolute timing) and is added and
//! deleted at the times it appears and leaves; static and environment obstacles stand. Each
//! planning problem places an ego (`Ego`) at its initial state, driven by the simulator's
//! default controller or by an outside one; its goal, where OpenSCENARIO can say it, is the end
//! condition, and the problem itself travels in a property of the ego so that converting the
//! scenario forward again gives it back. Traffic-light cycles become traffic-signal controllers.
//! The map is one `.xodr` per distinct lanelet network, named by its content ([`map_file`], the
//! only module that knows how the map is made: `road_export`). Batches ([`run_batch`]) search
//! folders, export in parallel, write every file whole or not at all, and report.
//!
//! It owns the CommonRoad → OpenSCENARIO mapping; it does not read OpenSCENARIO, simulate, or
//! convert roads itself, and it prints nothing (warnings are returned as data).
//!
//! ```no_run
//! use std::path::Path;
//! let source = export::read_source(Path::new("USA_US101-4_1_T-1.xml"))?;
//! let exported = export::export(&source, "", &export::ExportOptions::default())?;
//! std::fs::write("USA_US101-4_1_T-1.xosc", &exported.xosc)?;
//! if let Some(map) = &exported.map {
//!     std::fs::write(&map.file_name, &map.xodr)?; // the name the scenario refers to
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod actions;
mod batch;
mod carrier;
mod ego;
mod entity;
mod exported;
mod goal;
mod lights;
mod map_file;
mod obstacles;
mod options;
mod report;
mod scenario;
mod source;
mod traj_filter;
mod trajectory;
mod xml;

pub use batch::{discover, export_file, run_batch, BatchOptions, Found};
pub use carrier::PLANNING_PROBLEM_PROPERTY;
pub use entity::{ID_PROPERTY, TYPE_PROPERTY};
pub use exported::{export, export_with, ExportError, Exported};
pub use map_file::{map_file, MapCache, MapFile, MapResult};
pub use options::{EgoController, ExportOptions, OscVersion};
pub use report::{summarise, BatchTotals, Failure, MapReport, Report, Skipped, Stage, Status, SummaryRow};
pub use scenario::{document, Document, Facts};
pub use source::{is_input, read_source, scenario_name, Source};
