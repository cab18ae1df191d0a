//! The schema pass of `osc2cr check`: every problem of a file at once, each at its line.

use openscenario::validate::{validate_str, Finding, Severity};
use std::path::Path;

fn scenario(minor: u8, params: &str, init: &str, story: &str) -> String {
    let vehicle = crate::common::VEHICLE;
    format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="{minor}" date="2024-01-01T00:00:00" description="t" author="t"/>
  <ParameterDeclarations>{params}</ParameterDeclarations>
  <CatalogLocations/>
  <RoadNetwork/>
  <Entities>
    <ScenarioObject name="Ego">
      {vehicle}
    </ScenarioObject>
  </Entities>
  <Storyboard>
    <Init><Actions>{init}</Actions></Init>
    {story}
    <StopTrigger/>
  </Storyboard>
</OpenSCENARIO>
"#
    )
}

fn speed(value: &str) -> String {
    format!(
        r#"<Private entityRef="Ego"><PrivateAction><LongitudinalAction><SpeedAction>
        <SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>
        <SpeedActionTarget><AbsoluteTargetSpeed value="{value}"/></SpeedActionTarget>
        </SpeedAction></LongitudinalAction></PrivateAction></Private>"#
    )
}

fn check(text: &str) -> Vec<Finding> {
    validate_str(Path::new("t.xosc"), text, &[])
}

fn errors(findings: &[Finding]) -> Vec<(u32, String)> {
    findings.iter().filter(|f| f.severity == Severity::Error).map(|f| (f.location.line, f.message.clone())).collect()
}

