//! PNG and SVG stills: sizes, the ego where it must be, colours by type, time stamps.

use crate::common::*;
use render::{render_layout, render_png, render_pngs, render_svg, style, Error, RenderOptions};

fn opts(time: f64) -> RenderOptions {
    whole(time)
}

/// Where world (x, y) is in the whole-map still at `time`.
fn at(s: &commonroad::Scenario, p: Option<&commonroad::PlanningProblemSet>, time: f64, x: f64, y: f64) -> (u32, u32) {
    px_of(&render_layout(s, p, &opts(time)).unwrap(), x, y)
}

#[test]
fn png_has_width_and_the_clamped_aspect() {
    let (s, p) = straight(50);
    let pm = decode_png(&render_png(&s, Some(&p), &opts(0.0)).unwrap());
    let l = render_layout(&s, Some(&p), &opts(0.0)).unwrap();
    assert_eq!((pm.width(), pm.height()), (l.width, l.height));
    // the map area has the clamped aspect 1/4, between the header and the footer
    assert_eq!((l.map.width(), l.map.height()), (1200.0, 300.0));
    assert!(l.map.y0 > 20.0 && f64::from(l.height) - l.map.y1 > 20.0, "{l:?}");
    // the view's own arithmetic, by hand
    assert_eq!(at(&s, Some(&p), 0.0, 20.0, 2.0), straight_px(20.0, 2.0, l.map.y0));
    let narrow = RenderOptions { width: 400, ..opts(0.0) };
    let l = render_layout(&s, Some(&p), &narrow).unwrap();
    assert_eq!((l.map.width(), l.map.height()), (400.0, 100.0));
}

#[test]
fn ego_found_from_the_planning_problem_is_drawn_in_ego_colour_where_it_is() {
    let (s, p) = straight(50);
    // t = 0: the car at x = 20; t = 1.0 s: 10 steps of 1 m later, x = 30
    for (t, x) in [(0.0, 20.0), (1.0, 30.0), (5.0, 70.0)] {
        let pm = decode_png(&render_png(&s, Some(&p), &opts(t)).unwrap());
        assert_eq!(pixel(&pm, at(&s, Some(&p), t, x, 2.0)), rgb(style::EGO), "t = {t}");
    }
    // the pedestrian (not the ego) in its type colour at x = 60, y = 0.5 + 0.01 * 10
    let pm = decode_png(&render_png(&s, Some(&p), &opts(1.0)).unwrap());
    let ped = rgb(style::dynamic_color(commonroad::DynamicObstacleType::Pedestrian));
    assert_eq!(pixel(&pm, at(&s, Some(&p), 1.0, 60.0, 0.6)), ped);
    // the road surface between them (behind the ego's trail); the background above the road
    assert_eq!(pixel(&pm, at(&s, Some(&p), 1.0, 45.0, 1.0)), rgb(style::ROAD));
    assert_eq!(pixel(&pm, at(&s, Some(&p), 1.0, 45.0, 10.0)), rgb(style::BACKGROUND));
}

#[test]
fn without_planning_problem_nothing_is_ego_unless_chosen() {
    let (s, _) = straight(50);
    let car = rgb(style::dynamic_color(commonroad::DynamicObstacleType::Car));
    let pm = decode_png(&render_png(&s, None, &opts(0.0)).unwrap());
    assert_eq!(pixel(&pm, at(&s, None, 0.0, 20.0, 2.0)), car);
    let chosen = RenderOptions { ego: Some(s.dynamic_obstacles[0].id.get()), ..opts(0.0) };
    let pm = decode_png(&render_png(&s, None, &chosen).unwrap());
    assert_eq!(pixel(&pm, at(&s, None, 0.0, 20.0, 2.0)), rgb(style::EGO));
}

#[test]
fn obstacles_vanish_after_their_trajectory() {
    let (s, p) = straight(10);
    // after step 10 the car is gone: its last position shows road again
    let pm = decode_png(&render_png(&s, Some(&p), &opts(2.0)).unwrap());
    assert_eq!(pixel(&pm, at(&s, Some(&p), 2.0, 30.0, 1.2)), rgb(style::ROAD));
}

