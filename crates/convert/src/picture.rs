//! The picture beside a converted scenario (`osc2cr convert --render`): the scenario at its
//! first time step as a PNG with the output's name, its road users labelled with their
//! entities' names, drawn from the model the conversion just
//! serialised (no second read of the XML), written whole or not at all.

use std::path::{Path, PathBuf};

use crate::pipeline::Model;

/// The picture's path: the scenario file's with the extension `png`.
pub fn picture_path(scenario_file: &Path) -> PathBuf {
    scenario_file.with_extension("png")
}

/// Draws `model` and writes it beside `scenario_file`; the error says what failed (drawing or
/// writing) — for the report's warnings, never a failed conversion.
pub fn write_picture(scenario_file: &Path, model: &Model) -> Result<PathBuf, String> {
    let options = render::RenderOptions {
        names: model.names.iter().cloned().collect(),
        marks: model.events.iter().map(|(time, text)| render::Mark { time: *time, text: text.clone() }).collect(),
        ..Default::default()
    };
    let png = render::render_png(&model.scenario, Some(&model.problems), &options).map_err(|e| format!("picture not drawn: {e}"))?;
    let path = picture_path(scenario_file);
    commonroad::xml::write_atomic(&path, &png).map_err(|e| format!("picture not written: {e}"))?;
    Ok(path)
}
