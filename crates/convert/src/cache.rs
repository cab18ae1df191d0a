//! What conversions of one batch share: the OpenDRIVE road network of a map file with its
//! lanelet network, and the encoded 2024 map made of it. Every variation of a parameter sweep
//! names the same OpenDRIVE file; loading and converting it once instead of per variation is
//! most of a sweep's time on a large map, and the 2024 map is encoded (and hashed) once.
//!
//! A road is keyed by the file's resolved path, its length and modification time (a file
//! changed in between is read again) and the options the map conversion reads (country,
//! tolerance). At most [`Caches::capacity`] roads are kept, the least recently used dropped
//! first, so a batch over a library of maps holds only a few at a time. An encoded map is
//! reused only when the scenario's map content equals the one it was made of (a run that sets
//! light cycles or adds a placeholder lanelet changes it).

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Instant, SystemTime};

use commonroad::protobuf::{encode_map, MapFile};
use commonroad::{EnvironmentObstacle, GeoLocation, LaneletNetwork, Scenario};

use crate::options::ConvertOptions;
use crate::stages::{run_map, MapOutput};

/// Encoded maps kept per road (the unchanged network and a few run-made variants).
const MAPS_PER_ROAD: usize = 4;

/// A road network and its lanelets, read and converted once.
pub struct Road {
    pub network: opendrive::RoadNetwork,
    /// The OpenDRIVE reader's warnings.
    pub warnings: Vec<String>,
    /// The lanelet network, its tags, lights and the map converter's warnings.
    pub map: MapOutput,
    /// Wall-clock time of reading the OpenDRIVE file and of converting it, ms.
    pub load_ms: f64,
    pub map_ms: f64,
    maps: Mutex<Vec<(MapContent, Arc<MapFile>)>>,
}

/// What a 2024 map is made of.
#[derive(PartialEq)]
struct MapContent {
    country: String,
    location: GeoLocation,
    network: LaneletNetwork,
    environment: Vec<EnvironmentObstacle>,
}

impl MapContent {
    fn of(s: &Scenario) -> Self {
        MapContent {
            country: s.header.benchmark_id.parts().country.to_string(),
            location: s.location.clone(),
            network: s.network.clone(),
            environment: s.environment_obstacles.clone(),
        }
    }

    fn is_of(&self, s: &Scenario) -> bool {
        self.country == s.header.benchmark_id.parts().country
            && self.location == s.location
            && self.environment == s.environment_obstacles
            && self.network == s.network
    }
}

impl Road {
    /// The 2024 map of `scenario` (made of this road), encoded once per distinct content.
    pub fn map_file(&self, scenario: &Scenario) -> Result<Arc<MapFile>, commonroad::Error> {
        if let Some((_, file)) = lock(&self.maps).iter().find(|(c, _)| c.is_of(scenario)) {
            return Ok(file.clone());
        }
        let file = Arc::new(encode_map(scenario)?);
        let mut maps = lock(&self.maps);
        if maps.len() >= MAPS_PER_ROAD {
            maps.remove(0);
        }
        maps.push((MapContent::of(scenario), file.clone()));
        Ok(file)
    }
}

/// A lock whose holder panicked still guards consistent data here (entries are added whole).
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    match m.lock() {
        Ok(g) => g,
        Err(poisoned) => poisoned.into_inner(),
    }
}

#[derive(Clone, PartialEq)]
struct RoadKey {
    path: PathBuf,
    len: u64,
    modified: Option<SystemTime>,
    country: String,
    tolerance: Option<u64>,
}

type Slot = Arc<OnceLock<Result<Arc<Road>, String>>>;

/// The roads of a batch (shared by its workers).
pub struct Caches {
    capacity: usize,
    /// Most recently used last.
    roads: Mutex<Vec<(RoadKey, Slot)>>,
}

impl Default for Caches {
    fn default() -> Self {
        Self::with_capacity(4)
    }
}

impl Caches {
    /// A cache keeping at most `capacity` roads (at least 1).
    pub fn with_capacity(capacity: usize) -> Self {
        Caches { capacity: capacity.max(1), roads: Mutex::new(Vec::new()) }
    }

    /// Roads kept at most.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// The road of the OpenDRIVE file `path`, read and converted with `options` on first use,
    /// and whether this call did that (`true`) or found it done. `Err`: the reader's error
    /// (file, line, column), the same for every conversion asking.
    pub fn road(&self, path: &Path, options: &ConvertOptions) -> (Result<Arc<Road>, String>, bool) {
        let meta = std::fs::metadata(path).ok();
        let key = RoadKey {
            path: std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()),
            len: meta.as_ref().map_or(0, |m| m.len()),
            modified: meta.and_then(|m| m.modified().ok()),
            country: options.country.clone(),
            tolerance: options.map_tolerance.map(f64::to_bits),
        };
        let slot = {
            let mut roads = lock(&self.roads);
            let slot = match roads.iter().position(|(k, _)| *k == key) {
                Some(i) => roads.remove(i).1,
                None => Slot::default(),
            };
            roads.push((key, slot.clone()));
            if roads.len() > self.capacity {
                roads.remove(0);
            }
            slot
        };
        // a second worker asking for the same road waits for the first one's result
        let mut fresh = false;
        let road = slot
            .get_or_init(|| {
                fresh = true;
                load_road(path, options)
            })
            .clone();
        (road, fresh)
    }
}

fn load_road(path: &Path, options: &ConvertOptions) -> Result<Arc<Road>, String> {
    let ms = |t: Instant| t.elapsed().as_secs_f64() * 1e3;
    let t = Instant::now();
    let loaded = opendrive::load(path).map_err(|e| e.to_string())?;
    let load_ms = ms(t);
    let t = Instant::now();
    let map = run_map(&loaded.network, options);
    Ok(Arc::new(Road {
        // the OpenDRIVE reader's warnings have always said so
        warnings: loaded.warnings.iter().map(|w| w.labelled("warning").to_string()).collect(),
        network: loaded.network,
        map,
        load_ms,
        map_ms: ms(t),
        maps: Mutex::new(Vec::new()),
    }))
}
