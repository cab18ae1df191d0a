//! What a picture frames and says: by default the road users at the still's time, large and
//! labelled; a region, a followed road user, a panning animation; names, events, the sheet.

use std::collections::BTreeMap;

use crate::common::*;
use render::frame::{Purpose, ViewPlan};
use render::scene::Prepared;
use render::{render_layout, render_png, render_sheet_png, render_svg, sheet_times, Frame, Layout, Mark, RenderOptions};

fn at(time: f64) -> RenderOptions {
    RenderOptions { time, ..Default::default() }
}

/// Every road user's box and label inside the map area, the labels clear of each other, each
/// car at least `min_length_px` long.
fn legible(l: &Layout, min_length_px: f64) {
    for o in &l.obstacles {
        if o.obstacle_type == "car" {
            assert!(o.length_px >= min_length_px, "{} is {:.1} px long", o.id, o.length_px);
        }
        assert!(o.bbox.inside(&l.map), "{} box {:?} outside {:?}", o.id, o.bbox, l.map);
        let label = o.label.as_ref().expect("labelled");
        assert!(label.rect.inside(&l.map), "{} label {:?} outside {:?}", o.id, label.rect, l.map);
    }
    for (i, a) in l.obstacles.iter().enumerate() {
        for b in &l.obstacles[i + 1..] {
            let (ra, rb) = (&a.label.as_ref().unwrap().rect, &b.label.as_ref().unwrap().rect);
            assert_eq!(ra.overlap(rb), 0.0, "labels of {} and {} overlap", a.id, b.id);
        }
    }
}

#[test]
fn a_still_frames_the_road_users_at_its_time() {
    let (s, p) = straight(50);
    for t in [0.0, 2.5, 5.0] {
        let l = render_layout(&s, Some(&p), &at(t)).unwrap();
        assert_eq!(l.obstacles.len(), 2);
        // the 4.5 m car: over 60 px (the whole 100 m map would give it 47)
        legible(&l, 0.9 * 4.5 * 1200.0 / 114.0);
        assert!(l.obstacles.iter().any(|o| o.ego && o.length_px > 60.0), "{l:?}");
        // the picture is no taller than wide
        assert!(l.map.height() <= l.map.width());
    }
    // the PNG is that picture: the ego's colour at its centre
    let l = render_layout(&s, Some(&p), &at(5.0)).unwrap();
    let pm = decode_png(&render_png(&s, Some(&p), &at(5.0)).unwrap());
    assert_eq!((pm.width(), pm.height()), (l.width, l.height));
    let ego = l.obstacles.iter().find(|o| o.ego).unwrap();
    assert_eq!(pixel(&pm, (ego.center.0 as u32, ego.center.1 as u32)), rgb(render::style::EGO));
}

#[test]
fn names_label_the_road_users_and_marks_appear_when_they_happen() {
    let (s, p) = straight(50);
    let ego = s.dynamic_obstacles[0].id.get();
    let ped = s.dynamic_obstacles[1].id.get();
    let names = BTreeMap::from([(ego, "Hero".to_string()), (ped, "Walker".to_string())]);
    let marks = vec![Mark { time: 1.0, text: "Start".into() }, Mark { time: 3.0, text: "Cross".into() }];
    let o = |time| RenderOptions { time, names: names.clone(), marks: marks.clone(), ..Default::default() };
    let l = render_layout(&s, Some(&p), &o(2.0)).unwrap();
    let label = |id| l.obstacles.iter().find(|x| x.id == id).unwrap().label.clone().unwrap().text;
    assert_eq!(label(ego), format!("Hero ({ego}) ego"));
    assert_eq!(label(ped), format!("Walker ({ped})"));
    let texts = |t| {
        let svg = render_svg(&s, Some(&p), &o(t)).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        doc.descendants().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).map(str::to_string).collect::<Vec<_>>()
    };
    let early = texts(0.5);
    assert!(!early.iter().any(|t| t.contains("Start")), "{early:?}");
    let mid = texts(2.0);
    assert!(mid.contains(&"1.0 s Start".to_string()) && !mid.iter().any(|t| t.contains("Cross")), "{mid:?}");
    let late = texts(4.0);
    assert!(late.contains(&"1.0 s Start".to_string()) && late.contains(&"3.0 s Cross".to_string()), "{late:?}");
}

#[test]
fn a_region_shows_that_rectangle() {
    let (s, p) = straight(50);
    let o = RenderOptions { frame: Frame::Region([10.0, -5.0, 50.0, 15.0]), ..at(0.0) };
    let l = render_layout(&s, Some(&p), &o).unwrap();
    assert!((l.world.min_x - 10.0).abs() < 1e-9 && (l.world.max_x - 50.0).abs() < 1e-9, "{:?}", l.world);
    assert!((l.scale - 1200.0 / 40.0).abs() < 1e-9);
    let bad = RenderOptions { frame: Frame::Region([10.0, 0.0, 5.0, 1.0]), ..at(0.0) };
    assert!(render_png(&s, Some(&p), &bad).unwrap_err().to_string().contains("--region"));
}

#[test]
fn follow_keeps_the_road_user_in_the_middle() {
    let (s, p) = straight(50);
    let id = s.dynamic_obstacles[0].id.get();
    for t in [0.0, 2.0, 5.0] {
        let l = render_layout(&s, Some(&p), &RenderOptions { frame: Frame::Follow(id), ..at(t) }).unwrap();
        let o = l.obstacles.iter().find(|o| o.id == id).unwrap();
        let (cx, cy) = l.map.center();
        assert!((o.center.0 - cx).abs() < 0.5 && (o.center.1 - cy).abs() < 0.5, "t = {t}: {:?} vs {:?}", o.center, (cx, cy));
        assert!((l.world.max_x - l.world.min_x - render::FOLLOW_SPAN_M).abs() < 1e-6);
    }
    let unknown = RenderOptions { frame: Frame::Follow(999), ..at(0.0) };
    assert!(render_png(&s, Some(&p), &unknown).unwrap_err().to_string().contains("--follow"));
}

