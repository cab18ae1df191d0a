//! What the road_export tests share: the maps of the acceptance (every lanelet network of
//! `../shared/commonroad-scenarios` and of osc2cr's own conversions of `../shared/corpus`,
//! converted in-process), their exports written once under `target/road_export_tests`, and
//! osc2cr's map conversion to read an export back.
#![allow(dead_code)]

use commonroad::LaneletNetwork;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// A lanelet network to export and where it came from.
pub(crate) struct Map {
    pub name: String,
    pub network: LaneletNetwork,
}

/// The lanelet networks of the CommonRoad scenarios (files without lanelets left out).
pub(crate) fn scenario_maps(shared: &Path) -> Vec<Map> {
    let mut out = Vec::new();
    for f in testkit::files_with_ext(&shared.join("commonroad-scenarios"), "xml") {
        let read = commonroad::xml::read_scenario_file(&f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        if read.scenario.network.lanelets.is_empty() {
            continue;
        }
        let rel = f.strip_prefix(shared).unwrap_or(&f).to_string_lossy().replace('/', "_");
        out.push(Map { name: rel.trim_end_matches(".xml").to_string(), network: read.scenario.network });
    }
    out
}

/// The distinct lanelet networks of osc2cr's conversions of the corpus scenarios.
pub(crate) fn corpus_maps(shared: &Path) -> Vec<Map> {
    let corpus = shared.join("corpus");
    let options = convert::ConvertOptions::default();
    let mut out: Vec<Map> = Vec::new();
    for f in testkit::files_with_ext(&corpus, "xosc") {
        let name = f.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        let request = convert::Request::named(&f, &name).keeping_model();
        let (_conversion, model) = convert::convert(&request, &options);
        let Some(model) = model else { continue };
        let network = model.scenario.network;
        if network.lanelets.is_empty() || out.iter().any(|m| m.network.lanelets == network.lanelets) {
            continue;
        }
        let rel = f.strip_prefix(&corpus).unwrap_or(&f).to_string_lossy().replace('/', "_");
        out.push(Map { name: format!("corpus_{}", rel.trim_end_matches(".xosc")), network });
    }
    out
}

/// One exported map: its name, network, the OpenDRIVE text, the file it was written to.
pub(crate) struct Exported {
    pub name: String,
    pub network: LaneletNetwork,
    pub export: road_export::RoadExport,
    pub file: PathBuf,
}

static EXPORTS: OnceLock<Option<Vec<Exported>>> = OnceLock::new();

/// Where the tests write their files.
pub(crate) fn out_dir() -> PathBuf {
    testkit::workspace_root().join("target/road_export_tests")
}

/// Every acceptance map exported (once per test process), or `None` (with a notice) when
/// the shared directory is missing.
pub(crate) fn exports() -> Option<&'static [Exported]> {
    EXPORTS
        .get_or_init(|| {
            let shared = testkit::shared_dir()?;
            let dir = out_dir().join("xodr");
            std::fs::create_dir_all(&dir).expect("creates the output folder");
            let mut maps = scenario_maps(&shared);
            maps.extend(corpus_maps(&shared));
            assert!(maps.len() > 50, "only {} maps found under {}", maps.len(), shared.display());
            let mut out = Vec::new();
            for m in maps {
                let options = road_export::Options { name: m.name.clone(), ..Default::default() };
                let export = road_export::export(&m.network, &options).unwrap_or_else(|e| panic!("{}: {e}", m.name));
                let file = dir.join(format!("{}.xodr", m.name));
                std::fs::write(&file, &export.xodr).expect("writes the export");
                out.push(Exported { name: m.name, network: m.network, export, file });
            }
            Some(out)
        })
        .as_deref()
}

/// osc2cr's map conversion of OpenDRIVE text (what `osc2cr map` does with the file).
pub(crate) fn read_back(xodr: &str) -> LaneletNetwork {
    let loaded = opendrive::parse_str(xodr, Path::new("export.xodr")).unwrap_or_else(|e| panic!("the export does not read back: {e}"));
    map::convert(&loaded.network, &map::MapOptions::default()).network
}

/// The OpenSCENARIO file of the load check: one car teleported onto lane `lane` of road
/// `road` at `s`, stopped after 0.1 s.
pub(crate) fn load_check_scenario(xodr: &Path, road: &str, lane: i32, s: f64) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2026-01-01T00:00:00" description="load check" author="osc2cr"/>
  <ParameterDeclarations/>
  <CatalogLocations/>
  <RoadNetwork><LogicFile filepath="{}"/></RoadNetwork>
  <Entities>
    <ScenarioObject name="Car">
      {vehicle}
    </ScenarioObject>
  </Entities>
  <Storyboard>
    <Init><Actions><Private entityRef="Car"><PrivateAction><TeleportAction><Position>
      <LanePosition roadId="{road}" laneId="{lane}" s="{s}" offset="0"/>
    </Position></TeleportAction></PrivateAction></Private></Actions></Init>
    <StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none">
      <ByValueCondition><SimulationTimeCondition value="0.1" rule="greaterThan"/></ByValueCondition>
    </Condition></ConditionGroup></StopTrigger>
  </Storyboard>
</OpenSCENARIO>
"#,
        xodr.display(),
        vehicle = testkit::VEHICLE
    )
}

/// Whether esmini 3.6.0 (`esmini`) loads `xodr`: the load check on the first lane of the
/// first road runs in `dir`, exits 0, places the car and logs no error.
pub(crate) fn esmini_loads(esmini: &Path, xodr: &Path, dir: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(xodr).map_err(|e| e.to_string())?;
    let net = opendrive::parse_str(&text, xodr).map_err(|e| format!("osc2cr cannot read it: {e}"))?.network;
    let road = net.roads.first().ok_or("no road")?;
    let lane = road.lane_sections.first().and_then(|s| s.right.first().or(s.left.first())).map_or(-1, |l| l.id);
    let file = dir.join(format!("{}.xosc", xodr.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default()));
    std::fs::write(&file, load_check_scenario(xodr, &road.id, lane, 0.5 * road.length)).map_err(|e| e.to_string())?;
    let out = std::process::Command::new(esmini)
        .args(["--headless", "--fixed_timestep", "0.05", "--disable_log", "--osc"])
        .arg(&file)
        .current_dir(dir)
        .output()
        .map_err(|e| format!("esmini does not run: {e}"))?;
    let log = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    let errors: Vec<&str> = log.lines().filter(|l| l.contains("[error]")).collect();
    if out.status.success() && errors.is_empty() && log.contains("Car New position") {
        Ok(())
    } else {
        Err(format!("exit {:?}; {}", out.status.code(), errors.join(" | ")))
    }
}
