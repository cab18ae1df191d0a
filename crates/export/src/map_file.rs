//! The map of a scenario: the one place that calls the road network converter
//! (`road_export::export`, the map half of issue 24), and names the OpenDRIVE file
//! by its content — `<COUNTRY>_<first 64 bits of the SHA-256 of its bytes, hex>.xodr`, as the
//! 2024 maps are named — so that every scenario on the same lanelet network refers to one file,
//! and different networks never share a name. Everything else of the export is independent of
//! how the map is built: entities are placed by world positions.
//!
//! A batch converts each distinct network once ([`MapCache`], keyed by a hash of the network's
//! full description and the geo reference).

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use commonroad::Scenario;
use sha2::{Digest, Sha256};

/// Hex digits of the content hash in a map's name.
const NAME_HEX_DIGITS: usize = 16;

/// An OpenDRIVE file, named by its content.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MapFile {
    /// `<COUNTRY>_<hash>.xodr`.
    pub file_name: String,
    pub xodr: String,
    /// What the OpenDRIVE file does not say of the lanelet network.
    pub warnings: Vec<String>,
}

/// The map of `scenario`'s lanelet network, or why there is none (`Ok(None)`: the network has no
/// lanelet, so there is nothing to write).
pub fn map_file(scenario: &Scenario) -> Result<Option<MapFile>, String> {
    if scenario.network.lanelets.is_empty() {
        return Ok(None);
    }
    let country = scenario.header.benchmark_id.parts().country.to_string();
    let options = road_export::Options {
        // the name is left empty so that the bytes, and so the file's name, depend only on the network
        name: String::new(),
        geo_reference: scenario.location.geo_transformation.as_ref().map(|g| g.geo_reference.clone()).filter(|g| !g.trim().is_empty()),
        // signs whose number is not German are read as this country's
        country: Some(country.clone()),
        tolerance: None,
    };
    let out = road_export::export(&scenario.network, &options).map_err(|e| format!("map: {e}"))?;
    let digest = Sha256::digest(out.xodr.as_bytes());
    let hash: String = digest.iter().map(|b| format!("{b:02x}")).collect::<String>()[..NAME_HEX_DIGITS].to_string();
    Ok(Some(MapFile { file_name: format!("{country}_{hash}.xodr"), xodr: out.xodr, warnings: out.warnings.iter().map(ToString::to_string).collect() }))
}

/// A map as a scenario gets it: the file (shared), none, or why not.
pub type MapResult = Result<Option<Arc<MapFile>>, String>;

/// The maps of a batch, each network converted once.
#[derive(Default)]
pub struct MapCache {
    maps: Mutex<HashMap<[u8; 32], MapResult>>,
}

impl MapCache {
    pub fn new() -> Self {
        Self::default()
    }

    /// The map of `scenario`, converted if this network was not seen before.
    pub fn get(&self, scenario: &Scenario) -> MapResult {
        let key = key(scenario);
        if let Some(m) = self.maps.lock().ok().and_then(|m| m.get(&key).cloned()) {
            return m;
        }
        // converted outside the lock: two threads may convert the same network (the same bytes)
        let made = map_file(scenario).map(|m| m.map(Arc::new));
        match self.maps.lock() {
            Ok(mut m) => m.entry(key).or_insert(made).clone(),
            Err(_) => made,
        }
    }
}

/// A hash of everything the map is made of: the lanelet network, the geo reference and the
/// country (Debug output is deterministic and shows every value, floats exactly).
fn key(scenario: &Scenario) -> [u8; 32] {
    let mut h = Sha256::new();
    h.update(format!("{:?}", scenario.network).as_bytes());
    h.update(format!("{:?}", scenario.location.geo_transformation).as_bytes());
    h.update(scenario.header.benchmark_id.parts().country.as_bytes());
    h.finalize().into()
}
