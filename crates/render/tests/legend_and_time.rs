//! What a picture explains about itself: the legend names the lines drawn over the map (the
//! ego's dashed path, the trails with a dot per second), the time bar's ticks are labelled in
//! seconds, the header gives every event its start time (those starting at the picture's time
//! too), and a sheet's panel shows its cars large enough to see.

use std::collections::BTreeMap;

use crate::common::*;
use render::frame::Purpose;
use render::scene::Prepared;
use render::{render_svg, Mark, RenderOptions};

fn svg_texts(s: &commonroad::Scenario, p: &commonroad::PlanningProblemSet, o: &RenderOptions) -> Vec<String> {
    let svg = render_svg(s, Some(p), o).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    doc.descendants().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).map(str::to_string).collect()
}

#[test]
fn the_legend_names_the_ego_path_and_the_trails() {
    let (s, p) = straight(60);
    let with = svg_texts(&s, &p, &RenderOptions { time: 5.5, ..Default::default() });
    assert!(with.contains(&"ego path".to_string()) && with.contains(&"trail, a dot per s".to_string()), "{with:?}");
    // no trail drawn, none in the legend; the ego's path is drawn all the same
    let without = svg_texts(&s, &p, &RenderOptions { time: 5.5, trail: 0.0, ..Default::default() });
    assert!(without.contains(&"ego path".to_string()) && !without.iter().any(|t| t.starts_with("trail")), "{without:?}");
    // the path swatch is dashed like the path, in the ego's colour
    let svg = render_svg(&s, Some(&p), &RenderOptions { time: 5.5, ..Default::default() }).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let dashed_ego =
        doc.descendants().filter(|n| n.attribute("stroke") == Some(render::style::EGO.hex().as_str()) && n.attribute("stroke-dasharray").is_some()).count();
    assert_eq!(dashed_ego, 2, "the path and its legend swatch");
}

#[test]
fn the_time_bar_labels_its_ticks_in_seconds() {
    let (s, p) = straight(60);
    let marks = vec![Mark { time: 1.0, text: "Start".into() }];
    let texts = svg_texts(&s, &p, &RenderOptions { time: 0.5, marks, ..Default::default() });
    // a 6 s run on 1200 px: a tick every second, labelled
    for label in ["0 s", "1 s", "3 s", "6 s"] {
        assert!(texts.contains(&label.to_string()), "{label} missing from {texts:?}");
    }
    // no time bar without events, so no labels
    let plain = svg_texts(&s, &p, &RenderOptions { time: 0.5, ..Default::default() });
    assert!(!plain.contains(&"1 s".to_string()), "{plain:?}");
}

#[test]
fn the_header_gives_every_event_its_start_time() {
    let (s, p) = straight(50);
    let marks = vec![Mark { time: 1.0, text: "Start".into() }, Mark { time: 3.0, text: "Cross".into() }];
    let names = BTreeMap::new();
    let o = |time| RenderOptions { time, names: names.clone(), marks: marks.clone(), ..Default::default() };
    // at the very step an event starts, it has its time like the earlier ones
    let at_cross = svg_texts(&s, &p, &o(3.0));
    assert!(at_cross.contains(&"1.0 s Start".to_string()) && at_cross.contains(&"3.0 s Cross".to_string()), "{at_cross:?}");
    assert!(!at_cross.contains(&"Cross".to_string()), "{at_cross:?}");
}

#[test]
fn a_sheet_panel_draws_its_cars_large_enough_to_see() {
    // the pedestrian 380 m ahead of the car: both in one panel would make the car 6 px long
    let (mut s, p) = straight(50);
    let walker = &mut s.dynamic_obstacles[1];
    walker.initial_state.x = 400.0;
    walker.trajectory.iter_mut().for_each(|st| st.x = 400.0);
    let ego = Some(s.dynamic_obstacles[0].id);
    let width = 591;
    let options = RenderOptions { width, ..Default::default() };
    let car = |purpose| {
        let l = Prepared::new(&s, Some(&p), &options, purpose, Some(0.6), false).unwrap().layout(0);
        l.obstacles.iter().find(|o| o.ego).map(|o| (o.length_px, o.bbox.inside(&l.map))).unwrap()
    };
    let (still, _) = car(Purpose::Still { step: 0, trail_steps: 10 });
    let (panel, inside) = car(Purpose::Panel { step: 0, trail_steps: 10, ego });
    assert!(still < f64::from(width) * render::frame::MIN_PANEL_USER_SHARE, "{still}");
    assert!(panel >= f64::from(width) * render::frame::MIN_PANEL_USER_SHARE && inside, "{panel}");
    // road users close together: the panel frames them all, as a still does
    let (s, p) = straight(50);
    let ego = Some(s.dynamic_obstacles[0].id);
    let plan = |purpose| Prepared::new(&s, Some(&p), &options, purpose, Some(0.6), false).unwrap().layout(0).world;
    assert_eq!(plan(Purpose::Still { step: 0, trail_steps: 10 }), plan(Purpose::Panel { step: 0, trail_steps: 10, ego }));
}
