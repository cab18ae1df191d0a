//! esmini 3.6.0 loads every export: a scenario with one car teleported onto the first lane
//! of the first road runs for 0.1 s, exits 0 and logs no error.

use crate::common::{exports, out_dir};
use std::path::Path;
use std::process::Command;

fn scenario(xodr: &Path, road: &str, lane: i32, s: f64) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2026-01-01T00:00:00" description="load check" author="osc2cr"/>
  <ParameterDeclarations/>
  <CatalogLocations/>
  <RoadNetwork><LogicFile filepath="{}"/></RoadNetwork>
  <Entities>
    <ScenarioObject name="Car">
      <Vehicle name="car" vehicleCategory="car">
        <BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="1.8" length="4.5" height="1.5"/></BoundingBox>
        <Performance maxSpeed="50" maxAcceleration="5" maxDeceleration="10"/>
        <Axles>
          <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/>
          <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/>
        </Axles>
        <Properties/>
      </Vehicle>
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
        xodr.display()
    )
}

#[test]
fn esmini_loads_every_export() {
    let Some(exports) = exports() else { return };
    let Some(shared) = testkit::shared_dir() else { return };
    let esmini = shared.join("tools/esmini/bin/esmini-3.6.0");
    if Command::new(&esmini).arg("--help").output().is_err() {
        assert!(std::env::var_os("CI").is_none(), "esmini cannot run: {}", esmini.display());
        eprintln!("notice: esmini cannot run here; test skipped");
        return;
    }
    let dir = out_dir().join("esmini");
    std::fs::create_dir_all(&dir).expect("creates the folder");
    let mut failures = Vec::new();
    for e in exports {
        let net = opendrive::parse_str(&e.export.xodr, &e.file).expect("reads").network;
        let road = net.roads.first().expect("a road");
        let sec = road.lane_sections.first().expect("a section");
        let lane = sec.right.first().or(sec.left.first()).map_or(-1, |l| l.id);
        let file = dir.join(format!("{}.xosc", e.name));
        std::fs::write(&file, scenario(&e.file, &road.id, lane, 0.5 * road.length)).expect("writes");
        let out = Command::new(&esmini)
            .args(["--headless", "--fixed_timestep", "0.05", "--disable_log", "--osc"])
            .arg(&file)
            .current_dir(&dir)
            .output()
            .expect("runs esmini");
        let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
        let errors: Vec<&str> = text.lines().filter(|l| l.contains("[error]")).collect();
        if !out.status.success() || !errors.is_empty() || !text.contains("Car New position") {
            failures.push(format!("{}: exit {:?}, {}", e.name, out.status.code(), errors.join(" | ")));
        }
    }
    eprintln!("esmini loads {} of {} exports", exports.len() - failures.len(), exports.len());
    assert!(failures.is_empty(), "esmini does not load:\n{}", failures.join("\n"));
}
