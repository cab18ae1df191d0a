//! `road_export` — a CommonRoad lanelet network as an OpenDRIVE 1.8 road network (it knows
//! nothing of OpenSCENARIO).
//!
//! Free road ends and joints whose points lie on no straight line are first sliced on straight
//! lines (`free_ends`, `joints`), and a lanelet beside a shorter neighbour is cut where the
//! neighbour starts or ends (`cuts`). Lanelets side by side that share their bounds become the lanes of one lane
//! section (`groups`); each section gets a reference line along its middle, perpendicular to its
//! first and last cross-section (`reference`, `section`), and every lane border is written as
//! cubic offsets from it, fitted to the lanelet bounds within [`Options::tolerance`]
//! (`offsets`; widths and the lane offset are differences of fitted borders). Sections become
//! roads (`roads`); successors and predecessors become lane links, road links and junctions
//! (`topology`): a CommonRoad intersection's lanelets become the connecting roads of a
//! default junction, other forks and merges direct junctions. Lanelet types become lane and
//! road types (`lane_kind`), line markings road marks (`marks`), traffic signs, lights and
//! stop lines signals whose ids are the CommonRoad ids (`signals`). What OpenDRIVE cannot say
//! is a [`Warning`] naming the element. [`round_trip`] compares a network with the one a
//! reader makes of the export.
//!
//! ```
//! use commonroad::{IdAllocator, Lanelet, LaneletBounds, LaneletNetwork, LaneletType, Point};
//!
//! let mut ids = IdAllocator::new();
//! let bounds = LaneletBounds::new(
//!     vec![Point::new(0.0, 3.5), Point::new(100.0, 3.5)],
//!     vec![Point::new(0.0, 0.0), Point::new(100.0, 0.0)],
//! )?;
//! let mut network = LaneletNetwork::default();
//! network.lanelets.push(Lanelet::new(ids.lanelet(), bounds, LaneletType::Urban));
//!
//! let options = road_export::Options { name: "straight".into(), ..Default::default() };
//! let export = road_export::export(&network, &options)?;
//! assert!(export.xodr.contains("<road "));
//! assert!(export.warnings.is_empty());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod cuts;
mod free_ends;
mod groups;
mod joints;
mod lane_kind;
mod lanelets;
mod marks;
mod model;
mod offsets;
mod reference;
mod roads;
pub mod round_trip;
mod section;
mod signals;
mod topology;
mod vec2;
mod warning;
mod write;

pub use warning::{Error, Subject, Warning};

use commonroad::LaneletNetwork;

/// Largest distance (m) between a written lane border and its lanelet bound when the
/// options name none.
pub const DEFAULT_TOLERANCE: f64 = 0.01;
/// Most lanelets exported (hostile input).
pub const MAX_LANELETS: usize = 1_000_000;
/// Most points of one bound (hostile input).
pub const MAX_BOUND_POINTS: usize = 1_000_000;

/// What the export writes besides the roads.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Options {
    /// The header's `name`.
    pub name: String,
    /// The header's `geoReference` (a PROJ string), if any.
    pub geo_reference: Option<String>,
    /// Country of the map (ISO 3166 alpha-3 as in a benchmark id, or alpha-2) for signs
    /// whose number is not German.
    pub country: Option<String>,
    /// Largest distance (m) between a lane border and its lanelet bound; `None` =
    /// [`DEFAULT_TOLERANCE`].
    pub tolerance: Option<f64>,
}

/// The exported road network.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadExport {
    /// The OpenDRIVE 1.8 document.
    pub xodr: String,
    /// What OpenDRIVE could not say, or what was approximated, each naming its element.
    pub warnings: Vec<Warning>,
}

/// Exports a lanelet network.
pub fn export(network: &LaneletNetwork, options: &Options) -> Result<RoadExport, Error> {
    if network.lanelets.len() > MAX_LANELETS {
        return Err(Error::TooLarge { what: "the number of lanelets", got: network.lanelets.len(), max: MAX_LANELETS });
    }
    if let Some(most) = network.lanelets.iter().map(|l| l.bounds.len()).max().filter(|&n| n > MAX_BOUND_POINTS) {
        return Err(Error::TooLarge { what: "the number of points of a bound", got: most, max: MAX_BOUND_POINTS });
    }
    let tol = options.tolerance.filter(|t| t.is_finite() && *t > 0.0).unwrap_or(DEFAULT_TOLERANCE).max(1e-4);
    // bowed free ends and zig-zag joints are sliced first: the cuts then follow the slices
    // into neighbours
    let mut cut: Option<cuts::Cut> = None;
    let stages: [fn(&LaneletNetwork) -> Option<cuts::Cut>; 3] = [free_ends::slice, joints::slice, cuts::cut];
    for stage in stages {
        if let Some(next) = stage(cut.as_ref().map_or(network, |c| &c.network)) {
            cut = Some(match cut {
                None => next,
                Some(prev) => prev.then(next),
            });
        }
    }
    let network = cut.as_ref().map_or(network, |c| &c.network);
    let mut warnings = cut.as_ref().map(|c| c.warnings.clone()).unwrap_or_default();
    let prep = lanelets::prepare_all(network, &mut warnings);
    let groups = groups::group(network, &prep, &mut warnings);
    let mut doc = model::Document { name: options.name.clone(), geo_reference: options.geo_reference.clone(), ..Default::default() };
    let mut placed: Vec<Option<roads::Placed>> = vec![None; network.lanelets.len()];
    for g in groups {
        let id = doc.roads.len() as u64 + 1;
        let Some(built) = roads::build_road(id, vec![g], network, &prep, tol, &mut warnings) else { continue };
        let r = doc.roads.len();
        for (si, g) in built.groups.iter().enumerate() {
            for (k, m) in g.members.iter().enumerate() {
                if let Some(p) = placed.get_mut(m.idx) {
                    *p = Some(roads::Placed { road: r, section: si, lane: roads::lane_id(k, g.centre), along: !m.flipped });
                }
            }
        }
        doc.roads.push(built.road);
    }
    let rename = |w: Vec<Warning>| match &cut {
        Some(c) => c.rename(w),
        None => w,
    };
    if doc.roads.is_empty() {
        return Err(Error::NoRoads(rename(warnings)));
    }
    let first_junction = doc.roads.len() as u64 + 1;
    doc.junctions = topology::link(network, &mut doc.roads, &placed, first_junction, &mut warnings);
    let lines: Vec<reference::RefLine> = doc.roads.iter().map(|r| reference::RefLine::of(r.geometries.clone())).collect();
    let mut next_id = network.max_id().max(first_junction + doc.junctions.len() as u64) + 1;
    let places = signals::Places { net: network, placed: &placed, lines: &lines, roads: &doc.roads, country: options.country.clone() };
    let mut roads_out = doc.roads.clone();
    signals::add_signals(&places, &mut roads_out, &mut next_id, &mut warnings);
    doc.roads = roads_out;
    Ok(RoadExport { xodr: write::write(&doc), warnings: rename(warnings) })
}