#[test]
fn an_animation_pans_and_zooms_with_road_users_that_go_far() {
    // the car alone, 500 m along: one view of it all would make it 10 px long
    let (mut s, p) = straight(500);
    s.dynamic_obstacles.truncate(1);
    let prepared = Prepared::new(&s, Some(&p), &RenderOptions::default(), Purpose::Animation, None, true).unwrap();
    assert!(matches!(prepared.plan, ViewPlan::Pan { .. }));
    for step in [0, 250, 500] {
        let l = prepared.layout(step);
        let o = &l.obstacles[0];
        assert!(o.length_px >= 30.0, "{}", o.length_px);
        legible(&l, 30.0);
    }
    // the car drives away from the pedestrian: the camera zooms out in time, nobody is cut off
    let (s, p) = straight(500);
    let prepared = Prepared::new(&s, Some(&p), &RenderOptions::default(), Purpose::Animation, None, true).unwrap();
    assert!(matches!(prepared.plan, ViewPlan::Pan { .. }));
    let scale = |k| prepared.layout(k).scale;
    assert!(scale(0) > 3.0 * scale(500), "{} {}", scale(0), scale(500));
    for step in (0..=500).step_by(10) {
        let l = prepared.layout(step);
        for o in &l.obstacles {
            assert!(o.bbox.inside(&l.map), "step {step}: {:?} outside {:?}", o.bbox, l.map);
        }
    }
    // the short run of `straight(50)` fits one view
    let (s, p) = straight(50);
    let prepared = Prepared::new(&s, Some(&p), &RenderOptions::default(), Purpose::Animation, None, true).unwrap();
    assert!(matches!(prepared.plan, ViewPlan::Fixed(_)));
}

#[test]
fn the_sheet_has_a_panel_per_event_time_and_is_deterministic() {
    let (s, p) = straight(50);
    let marks = vec![
        Mark { time: 1.0, text: "A".into() },
        Mark { time: 1.02, text: "B".into() }, // the same step as A
        Mark { time: 3.0, text: "C".into() },
        Mark { time: 99.0, text: "after the end".into() },
    ];
    assert_eq!(sheet_times(&s, &marks), vec![0, 10, 30, 50]);
    let o = RenderOptions { marks, ..Default::default() };
    let png = render_sheet_png(&s, Some(&p), &o).unwrap();
    let pm = decode_png(&png);
    assert_eq!(pm.width(), 1200);
    assert!(pm.height() > 400 && pm.height() < 1400, "{}", pm.height());
    assert_eq!(png, render_sheet_png(&s, Some(&p), &o).unwrap());
    // no marks: the start and the end
    assert_eq!(sheet_times(&s, &[]), vec![0, 50]);
    // more event times than panels: the first ones, the end; the sheet says so
    let many: Vec<Mark> = (1..=20).map(|k| Mark { time: 0.2 * k as f64, text: format!("E{k}") }).collect();
    let times = sheet_times(&s, &many);
    assert_eq!(times.len(), render::MAX_PANELS);
    assert_eq!((times[1], times[10], times[11]), (2, 20, 50));
    let o = RenderOptions { marks: many, ..Default::default() };
    let svgless = render_sheet_png(&s, Some(&p), &o).unwrap();
    assert!(decode_png(&svgless).height() > 1000);
}

#[test]
fn the_font_has_every_printable_ascii_character() {
    use render::font::{glyph, CELL_H};
    let unknown = glyph('\u{263A}');
    assert_eq!(unknown, glyph('?'));
    let mut seen = std::collections::BTreeSet::new();
    for c in ' '..='~' {
        let g = glyph(c);
        assert_eq!(g.len(), CELL_H);
        if c != ' ' {
            assert!(g.iter().any(|&r| r != 0), "{c:?} is blank");
        }
        // letters and digits are told apart
        if c.is_ascii_alphanumeric() {
            assert!(seen.insert(g), "{c:?} looks like another character");
        }
    }
}

#[test]
fn a_time_bar_shows_when_the_events_happen() {
    let (s, p) = straight(50);
    let plain = render_layout(&s, Some(&p), &at(0.5)).unwrap();
    let marks = vec![Mark { time: 1.0, text: "Start".into() }, Mark { time: 3.0, text: "Cross".into() }];
    let o = RenderOptions { marks, ..at(0.5) };
    let with = render_layout(&s, Some(&p), &o).unwrap();
    // a strip under the map, the map itself the same
    assert!(with.height > plain.height);
    assert_eq!(with.map, plain.map);
    // before either event the header names none, but the bar's ticks show both
    let pm = decode_png(&render_png(&s, Some(&p), &o).unwrap());
    let c = rgb(render::style::MARK_NEW);
    let below: usize = (with.map.y1 as u32..pm.height()).flat_map(|y| (0..pm.width()).map(move |x| (x, y))).filter(|&xy| pixel(&pm, xy) == c).count();
    assert!(below > 20, "{below} tick pixels");
    let above: usize = (0..with.map.y0 as u32).flat_map(|y| (0..pm.width()).map(move |x| (x, y))).filter(|&xy| pixel(&pm, xy) == c).count();
    assert_eq!(above, 0, "no event highlighted in the header yet");
}
