//! Every entity of the run becomes an obstacle — the implicit trailers of a catalog vehicle
//! included. The engine names an inline trailer after its tow vehicle plus `+` (esmini's rule:
//! `Truck+`, `Truck++`); each such entity must reach the CommonRoad file as a truck with its own
//! trajectory and a unique id. Checked on the corpus scenarios whose vehicles carry trailers.

use std::collections::BTreeSet;

use commonroad::DynamicObstacleType;
use convert::{convert, ConvertOptions, Request};

const SCENARIOS: &[&str] = &["trailers", "truck_with_rotating_axle", "lane_change", "parking_lot", "cut-in_cr"];

#[test]
fn implicit_trailers_become_truck_obstacles() {
    let Some(shared) = testkit::shared_dir() else { return };
    for name in SCENARIOS {
        let path = shared.join(format!("corpus/esmini/xosc/{name}.xosc"));
        let (scenario, _) = openscenario::load_scenario(&path, &Default::default()).expect("corpus scenario loads");
        let road = scenario.road_network.logic_file.as_ref().map(|f| opendrive::load(f).expect("map loads").network);
        let run = engine::simulate(&scenario, road.as_ref(), &engine::Settings::default()).expect("runs");
        let trailers: Vec<&str> = run.trace.entities.iter().map(|e| e.name.as_str()).filter(|n| n.ends_with('+')).collect();
        assert!(!trailers.is_empty(), "{name}: the corpus scenario is expected to have an implicit trailer");
        let road_users = run.trace.entities.iter().filter(|e| !run.trace.ghosts.contains(&e.name)).count();

        let (conversion, model) = convert(&Request::named(&path, name).keeping_model(), &ConvertOptions::default());
        conversion.result.as_ref().unwrap_or_else(|f| panic!("{name}: {f:?}"));
        assert!(
            !conversion.warnings.iter().any(|w| w.message.contains("not declared in the scenario")),
            "{name}: an entity of the trace was left out: {:?}",
            conversion.warnings
        );
        let model = model.expect("kept");
        let s = &model.scenario;
        let obstacles = s.dynamic_obstacles.len() + s.static_obstacles.len();
        assert_eq!(obstacles, road_users, "{name}: one obstacle per road user of the run");
        let ids: BTreeSet<_> = s.dynamic_obstacles.iter().map(|o| o.id).chain(s.static_obstacles.iter().map(|o| o.id)).collect();
        assert_eq!(ids.len(), obstacles, "{name}: obstacle ids are unique");
        let trucks = s.dynamic_obstacles.iter().filter(|o| o.obstacle_type == DynamicObstacleType::Truck).count();
        assert!(trucks >= trailers.len(), "{name}: {} trailers {trailers:?} but {trucks} truck obstacles", trailers.len());
    }
}
