//! SpeedAction rules of esmini's LongSpeedAction::Start / Step, on the straight fixture road
//! (see `common`): a relative target reads the reference's speed every step, continuous or not,
//! and every step stays within the vehicle's acceleration limits.

use crate::common::*;

fn relative_speed(entity: &str, shape: &str, dim: &str, value: f64, continuous: bool) -> String {
    format!(
        r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="{shape}" dynamicsDimension="{dim}" value="{value}"/><SpeedActionTarget><RelativeTargetSpeed entityRef="{entity}" value="0" speedTargetValueType="delta" continuous="{continuous}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#
    )
}

/// Two maneuver groups started at once by the act: Target's event at t > `t_target`, then
/// Ego's at t > `t_ego`.
fn two_groups(target_action: &str, t_target: f64, ego_action: &str, t_ego: f64) -> String {
    let group = |name: &str, actor: &str, action: &str, t: f64| {
        format!(
            r#"<ManeuverGroup maximumExecutionCount="1" name="{name}"><Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}M">{}</Maneuver></ManeuverGroup>"#,
            event(&format!("{name}E"), "overwrite", action, &trigger(&sim_time(t, "greaterThan", "none", 0.0)))
        )
    };
    format!(
        r#"<Story name="S"><Act name="A">{}{}{}</Act></Story>"#,
        group("T", "Target", target_action, t_target),
        group("G", "Ego", ego_action, t_ego),
        trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))
    )
}

#[test]
fn a_non_continuous_relative_target_follows_the_reference_until_reached() {
    // Target drives 10 m/s and from t = 1.01 accelerates at 2 m/s² to 20 m/s. Ego, at rest,
    // starts a non-continuous relative target (delta 0) at 5 m/s² at the same time. On the
    // rate scale the shape is v = 5 m/s² · τ; the target moves with the Target's speed
    // 10 + 2τ, so they meet at τ = 10/3 s (16.67 m/s), not at τ = 2 s (10 m/s, the speed at
    // the start). Hand-worked on the 0.01 s grid: Ego reaches at step 334 or 333 (whichever
    // order the two actions take), at the Target's speed then, 16.66..16.68 m/s.
    // One Private element per entity: esmini refuses a second one for the same entity.
    let init = format!("{}{}", teleport("Ego", 10.0, -1), placed_in_one_private("Target", 10.0, -2, 10.0));
    let stories = two_groups(&speed_action("linear", "rate", 2.0, 20.0), 1.0, &relative_speed("Target", "linear", "rate", 5.0, false), 1.0);
    let text = xosc(&init, &stories, &stop_at(10.0));
    let run = run(&text);
    let end = event_time(&run, "GEAction", "end").expect("Ego's action ends");
    assert!(close(end, 1.01 + 3.34, 0.011), "ends at {end}");
    let v = at(&run, "Ego", 6.0).speed;
    assert!((16.66 - 1e-9..=16.68 + 1e-9).contains(&v), "Ego keeps the speed it reached: {v}");
    assert!(close(at(&run, "Target", 9.0).speed, 20.0, 1e-9));
    // esmini 3.6.0 on this scenario (run by hand, --fixed_timestep 0.01): the action ends at
    // 4.34, Ego 16.68 m/s at x = 65.4943 m at t = 6.
    assert!(close(end, 4.34, 1e-9), "ends at {end}");
    assert!(close(v, 16.68, 1e-9) && close(at(&run, "Ego", 6.0).x, 65.4943, 1e-4), "{:?}", at(&run, "Ego", 6.0));
}

#[test]
fn a_continuous_relative_step_target_is_followed_within_the_acceleration_limit() {
    // Ego (maxAcceleration 4 m/s²) at rest follows the Target's speed (0) with a step shape
    // from t = 1.01; the Target jumps to 10 m/s at t = 2.01. The step's value is the target,
    // but each step may change the speed by at most 4 · 0.01 m/s: 10 m/s 2.5 s later.
    let init = format!("{}{}", teleport("Ego", 10.0, -1), teleport("Target", 10.0, -2));
    let stories = two_groups(&speed_action("step", "time", 0.0, 10.0), 2.0, &relative_speed("Target", "step", "time", 0.0, true), 1.0);
    let text = xosc(&init, &stories, &stop_at(6.0)).replacen(r#"maxAcceleration="200""#, r#"maxAcceleration="4""#, 1);
    let run = run(&text);
    assert!(close(at(&run, "Target", 2.5).speed, 10.0, 1e-9));
    assert!(close(at(&run, "Ego", 2.0).speed, 0.0, 1e-9));
    assert!(close(at(&run, "Ego", 3.01).speed, 4.0, 0.041), "{}", at(&run, "Ego", 3.01).speed);
    assert!(close(at(&run, "Ego", 5.0).speed, 10.0, 1e-9));
    assert!(event_time(&run, "GEAction", "end").is_none(), "a continuous target never ends");
    // esmini 3.6.0 on this scenario (run by hand): Ego 9.96 m/s at x = 22.45 m at t = 4.5.
    let e = at(&run, "Ego", 4.5);
    assert!(close(e.speed, 9.96, 1e-9) && close(e.x, 22.45, 1e-4), "{e:?}");
}
