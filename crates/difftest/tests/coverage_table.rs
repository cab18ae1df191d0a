//! The coverage table `COVERAGE.md` is what `difftest coverage --write` makes of the schema,
//! the engine's source, the generator and `measured.tsv`; and every element the engine acts
//! on is generated. Run with `OSC2CR_BLESS=1` to rewrite the table after a change, and review
//! the diff.

use std::path::Path;

use difftest::coverage::{markdown, read_measured, rows, schema_elements, CONTROLLER};
use difftest::measure::{generated_elements, SAMPLE_COUNT, SAMPLE_SEED};

use crate::common::maps;

fn crates() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn coverage_table_is_current_and_every_element_the_engine_acts_on_is_generated() {
    let (_, maps) = maps("coverage");
    let generated = generated_elements(SAMPLE_SEED, SAMPLE_COUNT, &maps);
    let rows = rows(&crates(), &generated);
    let missing: Vec<String> = rows.iter().filter(|r| r.engine && !r.generated).map(|r| format!("{} {}", r.category, r.element)).collect();
    assert!(missing.is_empty(), "the engine acts on these, the generator never emits them: {missing:#?}");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (runs, measured) = read_measured(&std::fs::read_to_string(dir.join("measured.tsv")).unwrap_or_default());
    let table = markdown(&rows, &runs, &measured);
    let path = dir.join("COVERAGE.md");
    if std::env::var_os("OSC2CR_BLESS").is_some() {
        std::fs::write(&path, &table).expect("write COVERAGE.md");
        return;
    }
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(written == table, "COVERAGE.md is stale: run `cargo run --release -p osc2cr-difftest -- coverage --write` (or OSC2CR_BLESS=1) and review the diff");
}

#[test]
fn the_engine_side_is_read_from_its_source() {
    let engine = difftest::coverage::engine_elements(&crates());
    let schema = schema_elements();
    // every element read from the engine is a schema element (or a driver model)
    for (category, elements) in &engine {
        for e in elements {
            if *category == "controller" {
                assert!(e.starts_with(CONTROLLER), "{e}");
            } else {
                assert!(schema.get(category).is_some_and(|s| s.contains(e)), "{category} {e} is not in the 1.3 schema");
            }
        }
    }
    let has = |c: &str, e: &str| engine.get(c).is_some_and(|s| s.contains(e));
    // the engine plainly acts on these ...
    assert!(has("action", "SpeedAction") && has("action", "FollowTrajectoryAction") && has("action", "ParameterSetAction"));
    assert!(has("condition", "ReachPositionCondition") && has("position", "RoutePosition") && has("trajectory-shape", "Nurbs"));
    assert!(has("controller", "controller:ACCController") && has("controller", "controller:ALKS_R157SM_Controller/Regulation"));
    assert!(has("controller", "controller:ALKS_R157SM_Controller/RSS") && has("controller", "controller:ALKS_R157SM_Controller/FSM"));
    // ... and only warns about these
    assert!(!has("position", "GeoPosition") && !has("condition", "RelativeAngleCondition") && !has("action", "RandomRouteAction"));
}
