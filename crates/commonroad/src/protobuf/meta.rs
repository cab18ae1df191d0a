//! Meta information: the benchmark id as a `ScenarioID`, the file information, the time step —
//! written alike into the scenario and the dynamic file, as commonroad-io's writer does.

use super::error::finite;
use super::messages::commonroad_common as pb;
use crate::header::{Date, Header};
use crate::Error;

/// commonroad-io 2026.1 accepts only its XML versions as `scenario_version` (it asserts
/// `scenario_version in {"2018b", "2020a"}` when it builds the id), and writes "2020a".
const SCENARIO_VERSION: &str = "2020a";

/// A date as commonroad-io's `TimeStamp` (hour and minute left out: the model has a day).
pub(super) fn time_stamp(date: Option<&Date>) -> pb::TimeStamp {
    match date {
        Some(d) => {
            pb::TimeStamp { year: Some(u32::from(d.year())), month: Some(u32::from(d.month())), day: Some(u32::from(d.day())), hour: None, minute: None }
        }
        None => pb::TimeStamp::default(),
    }
}

pub(super) fn file_information(date: Option<&Date>, author: &str, affiliation: &str, source: &str) -> pb::FileInformation {
    pb::FileInformation {
        license_name: String::new(),
        license_text: None,
        date: time_stamp(date),
        author: author.to_string(),
        affiliation: affiliation.to_string(),
        source: source.to_string(),
    }
}

/// The header's benchmark id, date, author, affiliation, source and time step. Warnings for
/// what the `ScenarioID` message cannot hold (it has one prediction id and needs a
/// configuration id).
pub(super) fn scenario_meta(header: &Header, warnings: &mut Vec<String>) -> Result<pb::ScenarioMetaInformation, Error> {
    let id = &header.benchmark_id;
    let parts = id.parts();
    let configuration_id = parts.configuration_id.unwrap_or_else(|| {
        warnings.push(format!("benchmark id {id} has no configuration id; the 2024 ScenarioID needs one: 1 is written"));
        1
    });
    let (obstacle_behavior, prediction_id) = match &parts.prediction {
        Some((behaviour, ids)) => {
            if ids.len() > 1 {
                warnings.push(format!("benchmark id {id} has {} prediction ids; the 2024 ScenarioID holds one: the first is written", ids.len()));
            }
            (Some(behaviour.to_string()), ids.first().copied())
        }
        None => (None, None),
    };
    Ok(pb::ScenarioMetaInformation {
        benchmark_id: pb::ScenarioId {
            cooperative: parts.cooperative,
            map_id: pb::MapId { country_id: parts.country.to_string(), map_name: parts.map_name.to_string(), map_id: parts.map_id },
            configuration_id,
            obstacle_behavior,
            prediction_id,
            scenario_version: SCENARIO_VERSION.to_string(),
        },
        file_information: file_information(Some(&header.date), &header.author, &header.affiliation, &header.source),
        time_step_size: finite(|| "timeStepSize".to_string(), header.time_step_size)?,
    })
}
