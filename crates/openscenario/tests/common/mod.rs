//! Locating the shared corpus.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// `../shared` (or $OSC2CR_SHARED). None (with a notice) when absent, unless CI is set.
pub(crate) fn shared() -> Option<PathBuf> {
    testkit::shared_dir()
}

/// Every `.xosc` under `dir`, sorted.
pub(crate) fn xosc_files(dir: &Path) -> Vec<PathBuf> {
    testkit::files_with_ext(dir, "xosc")
}

/// Path relative to the corpus root, with '/' separators.
pub(crate) fn rel(corpus: &Path, p: &Path) -> String {
    p.strip_prefix(corpus).unwrap_or(p).to_string_lossy().replace('\\', "/")
}

/// A fresh directory under the system temp dir for one test, removed when the test passes.
pub(crate) fn temp_dir(name: &str) -> testkit::ScratchDir {
    testkit::ScratchDir::new(&format!("openscenario-{name}"))
}

/// 1-based (line, column) of the first occurrence of `needle` in `text`.
pub(crate) fn pos_of(text: &str, needle: &str) -> (u32, u32) {
    let at = text.find(needle).unwrap_or_else(|| panic!("'{needle}' not in text"));
    let before = &text[..at];
    let line = before.matches('\n').count() as u32 + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) as u32 + 1;
    (line, col)
}

pub(crate) use testkit::VEHICLE;

/// A minimal scenario with the given parts.
pub(crate) fn scenario(params: &str, catalogs: &str, entities: &str, init: &str, stories: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="0" date="2020-01-01T00:00:00" description="test" author="test"/>
  <ParameterDeclarations>
    {params}
  </ParameterDeclarations>
  <CatalogLocations>{catalogs}</CatalogLocations>
  <RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
  <Entities>
    {entities}
  </Entities>
  <Storyboard>
    <Init><Actions>
      {init}
    </Actions></Init>
    {stories}
  </Storyboard>
</OpenSCENARIO>
"#
    )
}

/// An entity named `name` with the inline test vehicle.
pub(crate) fn car(name: &str) -> String {
    format!(r#"<ScenarioObject name="{name}">{VEHICLE}</ScenarioObject>"#)
}

/// A Private init block teleporting `entity` to a world position with the given x attribute text.
pub(crate) fn teleport(entity: &str, x: &str) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><WorldPosition x="{x}" y="0"/></Position></TeleportAction></PrivateAction></Private>"#
    )
}
