//! The maps scenarios run on: four written by the tool itself (so it works without the corpus:
//! a straight road, a curved road, a four-way crossing with signals and a T junction under
//! left-hand traffic) and, when asked, every OpenDRIVE file of a folder (esmini's own maps in
//! `../shared/corpus`: junctions, a roundabout, crests, banked and left-hand-traffic roads).
//! Each map is loaded once and analysed (`lanes::spots`); the generator computes every place
//! from the loaded network.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use opendrive::{HeaderOffset, RoadNetwork, TrafficRule};

use super::lanes::{spots, Spot};
use super::map_text;

/// A map: its file name as scenarios refer to it, where it is, the network and where entities
/// may start.
#[derive(Debug, Clone)]
pub struct MapChoice {
    /// The `LogicFile` path scenarios give (a file name beside the scenario for the built-in
    /// maps, an absolute path for a folder's).
    pub name: String,
    pub path: PathBuf,
    /// The map's feature label: `builtin-straight`, `builtin-curve`, `builtin-crossing`,
    /// `builtin-tee` or `folder`.
    pub label: String,
    pub net: Arc<RoadNetwork>,
    pub spots: Vec<Spot>,
    /// The map's traffic lights a scenario may switch, each with its lamp count.
    pub signals: Vec<MapSignal>,
    /// Some road drives on the left.
    pub left_hand: bool,
}

/// A traffic light of the map: its signal id and how many lamps it has.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct MapSignal {
    pub id: String,
    pub lamps: usize,
}

impl MapSignal {
    /// The states a scenario may set: one lamp on, the others off, for each lamp.
    pub fn states(&self) -> Vec<String> {
        (0..self.lamps).map(|on| self.one_on(on)).collect()
    }

    /// The state of phase `phase` (0 stop, 1 ready, 2 go) of the generator's signal controller:
    /// the top lamp for stop, the bottom one for go, the middle one (or the top) for ready.
    pub fn phase_state(&self, phase: usize) -> String {
        let on = match phase {
            0 => 0,
            1 if self.lamps >= 3 => 1,
            1 => 0,
            _ => self.lamps.saturating_sub(1),
        };
        self.one_on(on)
    }

    fn one_on(&self, on: usize) -> String {
        (0..self.lamps).map(|i| if i == on { "on" } else { "off" }).collect::<Vec<_>>().join(";")
    }
}

impl MapChoice {
    fn new(name: String, path: PathBuf, label: &str, net: RoadNetwork) -> Option<Self> {
        let spots = spots(&net);
        if !spots.iter().any(|s| !s.sidewalk) {
            return None;
        }
        // esmini switches only the traffic lights it knows, and wants a state of as many lamp
        // modes as the light has lamps (TrafficLight::CheckValidLampModes)
        let signals: BTreeSet<MapSignal> = net
            .roads
            .iter()
            .flat_map(|r| r.signals.iter())
            .filter_map(|s| Some(MapSignal { id: s.id.clone(), lamps: opendrive::traffic_light_lamps(s)? }))
            .collect();
        let left_hand = net.roads.iter().any(|r| r.rule == TrafficRule::LeftHand);
        Some(MapChoice { name, path, label: label.to_string(), net: Arc::new(net), spots, signals: signals.into_iter().collect(), left_hand })
    }

    /// The driving spots (no sidewalks).
    pub fn driving_spots(&self) -> impl Iterator<Item = &Spot> {
        self.spots.iter().filter(|s| !s.sidewalk)
    }

    /// The header offset esmini applies to a WorldPosition of a scenario on this map.
    pub fn offset(&self) -> Option<&HeaderOffset> {
        self.net.header.offset.as_ref()
    }

    /// Scenario world coordinates (x, y, h) of the map point (x, y) heading `h`: esmini
    /// moves a WorldPosition by the header offset and turns it by its heading
    /// (ScenarioReader::parseOSCPosition), so the scenario gives the point moved back.
    pub fn scenario_xyh(&self, x: f64, y: f64, h: f64) -> (f64, f64, f64) {
        match self.offset() {
            None => (x, y, h),
            Some(o) => {
                let (sin, cos) = (-o.hdg).sin_cos();
                (x * cos - y * sin - o.x, x * sin + y * cos - o.y, h - o.hdg)
            }
        }
    }
}

/// The built-in maps, written into `dir`.
pub fn builtin(dir: &Path) -> std::io::Result<Vec<MapChoice>> {
    let mut out = Vec::new();
    for (name, text) in [("straight", map_text::straight()), ("curve", map_text::curve()), ("crossing", map_text::crossing()), ("tee", map_text::tee())] {
        let path = dir.join(format!("{name}.xodr"));
        std::fs::write(&path, &text)?;
        let net = opendrive::parse_str(&text, &path).map_err(|e| std::io::Error::other(format!("built-in map {name}: {e}")))?.network;
        let label = format!("builtin-{name}");
        let map = MapChoice::new(format!("{name}.xodr"), path, &label, net).ok_or_else(|| std::io::Error::other(format!("built-in map {name} has no spot")))?;
        out.push(map);
    }
    Ok(out)
}

/// The OpenDRIVE files of a folder and its subfolders, in path order, each content once (the
/// corpus holds copies of some maps), that load and have a driving spot; at most `max_maps`.
pub fn from_folder(dir: &Path, max_maps: usize) -> Vec<MapChoice> {
    let files = crate::files_with_ext(dir, "xodr");
    let mut seen = BTreeSet::new();
    let mut out = Vec::new();
    for path in files {
        if out.len() >= max_maps {
            break;
        }
        let Ok(bytes) = std::fs::read(&path) else { continue };
        if !seen.insert(bytes) {
            continue;
        }
        let Ok(loaded) = opendrive::network::load(&path) else { continue };
        let path = std::fs::canonicalize(&path).unwrap_or(path);
        let name = path.to_string_lossy().to_string();
        if let Some(m) = MapChoice::new(name, path, "folder", loaded.network) {
            out.push(m);
        }
    }
    out
}
