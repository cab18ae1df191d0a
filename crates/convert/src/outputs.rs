//! The files of one conversion of a batch: where they go, writing them (each whole or not at
//! all), and whether an earlier run already wrote them all (`--resume`).
//!
//! 2020a: `<name>.xml`. 2024: the dynamic file `<name>.pb`, then the scenario file
//! `<name>-SC.pb` — written last, so that its presence means the conversion's files are all
//! there — and the map `<map id>.pb` at the top of the output folder, written once per batch
//! (its name is its content: a map file that exists is the map).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use commonroad::protobuf::{dynamic_file_name, map_id_of_scenario, scenario_file_name, MapFile};
use commonroad::xml::write_atomic;

use crate::options::OutputFormat;
use crate::picture::picture_path;
use crate::pipeline::Output;

/// The paths of one conversion's files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OutputPaths {
    /// The XML file (2020a) or the scenario file (2024).
    pub main: PathBuf,
    /// The dynamic file (2024).
    pub dynamic: Option<PathBuf>,
    /// The picture (`--render`).
    pub picture: Option<PathBuf>,
}

impl OutputPaths {
    /// The files of the output named `stem` (output folder joined with the name, no extension).
    pub fn of(stem: &Path, format: OutputFormat, render: bool) -> Self {
        let name = |s: String| stem.with_file_name(s);
        let file = stem.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let (main, dynamic) = match format {
            OutputFormat::Xml2020a => (name(format!("{file}.xml")), None),
            OutputFormat::Protobuf2024 => (name(scenario_file_name(&file)), Some(name(dynamic_file_name(&file)))),
        };
        // the picture takes the name of the file that holds the obstacles
        let picture = render.then(|| picture_path(dynamic.as_ref().unwrap_or(&main)));
        OutputPaths { main, dynamic, picture }
    }
}

/// Maps written (or found) by this batch, by file name, so each is written once.
pub struct MapFiles {
    dir: PathBuf,
    known: Mutex<BTreeMap<String, Result<PathBuf, String>>>,
}

impl MapFiles {
    /// Maps go to the top of the output folder `dir`.
    pub fn new(dir: &Path) -> Self {
        MapFiles { dir: dir.to_path_buf(), known: Mutex::new(BTreeMap::new()) }
    }

    /// The map's file, written if it is not there yet. A file of that name with other bytes is
    /// an error (not overwritten): the name is the hash of the content, so it is someone else's
    /// file, or a hash collision.
    pub(crate) fn ensure(&self, map: &MapFile) -> Result<PathBuf, String> {
        let mut known = match self.known.lock() {
            Ok(g) => g,
            Err(poisoned) => poisoned.into_inner(),
        };
        let name = map.file_name();
        if let Some(r) = known.get(&name) {
            return r.clone();
        }
        let path = self.dir.join(&name);
        let result = match std::fs::read(&path) {
            Ok(existing) if existing == map.bytes => Ok(path),
            Ok(_) => Err(format!("{} exists with other content than the map of that name: not overwritten", path.display())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => write_atomic(&path, &map.bytes).map(|()| path).map_err(|e| e.to_string()),
            Err(e) => Err(format!("cannot read {}: {e}", path.display())),
        };
        known.insert(name, result.clone());
        result
    }
}

/// The files written for one conversion.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Written {
    pub main: Option<PathBuf>,
    pub dynamic: Option<PathBuf>,
    pub map: Option<PathBuf>,
}

fn create_parent(path: &Path) -> Result<(), String> {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => std::fs::create_dir_all(dir).map_err(|e| format!("cannot create folder {}: {e}", dir.display())),
        _ => Ok(()),
    }
}

/// Writes a conversion's output files.
pub fn write_output(paths: &OutputPaths, output: &Output, maps: &MapFiles) -> Result<Written, String> {
    create_parent(&paths.main)?;
    match output {
        Output::Xml(bytes) => {
            write_atomic(&paths.main, bytes).map_err(|e| e.to_string())?;
            Ok(Written { main: Some(paths.main.clone()), ..Default::default() })
        }
        Output::Protobuf(files) => {
            let map = maps.ensure(&files.map)?;
            let dynamic = paths.dynamic.clone().ok_or("a 2024 output needs a dynamic file name")?;
            write_atomic(&dynamic, &files.dynamic).map_err(|e| e.to_string())?;
            write_atomic(&paths.main, &files.scenario).map_err(|e| e.to_string())?;
            Ok(Written { main: Some(paths.main.clone()), dynamic: Some(dynamic), map: Some(map) })
        }
    }
}

/// The files an earlier run wrote for this conversion, if it wrote them all (a file written by
/// `write_atomic` is whole when it exists).
pub(crate) fn complete(paths: &OutputPaths, maps_dir: &Path) -> Option<Written> {
    if !paths.main.is_file() || paths.picture.as_ref().is_some_and(|p| !p.is_file()) {
        return None;
    }
    let Some(dynamic) = &paths.dynamic else {
        return Some(Written { main: Some(paths.main.clone()), ..Default::default() });
    };
    if !dynamic.is_file() {
        return None;
    }
    let map_id = map_id_of_scenario(&std::fs::read(&paths.main).ok()?)?;
    let map = maps_dir.join(format!("{map_id}.pb"));
    map.is_file().then(|| Written { main: Some(paths.main.clone()), dynamic: Some(dynamic.clone()), map: Some(map) })
}
