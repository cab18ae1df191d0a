//! Reading an OpenSCENARIO file for the commands that run or show it themselves (`simulate`,
//! `inspect`): a file that cannot be read fails with its real cause — no such file, not
//! well-formed XML, a `--param` value that does not fit its parameter — as `convert` says it
//! (`convert::preflight`), and a road network that cannot be read at the `<LogicFile>` naming it.

use std::path::Path;

use crate::failure::Failure;

/// `openscenario::load`, failing with the cause of a failure when there is one to name (a
/// `--param` value that does not fit is one even where the reader reads past it, as esmini
/// would, to a problem of the attribute that uses it).
pub(crate) fn load(path: &Path, options: &openscenario::LoadOptions) -> Result<openscenario::Loaded, Failure> {
    let causes = convert::preflight::cause(path, &options.parameters, &[]);
    if !causes.is_empty() {
        return Err(Failure::input(causes.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n")));
    }
    openscenario::load(path, options).map_err(|e| Failure::input(e.to_string()))
}

/// The road network `scenario` names, if any, with its warnings.
pub(crate) fn road_network(scenario: &openscenario::Scenario) -> Result<Option<opendrive::Loaded>, Failure> {
    let Some(xodr) = &scenario.road_network.logic_file else { return Ok(None) };
    opendrive::load(xodr).map(Some).map_err(|e| Failure::input(convert::preflight::road_failure(scenario, xodr, &e.to_string()).to_string()))
}