#[test]
fn several_stills_of_the_whole_map_share_one_view_and_differ() {
    let (s, p) = straight(50);
    let pngs = render_pngs(&s, Some(&p), &opts(0.0), &[0.0, 2.5]).unwrap();
    assert_eq!(pngs.len(), 2);
    let (a, b) = (decode_png(&pngs[0]), decode_png(&pngs[1]));
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    assert_ne!(a.data(), b.data());
    // deterministic: the same input gives the same bytes
    assert_eq!(pngs[0], render_png(&s, Some(&p), &opts(0.0)).unwrap());
}

#[test]
fn svg_parses_and_has_the_time_stamp() {
    let (s, p) = straight(60);
    let no_trail = RenderOptions { trail: 0.0, ..opts(5.5) };
    let text = render_svg(&s, Some(&p), &no_trail).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let l = render_layout(&s, Some(&p), &opts(5.5)).unwrap();
    assert_eq!(root.attribute("width"), Some("1200"));
    assert_eq!(root.attribute("height"), Some(l.height.to_string().as_str()));
    let texts: Vec<&str> = doc.descendants().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    // labels, the time, the scale and the legend
    assert_eq!(texts, vec!["id 3", "id 2 ego", "t = 5.5 s", "5 m", "ego", "pedestrian", "goal", "ego path"]);
    // the ego's fill colour appears twice without trails: the ego's box, its legend swatch
    let ego = style::EGO.hex();
    let n = doc.descendants().filter(|n| n.attribute("fill") == Some(ego.as_str())).count();
    assert_eq!(n, 2);
}

#[test]
fn bad_options_and_empty_scenarios_are_errors() {
    let (s, p) = straight(5);
    let e = render_png(&s, Some(&p), &RenderOptions { ego: Some(999), ..opts(0.0) }).unwrap_err();
    assert_eq!(e, Error::UnknownEgo(999));
    let e = render_png(&s, Some(&p), &RenderOptions { width: 10, ..opts(0.0) }).unwrap_err();
    assert!(e.to_string().contains("--width"), "{e}");
    assert!(render_png(&s, Some(&p), &opts(f64::NAN)).is_err());
    let empty = commonroad::Scenario::new(s.header.clone());
    assert!(matches!(render_png(&empty, None, &opts(0.0)), Err(Error::View(_))));
}

#[test]
fn time_labels_show_the_step_resolution() {
    assert_eq!(render::time_label(55, 0.1), "t = 5.5 s");
    assert_eq!(render::time_label(0, 0.1), "t = 0.0 s");
    assert_eq!(render::time_label(111, 0.05), "t = 5.55 s");
    assert_eq!(render::time_label(3, 1.0), "t = 3.0 s");
}

#[test]
fn traffic_light_cycles() {
    use commonroad::{CycleElement, TrafficLight, TrafficLightColor::*, TrafficLightId};
    use std::num::NonZeroU64;
    let phase = |d, color| CycleElement { duration: NonZeroU64::new(d).unwrap(), color };
    let mut light = TrafficLight {
        id: TrafficLightId::new(1).unwrap(),
        cycle: vec![phase(50, Red), phase(10, RedYellow), phase(50, Green), phase(10, Yellow)],
        time_offset: 0,
        position: None,
        direction: None,
        active: Some(true),
    };
    let at = |l: &TrafficLight, t| render::timeline::light_color(l, t);
    assert_eq!([at(&light, 0), at(&light, 49), at(&light, 50), at(&light, 60), at(&light, 119), at(&light, 120)], [Red, Red, RedYellow, Green, Yellow, Red]);
    light.time_offset = 60; // starts 60 steps into the cycle: green
    assert_eq!(at(&light, 0), Green);
    light.active = Some(false);
    assert_eq!(at(&light, 0), Inactive);
}
