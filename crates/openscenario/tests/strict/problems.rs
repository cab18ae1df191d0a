//! What a strict reading rejects is returned as positioned problems (never silently read as
//! something else): names that refer to nothing, overrides of undeclared parameters, and
//! distributions that cannot be sampled. Lines and columns are counted by hand in the texts.

use openscenario::*;
use std::path::Path;

fn problems(text: &str, overrides: &[(&str, &str)]) -> Vec<Diagnostic> {
    let options = LoadOptions { parameters: overrides.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect(), seed: None, ..Default::default() };
    match load_str(Path::new("/virtual/strict.xosc"), text, &options) {
        Ok(l) => l.problems,
        Err(e) => panic!("{e}"),
    }
}

/// A scenario with one car `Ego`; `init` and `story` are spliced in (each on its own line).
fn scenario(init: &str, story: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations><ParameterDeclaration name="Speed" parameterType="double" value="10"/></ParameterDeclarations>
<RoadNetwork/>
<Entities><ScenarioObject name="Ego"><MiscObject name="box" miscObjectCategory="obstacle" mass="1"><BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="1" length="1" height="1"/></BoundingBox><Properties/></MiscObject></ScenarioObject></Entities>
<Storyboard>
<Init><Actions>
{init}
</Actions></Init>
{story}
</Storyboard>
</OpenSCENARIO>"#
    )
}

fn teleport(entity: &str) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0"/></Position></TeleportAction></PrivateAction></Private>"#
    )
}

fn story(actor: &str, action: &str, condition: &str) -> String {
    format!(
        r#"<Story name="S"><Act name="A"><ManeuverGroup name="G" maximumExecutionCount="1"><Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors><Maneuver name="M"><Event name="E" priority="parallel">
<Action name="Act1">{action}</Action>
<StartTrigger><ConditionGroup>
<Condition name="C" delay="0" conditionEdge="none">{condition}</Condition>
</ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup></Act></Story>"#
    )
}

const SIM_TIME: &str = r#"<ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition>"#;
const SPEED: &str = r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="1"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#;

fn one(found: &[Diagnostic]) -> &Diagnostic {
    assert_eq!(found.len(), 1, "{found:?}");
    &found[0]
}

#[test]
fn a_valid_scenario_has_no_problem() {
    assert!(problems(&scenario(&teleport("Ego"), &story("Ego", SPEED, SIM_TIME)), &[]).is_empty());
}

#[test]
fn init_actions_for_an_undeclared_entity() {
    let found = problems(&scenario(&teleport("Nobody"), ""), &[]);
    let p = one(&found);
    // line 9 holds the Init private; the value of its entityRef starts at column 21, after
    // `<Private entityRef="` (20 characters)
    assert_eq!((p.location.line, p.location.col), (9, 21), "{p}");
    assert!(p.message.contains("`Nobody` is not an entity"), "{p}");
}

#[test]
fn an_undeclared_actor_and_reference_entity() {
    let relative = r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><RelativeTargetSpeed entityRef="Ghost" value="1" speedTargetValueType="delta" continuous="false"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#;
    let found = problems(&scenario(&teleport("Ego"), &story("Other", relative, SIM_TIME)), &[]);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found.iter().any(|p| p.message.contains("maneuver group `G`") && p.message.contains("`Other`")), "{found:?}");
    let speed = found.iter().find(|p| p.message.contains("SpeedAction")).expect("the relative speed target");
    assert!(speed.message.contains("`Ghost`"), "{speed}");
    assert_eq!(speed.location.line, 12, "{speed}");
}

