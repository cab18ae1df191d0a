//! A TeleportAction does nothing while a controller in override mode owns the entity's motion
//! (esmini's TeleportAction::Start returns when IsControllerModeOnAnyOfDomains(MODE_OVERRIDE)).
//! Found by crates/difftest (ACC in override mode); the numbers are esmini 3.6.0's run of this
//! scenario (`write_for_esmini`): Ego keeps its ACC set speed of 20 m/s on lane -1 from s = 100,
//! and the teleport to s = 600 at 1 s is not carried out.

use crate::common::*;

fn scenario(mode: &str) -> String {
    let ego = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>{}<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="false"/></ControllerAction></PrivateAction></Private>"#,
        lane_pos(100.0, -1),
        speed_action("step", "time", 0.0, 20.0)
    );
    let hop = event(
        "Hop",
        "parallel",
        &format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(600.0, -1)),
        &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)),
    );
    let text = xosc(&format!("{ego}{}", teleport("Target", 900.0, -2)), &story("Ego", &hop), &stop_at(2.0));
    let acc = format!(
        r#"<ObjectController><Controller name="ACC"><Properties><Property name="esminiController" value="ACCController"/><Property name="timeGap" value="1"/><Property name="mode" value="{mode}"/><Property name="setSpeed" value="20"/></Properties></Controller></ObjectController></ScenarioObject>"#
    );
    // the controller goes into Ego's ScenarioObject (the first one)
    text.replacen("</ScenarioObject>", &acc, 1)
}

#[test]
fn a_teleport_is_ignored_while_acc_overrides() {
    let overriding = run(&scenario("override"));
    let s = at(&overriding, "Ego", 2.0);
    // esmini: x = 140 at 2 s — 20 m/s from s = 100, no jump to 600
    assert!((s.x - 140.0).abs() < 1e-3, "{s:?}");
    assert!(overriding.warnings.iter().any(|w| w.message.contains("TeleportAction: ignored")), "{:?}", overriding.warnings);
    // additive mode leaves the motion to the storyboard: the teleport happens
    let additive = run(&scenario("additive"));
    assert!(at(&additive, "Ego", 2.0).x > 600.0);
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("acc_override_teleport.xosc"), scenario("override")).expect("write");
}
