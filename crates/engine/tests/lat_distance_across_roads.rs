//! LateralDistanceAction between entities on different roads: esmini measures the distance
//! through its road-path delta, which osc2cr does not reproduce; the run says so with a
//! positioned warning instead of diverging silently. Fixture: `fixtures/opposite_roads.xodr`.

mod common;
use common::*;

fn run_lateral(reference_road: u32, reference_s: f64) -> engine::Run {
    let init = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="{reference_road}" laneId="-1" offset="0" s="{reference_s}"/></Position></TeleportAction></PrivateAction></Private><Private entityRef="Target"><PrivateAction><TeleportAction><Position><LanePosition roadId="0" laneId="-1" offset="0" s="50"/></Position></TeleportAction></PrivateAction>{}</Private>"#,
        speed_action("step", "time", 0.0, 5.0)
    );
    let action = r#"<PrivateAction><LateralAction><LateralDistanceAction entityRef="Ego" distance="1" freespace="false" continuous="false" coordinateSystem="road" displacement="leftToReferencedEntity"/></LateralAction></PrivateAction>"#;
    let stories = story("Target", &event("L", "overwrite", action, &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))));
    let stop = format!("<ConditionGroup>{}</ConditionGroup>", sim_time(2.0, "greaterThan", "none", 0.0));
    let text = xosc(&init, &stories, &stop).replace("straight.xodr", "opposite_roads.xodr");
    let path = fixtures().join("test.xosc");
    let loaded = openscenario::load_str(&path, &text, &Default::default()).expect("test scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("not a scenario") };
    let net = opendrive::load(fixtures().join("opposite_roads.xodr")).expect("fixture road loads").network;
    engine::simulate(&scenario, Some(&net), &engine::Settings { step: 0.01, max_time: 5.0 }).expect("simulate")
}

fn cross_road_warnings(run: &engine::Run) -> Vec<&engine::Warning> {
    run.warnings.iter().filter(|w| w.message.contains("LateralDistanceAction") && w.message.contains("different roads")).collect()
}

#[test]
fn a_reference_on_another_road_is_a_positioned_warning() {
    let run = run_lateral(1, 100.0);
    let w = cross_road_warnings(&run);
    assert_eq!(w.len(), 1, "{:?}", run.warnings);
    assert!(w[0].line > 0 && w[0].col > 0, "{}", w[0]);
}

#[test]
fn a_reference_on_the_same_road_is_measured_without_warning() {
    // Reference on road 0 too: t of the actor becomes the reference's t + 1 (lane -1's centre
    // is t = −1.5, so y = −0.5) and nothing is approximated.
    let run = run_lateral(0, 100.0);
    assert!(cross_road_warnings(&run).is_empty(), "{:?}", run.warnings);
    assert!(close(at(&run, "Target", 1.5).y, -0.5, 1e-9), "{:?}", at(&run, "Target", 1.5));
}