#[test]
fn a_condition_on_what_does_not_exist() {
    let cases = [
        (
            r#"<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><RelativeDistanceCondition entityRef="Phantom" value="5" freespace="false" relativeDistanceType="longitudinal" rule="lessThan"/></EntityCondition></ByEntityCondition>"#,
            "`Phantom`",
        ),
        (
            r#"<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="NoSuchEvent" state="endTransition"/></ByValueCondition>"#,
            "NoSuchEvent",
        ),
        (r#"<ByValueCondition><ParameterCondition parameterRef="Undeclared" value="1" rule="equalTo"/></ByValueCondition>"#, "parameter `Undeclared`"),
        (r#"<ByValueCondition><VariableCondition variableRef="NoVar" value="1" rule="equalTo"/></ByValueCondition>"#, "variable `NoVar`"),
    ];
    for (condition, expected) in cases {
        let text = scenario(&teleport("Ego"), &story("Ego", SPEED, condition));
        let found = problems(&text, &[]);
        let p = one(&found);
        assert!(p.message.contains(expected), "{p}");
        // at the value of the attribute that names it (the condition is on line 14)
        let name = expected.trim_start_matches("parameter ").trim_start_matches("variable ").trim_matches('`');
        let column = text.lines().nth(13).and_then(|l| l.find(&format!("\"{name}\""))).expect("the name on line 14") + 2;
        assert_eq!((p.location.line, p.location.col), (14, column as u32), "{p}");
    }
    // an element of the right type and name is found, also by a `::` path
    let path = r#"<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="S::A::G::M::E" state="endTransition"/></ByValueCondition>"#;
    assert!(problems(&scenario(&teleport("Ego"), &story("Ego", SPEED, path)), &[]).is_empty());
}

#[test]
fn a_parameter_set_on_an_undeclared_parameter() {
    let set = r#"<GlobalAction><ParameterAction parameterRef="Missing"><SetAction value="3"/></ParameterAction></GlobalAction>"#;
    let found = problems(&scenario(&teleport("Ego"), &story("Ego", set, SIM_TIME)), &[]);
    assert!(one(&found).message.contains("parameter `Missing` is not declared"), "{found:?}");
}

#[test]
fn an_override_of_an_undeclared_parameter() {
    let found = problems(&scenario(&teleport("Ego"), ""), &[("Speed", "3"), ("Sped", "4")]);
    assert!(one(&found).message.contains("'Sped'"), "{found:?}");
}

fn stochastic(distribution: &str) -> String {
    testkit::stochastic_set("strict.xosc", "Speed", distribution)
}

#[test]
fn distributions_that_cannot_be_sampled() {
    let cases = [
        (r#"<NormalDistribution expectedValue="10" variance="-1"/>"#, "variance -1 is negative"),
        (r#"<LogNormalDistribution expectedValue="1" variance="-0.5"/>"#, "variance -0.5 is negative"),
        (r#"<UniformDistribution><Range lowerLimit="5" upperLimit="2"/></UniformDistribution>"#, "empty or inverted"),
        (r#"<UniformDistribution><Range lowerLimit="5" upperLimit="5"/></UniformDistribution>"#, "empty or inverted"),
        (r#"<NormalDistribution expectedValue="10" variance="1"><Range lowerLimit="20" upperLimit="0"/></NormalDistribution>"#, "inverted"),
        (r#"<ProbabilityDistributionSet><Element value="1" weight="0"/><Element value="2" weight="0"/></ProbabilityDistributionSet>"#, "sum to 0"),
        (r#"<ProbabilityDistributionSet><Element value="1" weight="-1"/><Element value="2" weight="3"/></ProbabilityDistributionSet>"#, "negative weight"),
        (r#"<PoissonDistribution expectedValue="-2"/>"#, "not positive"),
    ];
    for (d, expected) in cases {
        let found = problems(&stochastic(d), &[]);
        let p = one(&found);
        assert!(p.message.contains(expected), "{d}: {p}");
        assert_eq!((p.location.line, p.location.col), (6, 1), "{p}");
    }
    // relative weights (the ASAM example's 5, 10, 20) are fine
    let relative = r#"<ProbabilityDistributionSet><Element value="1" weight="5"/><Element value="2" weight="10"/></ProbabilityDistributionSet>"#;
    assert!(problems(&stochastic(relative), &[]).is_empty());
}

#[test]
fn deterministic_ranges_and_sets_without_values() {
    let text = r#"<?xml version="1.0"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterValueDistribution><ScenarioFile filepath="strict.xosc"/>
<Deterministic>
<DeterministicSingleParameterDistribution parameterName="Speed"><DistributionRange stepWidth="1">
<Range lowerLimit="10" upperLimit="1"/></DistributionRange></DeterministicSingleParameterDistribution>
<DeterministicSingleParameterDistribution parameterName="Other"><DistributionSet>
</DistributionSet></DeterministicSingleParameterDistribution>
</Deterministic>
</ParameterValueDistribution>
</OpenSCENARIO>"#;
    let found = problems(text, &[]);
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!(found[0].location.line, 7, "{}", found[0]);
    assert!(found[0].message.contains("below lowerLimit"), "{}", found[0]);
    assert_eq!(found[1].location.line, 8, "{}", found[1]);
    assert!(found[1].message.contains("no Element"), "{}", found[1]);
}
