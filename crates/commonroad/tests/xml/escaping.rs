//! Text and attribute escaping, checked by parsing the written file back with roxmltree.

use crate::common;

use commonroad::xml::{escape, write_scenario};
use commonroad::Error;

#[test]
fn markup_characters_become_entities() {
    assert_eq!(escape("a&b<c>d\"e'f").unwrap(), "a&amp;b&lt;c&gt;d&quot;e&apos;f");
    assert_eq!(escape("plain Zoë ✓").unwrap(), "plain Zoë ✓");
    assert_eq!(escape("").unwrap(), "");
}

#[test]
fn whitespace_controls_become_character_references() {
    assert_eq!(escape("a\tb\nc\rd").unwrap(), "a&#9;b&#10;c&#13;d");
}

#[test]
fn characters_xml_cannot_carry_are_refused() {
    assert_eq!(escape("a\u{0}b"), Err('\u{0}'));
    assert_eq!(escape("\u{1b}[31m"), Err('\u{1b}'));
    assert_eq!(escape("x\u{FFFF}"), Err('\u{FFFF}'));
}

#[test]
fn hostile_strings_round_trip_through_a_parser() {
    let mut m = common::minimal();
    let author = "O'Neil & \"Sons\" <script>\t\n\r end";
    let value = "]]> & <![CDATA[ x";
    m.scenario.header.author = author.to_string();
    m.scenario.network.traffic_signs[0].elements[0].additional_values = vec![value.to_string()];
    let text = String::from_utf8(write_scenario(&m.scenario, &m.problems).unwrap()).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(doc.root_element().attribute("author"), Some(author));
    let v = doc.descendants().find(|n| n.has_tag_name("additionalValue")).unwrap();
    assert_eq!(v.text(), Some(value));
}

#[test]
fn writing_an_unrepresentable_character_is_an_error_naming_the_place() {
    let mut m = common::minimal();
    m.scenario.header.source = "bad\u{7}bell".into();
    match write_scenario(&m.scenario, &m.problems) {
        Err(Error::InvalidChar { context, ch }) => {
            assert_eq!(ch, '\u{7}');
            assert!(context.contains("source"), "{context}");
        }
        other => panic!("expected InvalidChar, got {other:?}"),
    }
}
