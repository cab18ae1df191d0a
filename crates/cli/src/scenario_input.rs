//! Reading an OpenSCENARIO file for the commands that run or show it themselves (`simulate`,
//! `inspect`): a file that cannot be read fails with its real cause — no such file, not
//! well-formed XML, a `--param` value that does not fit its parameter — as `convert` says it
//! (`convert::preflight`), and a road network that cannot be read at the `<LogicFile>` naming it.

use std::path::Path;

use crate::Failure;

/// `openscenario::load`, failing with the cause of a failure when there is one to name.
pub(crate) fn load(path: &Path, options: &openscenario::LoadOptions) -> Result<openscenario::Loaded, Failure> {
    openscenario::load(path, options).map_err(|e| {
        let causes = convert::preflight::cause(path, &options.parameters, &[]);
        if causes.is_empty() {
            Failure::input(e.to_string())
        } else {
            Failure::input(causes.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n"))
        }
    })
}

/// The road network `scenario` names, if any, with its warnings.
pub(crate) fn road_network(scenario: &openscenario::Scenario) -> Result<Option<opendrive::Loaded>, Failure> {
    let Some(xodr) = &scenario.road_network.logic_file else { return Ok(None) };
    opendrive::load(xodr).map(Some).map_err(|e| Failure::input(convert::preflight::road_failure(scenario, xodr, &e.to_string()).to_string()))
}
