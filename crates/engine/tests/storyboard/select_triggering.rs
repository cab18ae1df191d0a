//! `selectTriggeringEntities="true"`: the maneuver group's actors are its listed actors plus
//! the entities that made its Act's start trigger true. Ego drives at 10 m/s, Target stands;
//! the Act starts at 1 s when "speed > 5" holds for one of [Target, Ego] — only Ego. The
//! group's speed action (step to 20 m/s) then applies to the actors only.

use crate::common::*;
use engine::Run;

fn init() -> String {
    format!("{}{}{}", teleport("Ego", 100.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0), teleport("Target", 50.0, -2))
}

fn act_trigger() -> String {
    let speed = r#"<Condition name="v" delay="0" conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Target"/><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><SpeedCondition value="5" rule="greaterThan"/></EntityCondition></ByEntityCondition></Condition>"#;
    trigger(&format!("{}{speed}", sim_time(1.0, "greaterOrEqual", "none", 0.0)))
}

/// One act started by `act_start`, one group with Actors `actors` (select = true).
fn scenario(actors: &str, act_start: &str) -> Run {
    let speed_up = event("SpeedUp", "parallel", &speed_action("step", "time", 0.0, 20.0), "");
    let stories = format!(
        r#"<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="true">{actors}</Actors><Maneuver name="M">{speed_up}</Maneuver></ManeuverGroup>{act_start}</Act></Story>"#
    );
    run(&xosc(&init(), &stories, &stop_at(3.0)))
}

#[test]
fn the_entity_that_made_the_act_start_acts() {
    // No listed actor: only Ego, which made the trigger true, speeds up (at 1.00 s: the row
    // at 1.01 s has 20 m/s); Target stays at 0.
    let r = scenario("", &act_trigger());
    assert!(close(at(&r, "Ego", 1.0).speed, 10.0, 1e-12));
    assert!(close(at(&r, "Ego", 1.01).speed, 20.0, 1e-12));
    assert!(close(at(&r, "Target", 2.0).speed, 0.0, 1e-12));
    // Ego moves 10 m/s · 0.01 s in each of the frames 1..=100 and 20 m/s · 0.01 s in each of
    // the frames 101..=200 (the one that sets the speed included): 100 + 10 + 20 = 130 m.
    assert!(close(at(&r, "Ego", 2.0).x, 130.0, 1e-9), "{:?}", at(&r, "Ego", 2.0));
    assert!(r.warnings.iter().all(|w| !w.message.contains("selectTriggeringEntities")), "{:?}", r.warnings);
}

#[test]
fn listed_actors_act_too() {
    let r = scenario(r#"<EntityRef entityRef="Target"/>"#, &act_trigger());
    assert!(close(at(&r, "Ego", 1.01).speed, 20.0, 1e-12));
    assert!(close(at(&r, "Target", 1.01).speed, 20.0, 1e-12));
}

#[test]
fn without_entity_conditions_only_the_listed_actors_act() {
    // The Act starts on time alone: no triggering entities, so only the listed Target acts
    // (what esmini, which ignores the attribute, does as well).
    let r = scenario(r#"<EntityRef entityRef="Target"/>"#, &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)));
    assert!(close(at(&r, "Target", 1.01).speed, 20.0, 1e-12));
    assert!(close(at(&r, "Ego", 2.0).speed, 10.0, 1e-12));
}
