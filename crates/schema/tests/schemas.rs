//! The embedded schemas read completely, and the tables answer as the XSD text says.

use schema::content::{match_children, ContentProblem};
use schema::simple::{check_literal, LiteralCheck};
use schema::{Primitive, Term};

#[test]
fn every_version_reads_and_every_type_reference_resolves() {
    for minor in 0..=3 {
        let s = schema::for_minor(minor).expect("schema");
        assert!(s.roots.iter().any(|r| r.name == "OpenSCENARIO"));
        let mut checked = 0;
        for ty in s.types() {
            for e in s.child_elements(ty) {
                assert!(s.complex_type(&e.type_name).is_some(), "1.{minor}: {}.{} has unknown type {}", ty.name, e.name, e.type_name);
                checked += 1;
            }
            for a in &ty.attributes {
                assert!(s.simple_kind(&a.type_name).is_some(), "1.{minor}: {}@{} has unknown type {}", ty.name, a.name, a.type_name);
            }
        }
        assert!(checked > 250, "1.{minor}: only {checked} element declarations");
    }
    assert!(schema::for_minor(4).is_none());
}

#[test]
fn the_embedded_schemas_are_the_shared_spec_files_unmodified() {
    let spec = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/spec");
    if !spec.is_dir() {
        eprintln!("skipped: no ../shared/spec beside the repository");
        return;
    }
    for (ours, theirs) in [("1.0", "1.0"), ("1.1", "1.1.1"), ("1.2", "1.2"), ("1.3", "1.3")] {
        let a = std::fs::read(format!("{}/xsd/OpenSCENARIO-{ours}.xsd", env!("CARGO_MANIFEST_DIR"))).expect("embedded");
        let b = std::fs::read(spec.join(format!("OpenSCENARIOv{theirs}.xsd"))).expect("spec");
        assert!(a == b, "xsd/OpenSCENARIO-{ours}.xsd differs from ../shared/spec");
    }
}

#[test]
fn attributes_and_simple_types_follow_the_xsd() {
    let s = schema::for_minor(3).expect("1.3");
    let brake = s.complex_type("Brake").expect("Brake");
    let value = brake.attributes.iter().find(|a| a.name == "value").expect("value");
    assert!(value.required);
    let double = s.simple_kind(&value.type_name).expect("Double");
    assert_eq!(double.primitive, Primitive::Double);
    assert!(double.allows_parameter && double.allows_expression);
    assert_eq!(check_literal(&double, "1e3"), LiteralCheck::Valid);
    assert_eq!(check_literal(&double, "$v"), LiteralCheck::Parameter);
    assert_eq!(check_literal(&double, "${$v + 1}"), LiteralCheck::Expression);
    assert!(matches!(check_literal(&double, "ezert"), LiteralCheck::Invalid(_)));
    assert!(matches!(check_literal(&double, "inf"), LiteralCheck::Invalid(_)));

    let string = s.simple_kind("String").expect("String");
    assert!(string.allows_parameter && !string.allows_expression);
    let ushort = s.simple_kind("UnsignedShort").expect("UnsignedShort");
    assert!(matches!(check_literal(&ushort, "65536"), LiteralCheck::Invalid(_)));
    assert_eq!(check_literal(&ushort, "65535"), LiteralCheck::Valid);
    let uint = s.simple_kind("UnsignedInt").expect("UnsignedInt");
    assert!(matches!(check_literal(&uint, "-56"), LiteralCheck::Invalid(_)));
    let date = s.simple_kind("DateTime").expect("DateTime");
    assert_eq!(check_literal(&date, "2017-02-24T10:00:00"), LiteralCheck::Valid);
    assert!(matches!(check_literal(&date, "2017-02-24"), LiteralCheck::Invalid(_)));
    assert!(!date.allows_expression);

    // Enumerations, with the literals the schema marks deprecated.
    let precipitation = s.simple_kind("PrecipitationType").expect("PrecipitationType");
    assert_eq!(check_literal(&precipitation, "rain"), LiteralCheck::Valid);
    assert!(matches!(check_literal(&precipitation, "TTTT"), LiteralCheck::Invalid(_)));
    let category = s.simple_kind("ObjectType").expect("ObjectType");
    assert!(category.literals.is_some() && category.allows_parameter);
    let cloud = s.simple_kind("CloudState").expect("CloudState");
    assert!(cloud.deprecated, "CloudState is deprecated in 1.3");
    let obstacle = s.simple_kind("MiscObjectCategory").expect("MiscObjectCategory");
    assert_eq!(check_literal(&obstacle, "wind"), LiteralCheck::DeprecatedLiteral);
}

#[test]
fn content_models_match_as_the_schema_says() {
    let s = schema::for_minor(3).expect("1.3");
    let story = s.complex_type("Story").expect("Story");
    assert_eq!(match_children(s, story, &["ParameterDeclarations", "Act", "Act"]), vec![]);
    assert_eq!(match_children(s, story, &[]), vec![ContentProblem::Missing { expected: vec!["Act".into()], before: None }]);
    assert_eq!(match_children(s, story, &["Act", "ParameterDeclarations"]), vec![ContentProblem::NotAllowedHere { child: 1 }]);
    assert_eq!(match_children(s, story, &["Act", "Test"]), vec![ContentProblem::Unknown { child: 1 }]);

    // A choice: exactly one alternative.
    let action = s.complex_type("Action").expect("Action");
    assert_eq!(match_children(s, action, &["PrivateAction"]), vec![]);
    assert_eq!(match_children(s, action, &["GlobalAction", "PrivateAction"]), vec![ContentProblem::NotAllowedHere { child: 1 }]);
    match &match_children(s, action, &[])[..] {
        [ContentProblem::Missing { expected, .. }] => {
            assert!(expected.contains(&"GlobalAction".to_string()) && expected.contains(&"PrivateAction".to_string()))
        }
        other => panic!("{other:?}"),
    }

    // xsd:all, any order, each at most once.
    let by_entity = s.complex_type("ByEntityCondition").expect("ByEntityCondition");
    assert!(matches!(by_entity.content.as_ref().map(|p| &p.term), Some(Term::All(_))));
    assert_eq!(match_children(s, by_entity, &["EntityCondition", "TriggeringEntities"]), vec![]);
    assert_eq!(match_children(s, by_entity, &["EntityCondition", "TriggeringEntities", "EntityCondition"]), vec![ContentProblem::NotAllowedHere { child: 2 }]);

    // Named groups inside sequences.
    let root = s.complex_type("OpenScenario").expect("OpenScenario");
    assert_eq!(match_children(s, root, &["FileHeader", "ParameterDeclarations", "CatalogLocations", "RoadNetwork", "Entities", "Storyboard"]), vec![]);
    assert_eq!(match_children(s, root, &["FileHeader", "Catalog"]), vec![]);
    assert!(!match_children(s, root, &["ParameterDeclarations"]).is_empty(), "FileHeader is required");
}
