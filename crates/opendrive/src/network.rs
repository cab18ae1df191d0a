//! The loaded road network: model + id indexes + spatial index, and (road, lane, s) → world.

use crate::error::Error;
use crate::model::header::Header;
use crate::model::junction::{Controller, Junction};
use crate::model::road::Road;
use crate::parse::parse_document;
use crate::road_geometry::WorldPose;
use crate::spatial_index::SpatialIndex;
use diagnostic::{Diagnostic, Location};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Files larger than this are refused (hostile input).
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// A parsed, indexed OpenDRIVE road network. Roads are addressed by index into `roads`
/// (stable for the life of the network) or by their OpenDRIVE id.
#[derive(Debug, Clone)]
pub struct RoadNetwork {
    pub file: PathBuf,
    pub header: Header,
    pub roads: Vec<Road>,
    pub junctions: Vec<Junction>,
    pub controllers: Vec<Controller>,
    road_ids: BTreeMap<String, usize>,
    junction_ids: BTreeMap<String, usize>,
    pub(crate) index: SpatialIndex,
}

/// Result of loading: the network and the warnings met on the way.
#[derive(Debug, Clone)]
pub struct Loaded {
    pub network: RoadNetwork,
    pub warnings: Vec<Diagnostic>,
}

/// Read and parse an OpenDRIVE file.
pub fn load(path: impl AsRef<Path>) -> Result<Loaded, Error> {
    let path = path.as_ref();
    let io = |source| Error::Io { path: path.to_path_buf(), source };
    let meta = std::fs::metadata(path).map_err(io)?;
    if meta.len() > MAX_FILE_BYTES {
        return Err(Error::Invalid {
            file: path.to_path_buf(),
            line: 1,
            col: 1,
            message: format!("file is {} bytes, more than the {} accepted", meta.len(), MAX_FILE_BYTES),
        });
    }
    let bytes = std::fs::read(path).map_err(io)?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let before = e.as_bytes().get(..e.utf8_error().valid_up_to()).unwrap_or(&[]);
        let line = before.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
        let col = before.iter().rev().take_while(|&&b| b != b'\n').count() as u32 + 1;
        Error::Xml { file: path.to_path_buf(), line, col, message: "the file is not valid UTF-8".into() }
    })?;
    parse_str(&text, path)
}

/// Parse OpenDRIVE text; `file` names the source in messages.
pub fn parse_str(text: &str, file: &Path) -> Result<Loaded, Error> {
    let parsed = parse_document(text, file)?;
    let road_ids = parsed.roads.iter().enumerate().map(|(i, r)| (r.id.clone(), i)).collect();
    let mut junction_ids = BTreeMap::new();
    for (i, j) in parsed.junctions.iter().enumerate() {
        junction_ids.entry(j.id.clone()).or_insert(i);
    }
    let (index, coarse) = SpatialIndex::build(&parsed.roads);
    let mut warnings = parsed.warnings;
    for r in coarse.iter().filter_map(|&i| parsed.roads.get(i)) {
        warnings.push(Diagnostic::new(
            Location::new(file, r.pos.line, r.pos.col),
            format!(
                "road `{}`: its reference line is too long or too tightly curved for the spatial index (more than {} samples per road, {} per network); sampled coarser, so finding a position near it is slower and less exact",
                r.id,
                crate::spatial_index::MAX_SAMPLES_PER_ROAD,
                crate::spatial_index::MAX_SEGMENTS
            ),
        ));
    }
    let network = RoadNetwork {
        file: file.to_path_buf(),
        header: parsed.header,
        roads: parsed.roads,
        junctions: parsed.junctions,
        controllers: parsed.controllers,
        road_ids,
        junction_ids,
        index,
    };
    warnings.extend(network.check_references());
    Ok(Loaded { network, warnings })
}

impl RoadNetwork {
    /// Index of the road with OpenDRIVE id `id`.
    pub fn road_index(&self, id: &str) -> Option<usize> {
        self.road_ids.get(id).copied()
    }
    /// The road with OpenDRIVE id `id`.
    pub fn road(&self, id: &str) -> Option<&Road> {
        self.road_index(id).and_then(|i| self.roads.get(i))
    }
    /// Index of the junction with OpenDRIVE id `id`.
    pub fn junction_index(&self, id: &str) -> Option<usize> {
        self.junction_ids.get(id).copied()
    }
    /// The junction with OpenDRIVE id `id`.
    pub fn junction(&self, id: &str) -> Option<&Junction> {
        self.junction_index(id).and_then(|i| self.junctions.get(i))
    }

    /// World pose of road coordinates (s, t) on road `road` (index); s clamped to the road.
    pub fn road_to_world(&self, road: usize, s: f64, t: f64) -> Option<WorldPose> {
        Some(self.roads.get(road)?.st_to_world(s, t))
    }

    /// World pose of a point `offset` metres (+t, i.e. to the left of the reference
    /// direction) from the centre of lane `lane_id` at `s` on road `road` (index).
    /// The heading is the reference line's; see [`crate::driving_heading`] for the lane's
    /// driving direction. `None` if the road or the lane (in the section at s) is missing.
    pub fn lane_to_world(&self, road: usize, lane_id: i32, s: f64, offset: f64) -> Option<WorldPose> {
        let r = self.roads.get(road)?;
        let s = s.clamp(0.0, r.length);
        let t = r.lane_center_t(r.section_index_at(s), lane_id, s)?;
        Some(r.st_to_world(s, t + offset))
    }

    /// [`RoadNetwork::lane_to_world`] with the road given by its OpenDRIVE id.
    pub fn lane_to_world_by_id(&self, road_id: &str, lane_id: i32, s: f64, offset: f64) -> Option<WorldPose> {
        self.lane_to_world(self.road_index(road_id)?, lane_id, s, offset)
    }

    /// Warnings for links that point nowhere (kept, not fatal: esmini also loads such maps).
    fn check_references(&self) -> Vec<Diagnostic> {
        let mut out = Vec::new();
        for r in &self.roads {
            for link in [&r.predecessor, &r.successor].into_iter().flatten() {
                let found = match link.element_type {
                    crate::model::road::ElementType::Road => self.road_index(&link.element_id).is_some(),
                    crate::model::road::ElementType::Junction => self.junction_index(&link.element_id).is_some(),
                };
                if !found {
                    out.push(Diagnostic::new(
                        Location::new(&self.file, r.pos.line, r.pos.col),
                        format!("road `{}` links to missing {:?} `{}`", r.id, link.element_type, link.element_id),
                    ));
                }
            }
        }
        out
    }
}
