//! A map-only CommonRoad scenario (what `osc2cr map` writes): the converted network, the
//! tags it implies, a `ZAM_<name>-1` benchmark id, and the OpenDRIVE geo reference.

use crate::options::MapResult;
use crate::tags::derived_tags;
use commonroad::{BenchmarkId, Date, GeoTransformation, Header, Scenario};
use opendrive::RoadNetwork;

/// `ZAM_<name>-1` from a file stem (letters and digits only; `Map` if none are left).
pub fn map_scenario_id(stem: &str) -> Result<BenchmarkId, commonroad::Error> {
    map_scenario_id_in("ZAM", stem)
}

/// `<country>_<name>-1`: [`map_scenario_id`] with another country code.
pub fn map_scenario_id_in(country: &str, stem: &str) -> Result<BenchmarkId, commonroad::Error> {
    let mut name: String = stem.chars().filter(char::is_ascii_alphanumeric).collect();
    if name.is_empty() {
        name = "Map".into();
    }
    BenchmarkId::parse(&format!("{country}_{name}-1"))
}

/// The scenario of a converted map. `date` is given (never "today") so output is reproducible.
pub fn map_scenario(net: &RoadNetwork, map: MapResult, name: &str, date: Date) -> Result<Scenario, commonroad::Error> {
    let header = Header {
        benchmark_id: map_scenario_id(name)?,
        date,
        author: "osc2cr".into(),
        affiliation: String::new(),
        source: format!("OpenDRIVE conversion of {}", net.file.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default()),
        time_step_size: 0.1,
    };
    let mut s = Scenario::new(header);
    s.tags = derived_tags(&map.network);
    if let Some(geo) = net.header.geo_reference.as_deref().filter(|g| !g.is_empty()) {
        s.location.geo_transformation = Some(GeoTransformation::proj(geo));
    }
    s.network = map.network;
    Ok(s)
}
