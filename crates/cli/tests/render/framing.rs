//! `osc2cr render` frames the action and says what is shown, checked from each picture's own
//! geometry: `--layout` writes where every road user and its label are, in pixels, and the PNG
//! is read back to see that the boxes are where the layout says. Corpus scenarios and the
//! shipped example; the sheet and the event marks.

use std::path::{Path, PathBuf};

use crate::common::png::Png;
use crate::common::{assert_ok as ok, example, osc2cr, s, tmp};
use render::style;
use serde_json::Value;

fn rect(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

fn inside(a: &[f64], b: &[f64]) -> bool {
    a[0] >= b[0] && a[1] >= b[1] && a[2] <= b[2] && a[3] <= b[3]
}

/// Renders `xosc` at `time` with its layout; checks every vehicle is at least 30 px long, its
/// box and label inside the map area, the label naming it, and the PNG showing its colour at its
/// centre and text in its label. Returns (name, length in px) of each road user.
fn check_still(xosc: &Path, time: f64, dir: &Path) -> Vec<(String, f64)> {
    let stem = xosc.file_stem().unwrap().to_str().unwrap();
    let png = dir.join(format!("{stem}.png"));
    let json = dir.join(format!("{stem}.json"));
    ok(&osc2cr(&["render", s(xosc), "-o", s(&png), "--time", &time.to_string(), "--layout", s(&json)]));
    let layout: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let pic = Png::read(&png);
    assert_eq!((u64::from(pic.width), u64::from(pic.height)), (layout["width"].as_u64().unwrap(), layout["height"].as_u64().unwrap()));
    let map = rect(&layout["map"]);
    let obstacles = layout["obstacles"].as_array().unwrap();
    assert!(obstacles.len() >= 2, "{stem}: {obstacles:?}");
    assert_eq!(obstacles.iter().filter(|o| o["ego"] == true).count(), 1, "{stem}: one ego");
    let mut out = Vec::new();
    for o in obstacles {
        let name = o["name"].as_str().unwrap_or_default().to_string();
        let what = format!("{stem} at {time} s: {name}");
        let length = o["length_px"].as_f64().unwrap();
        let kind = o["type"].as_str().unwrap();
        if !["pedestrian", "bicycle"].contains(&kind) {
            assert!(length >= 30.0, "{what} is {length:.1} px long");
        }
        let b = rect(&o["box"]);
        assert!(inside(&b, &map), "{what}: box {b:?} outside the map area {map:?}");
        let label = &o["label"];
        let text = label["text"].as_str().unwrap();
        assert!(text.starts_with(&format!("{name} (")), "{what}: label {text:?}");
        let lb = rect(&label["box"]);
        assert!(inside(&lb, &map), "{what}: label {lb:?} outside the map area {map:?}");
        assert!(pic.count_in(&lb, style::TEXT) > 10 * text.len(), "{what}: no text in its label");
        let c = rect(&o["center"]);
        let fill = if o["ego"] == true {
            style::EGO
        } else {
            let t = commonroad::DynamicObstacleType::ALL.iter().find(|t| t.as_str() == kind).unwrap();
            style::dynamic_color(*t)
        };
        assert_eq!(pic.at(c[0], c[1]), [fill.r, fill.g, fill.b], "{what}: its colour at its centre");
        out.push((name, length));
    }
    out
}

fn corpus(rel: &str) -> Option<PathBuf> {
    testkit::shared_dir().map(|d| d.join("corpus").join(rel))
}

#[test]
fn cut_in_still_at_8_s_shows_every_vehicle_large_and_labelled() {
    let dir = tmp("render_framing", "cut_in");
    let ours = check_still(&example(), 8.0, &dir);
    assert_eq!(ours.len(), 3, "{ours:?}");
    eprintln!("examples/cut_in.xosc at 8 s: {ours:?}");
    let Some(esmini) = corpus("esmini/xosc/cut-in.xosc") else { return };
    let theirs = check_still(&esmini, 8.0, &dir);
    eprintln!("esmini cut-in.xosc at 8 s: {theirs:?}");
}

#[test]
fn corpus_stills_show_every_vehicle_large_and_labelled() {
    let dir = tmp("render_framing", "corpus");
    // two junctions (crossing, left turn across path) and an arrival at an intersection
    for (rel, time) in [
        ("osc-examples-1.2/CloseVehicleCrossing.xosc", 12.0),
        ("esmini/xosc/ltap-od.xosc", 4.0),
        ("osc-examples-1.2/SynchronizedArrivalToIntersection.xosc", 4.0),
    ] {
        let Some(xosc) = corpus(rel) else { return };
        let sizes = check_still(&xosc, time, &dir);
        eprintln!("{rel} at {time} s: {sizes:?}");
    }
}

/// Frames of a GIF (RGBA) that hold the highlight colour of a fresh event.
fn frames_with_marks(path: &Path) -> (usize, usize) {
    let mut opts = gif::DecodeOptions::new();
    opts.set_color_output(gif::ColorOutput::RGBA);
    let bytes = std::fs::read(path).unwrap();
    let mut d = opts.read_info(bytes.as_slice()).unwrap();
    let c = style::MARK_NEW;
    let (mut n, mut marked) = (0, 0);
    while let Some(f) = d.read_next_frame().unwrap() {
        n += 1;
        if f.buffer.chunks_exact(4).any(|p| p[..3] == [c.r, c.g, c.b]) {
            marked += 1;
        }
    }
    (n, marked)
}

#[test]
fn sheets_and_event_marks_of_two_corpus_scenarios() {
    let dir = tmp("render_framing", "sheets");
    for (rel, first_event) in [("esmini/xosc/cut-in.xosc", "CutInEvent"), ("esmini/xosc/ltap-od.xosc", "")] {
        let Some(xosc) = corpus(rel) else { return };
        let stem = xosc.file_stem().unwrap().to_str().unwrap();
        let sheet = dir.join(format!("{stem}_sheet.png"));
        ok(&osc2cr(&["render", s(&xosc), "-o", s(&sheet), "--sheet"]));
        let pic = Png::read(&sheet);
        assert_eq!(pic.width, 1200);
        let all = [0.0, 0.0, f64::from(pic.width), f64::from(pic.height)];
        assert!(pic.count_in(&all, style::MARK_NEW) > 500, "{rel}: no event highlighted on the sheet");
        assert!(pic.count_in(&all, style::EGO) > 200, "{rel}: no ego on the sheet");
        // the same bytes again
        let again = dir.join(format!("{stem}_sheet2.png"));
        ok(&osc2cr(&["render", s(&xosc), "-o", s(&again), "--sheet"]));
        assert_eq!(std::fs::read(&sheet).unwrap(), std::fs::read(&again).unwrap());

        let gif = dir.join(format!("{stem}.gif"));
        ok(&osc2cr(&["render", s(&xosc), "-o", s(&gif), "--width", "600"]));
        let (n, marked) = frames_with_marks(&gif);
        assert!(n > 10 && marked >= 2, "{rel}: {marked} of {n} frames mark an event");

        if !first_event.is_empty() {
            // a still just after the event names it in the header
            let svg = dir.join(format!("{stem}.svg"));
            ok(&osc2cr(&["render", s(&xosc), "-o", s(&svg), "--time", "6.5"]));
            let text = std::fs::read_to_string(&svg).unwrap();
            assert!(text.contains(&format!(" s {first_event}</text>")), "{rel}: {first_event} not in the header");
        }
    }
}

#[test]
fn follow_region_and_whole_map_choose_the_view() {
    let dir = tmp("render_framing", "choose");
    let xosc = example();
    let json = dir.join("l.json");
    let layout = |args: &[&str]| -> Value {
        let png = dir.join("x.png");
        let mut all = vec!["render", s(&xosc), "-o", s(&png), "--layout", s(&json)];
        all.extend(args);
        ok(&osc2cr(&all));
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap()
    };
    let l = layout(&["--time", "5", "--follow", "Ego"]);
    let map = rect(&l["map"]);
    let ego = l["obstacles"].as_array().unwrap().iter().find(|o| o["name"] == "Ego").unwrap();
    let c = rect(&ego["center"]);
    assert!((c[0] - 0.5 * (map[0] + map[2])).abs() < 1.0 && (c[1] - 0.5 * (map[1] + map[3])).abs() < 1.0, "{c:?} {map:?}");
    let l = layout(&["--region", "-10,-20,90,30"]);
    assert_eq!(rect(&l["world"])[0], -10.0);
    let whole = layout(&["--whole-map"]);
    let action = layout(&[]);
    assert!(whole["pixels_per_metre"].as_f64().unwrap() < action["pixels_per_metre"].as_f64().unwrap());
    // bad requests: exit 2 with the option named
    for (args, expect) in [
        (vec!["--follow", "Nobody"], "--follow Nobody"),
        (vec!["--region", "1,2,3"], "--region"),
        (vec!["--follow", "Ego", "--whole-map"], "cannot be used with"),
    ] {
        let png = dir.join("bad.png");
        let mut all = vec!["render", s(&xosc), "-o", s(&png)];
        all.extend(args.iter().copied());
        let o = osc2cr(&all);
        assert_eq!(o.status.code(), Some(2), "{all:?}");
        assert!(String::from_utf8_lossy(&o.stderr).contains(expect), "{all:?}: {}", String::from_utf8_lossy(&o.stderr));
    }
}