#[test]
fn a_valid_file_has_no_finding() {
    let f = check(&scenario(3, r#"<ParameterDeclaration name="v" parameterType="double" value="10"/>"#, &speed("$v"), ""));
    assert!(f.is_empty(), "{f:#?}");
}

#[test]
fn every_problem_is_reported_at_its_line_in_one_run() {
    let story = r#"<Story name="s"></Story>"#;
    let init = format!("{}{}", speed("fast"), speed("$nope"));
    let text = scenario(3, r#"<ParameterDeclaration name="v" parameterType="double" value="ten"/>"#, &init, story)
        .replace("<Properties/>", "<Properties/><Colour/>")
        .replace(r#"vehicleCategory="car""#, r#"vehicleCategory="spaceship""#);
    let e = errors(&check(&text));
    let has = |line: u32, needle: &str| e.iter().any(|(l, m)| *l == line && m.contains(needle));
    assert!(has(4, "'ten' is not a valid double"), "{e:#?}");
    assert!(has(9, "'spaceship' is not one of"), "{e:#?}");
    assert!(has(16, "unknown element <Colour>"), "{e:#?}");
    assert!(has(23, "'fast' is not a valid double"), "{e:#?}");
    assert!(has(26, "parameter '$nope' is not declared"), "{e:#?}");
    assert!(has(28, "<Act>"), "a Story needs an Act: {e:#?}");
    assert_eq!(e.len(), 6, "{e:#?}");
}

#[test]
fn expressions_are_evaluated_and_their_failures_positioned() {
    let params = r#"<ParameterDeclaration name="zero" parameterType="double" value="0"/><ParameterDeclaration name="when" parameterType="dateTime" value="2024-01-01T00:00:00"/>"#;
    for (expr, needle) in
        [("${1/$zero}", "division by zero"), ("${sqrt(-1)}", "sqrt"), ("${1e308 * 10}", "finite"), ("${5}}", "unexpected"), ("${$when + 1}", "dateTime")]
    {
        let e = errors(&check(&scenario(3, params, &speed(expr), "")));
        assert!(e.len() == 1 && e[0].1.contains(needle), "{expr}: {e:#?}");
    }
    let fine = check(&scenario(3, params, &speed("${2 * 3 + $zero}"), ""));
    assert!(errors(&fine).is_empty(), "{fine:#?}");
}

#[test]
fn a_parameter_whose_declaration_is_wrong_is_flagged_where_it_is_used() {
    let text = scenario(3, r#"<ParameterDeclaration name="v" parameterType="double" value="x"/>"#, &speed("$v"), "");
    let e = errors(&check(&text));
    assert_eq!(e.len(), 2, "{e:#?}");
    assert!(e[1].1.contains("declaration at line 4 is wrong"), "{e:#?}");
}

#[test]
fn constraint_groups_hold_or_the_declaration_is_an_error() {
    let decl = |value: &str| {
        format!(
            r#"<ParameterDeclaration name="v" parameterType="double" value="{value}">
            <ConstraintGroup><ValueConstraint rule="greaterThan" value="0"/><ValueConstraint rule="lessThan" value="10"/></ConstraintGroup>
            <ConstraintGroup><ValueConstraint rule="equalTo" value="100"/></ConstraintGroup></ParameterDeclaration>"#
        )
    };
    for (value, ok) in [("5", true), ("100", true), ("10", false), ("-1", false)] {
        let e = errors(&check(&scenario(3, &decl(value), &speed("$v"), "")));
        assert_eq!(e.is_empty(), ok, "{value}: {e:#?}");
    }
}

#[test]
fn deprecated_and_later_version_elements_are_warnings() {
    let init = speed("1").replace(r#"priority"#, "x");
    let story = r#"<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="1"><Actors selectTriggeringEntities="false"/>
      <Maneuver name="m"><Event name="e" priority="overwrite"><Action name="x"><PrivateAction><LongitudinalAction><SpeedAction>
        <SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="1"/></SpeedActionTarget>
      </SpeedAction></LongitudinalAction></PrivateAction></Action>
      <StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>
      </Event></Maneuver></ManeuverGroup><StartTrigger/></Act></Story>"#;
    let f = check(&scenario(2, "", &init, story));
    assert!(errors(&f).is_empty(), "{f:#?}");
    assert!(f.iter().any(|w| w.severity == Severity::Warning && w.message.contains("'overwrite' is deprecated since OpenSCENARIO 1.2")), "{f:#?}");

    // VariableDeclarations came with 1.2: in a file declaring 1.0 it is a warning, not an error.
    let text = scenario(0, "", &speed("1"), "").replace("<CatalogLocations/>", "<VariableDeclarations/><CatalogLocations/>");
    let f = check(&text);
    assert!(errors(&f).is_empty(), "{f:#?}");
    // the warning names the version the construct came with, not the newest that has it
    assert!(f.iter().any(|w| w.message.contains("are OpenSCENARIO 1.2 (the file declares 1.0)")), "{f:#?}");

    // SpeedCondition's direction came with 1.2 (1.3 has it too)
    let by_speed = r#"<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition><SpeedCondition value="1" rule="greaterThan" direction="longitudinal"/></EntityCondition></ByEntityCondition>"#;
    let text =
        scenario(1, "", &init, &story.replace(r#"<ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition>"#, by_speed));
    let f = check(&text);
    assert!(errors(&f).is_empty(), "{f:#?}");
    assert!(f.iter().any(|w| w.message.contains("attribute 'direction' of <SpeedCondition> is OpenSCENARIO 1.2 (the file declares 1.1)")), "{f:#?}");
}

#[test]
fn ranges_of_the_standard_are_checked() {
    let text = scenario(3, "", &speed("1"), "")
        .replace(r#"wheelDiameter="0.6" trackWidth="1.8" positionX="3""#, r#"wheelDiameter="-0.6" trackWidth="1.8" positionX="3""#);
    let e = errors(&check(&text));
    assert!(e.len() == 1 && e[0].0 == 13 && e[0].1.contains("wheelDiameter > 0"), "{e:#?}");
}

#[test]
fn injected_parameters_must_fit_their_declaration() {
    let text = scenario(3, r#"<ParameterDeclaration name="v" parameterType="double" value="10"/>"#, &speed("$v"), "");
    let run = |inj: &[(&str, &str)]| {
        let inj: Vec<(String, String)> = inj.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
        validate_str(Path::new("t.xosc"), &text, &inj)
    };
    assert!(run(&[("v", "12.5")]).is_empty());
    let e = errors(&run(&[("v", "fast")]));
    assert!(e.len() == 1 && e[0].0 == 4, "{e:#?}");
    let w = run(&[("w", "1")]);
    assert!(w.len() == 1 && w[0].severity == Severity::Warning && w[0].message.contains("no global parameter 'w'"), "{w:#?}");
}

#[test]
fn malformed_xml_is_one_positioned_error() {
    let f = check("<OpenSCENARIO><FileHeader></OpenSCENARIO>");
    assert_eq!(f.len(), 1);
    assert_eq!(f[0].severity, Severity::Error);
    assert!(f[0].location.line == 1 && f[0].location.col > 1, "{f:#?}");
}
