//! `osc2cr render` end to end: CommonRoad files, converted OpenSCENARIO files and corpus maps
//! drawn as PNG, SVG and GIF; the files decode, have plausible sizes and real content.

use std::path::{Path, PathBuf};

use crate::common::png::Png;
use crate::common::{assert_ok as ok, osc2cr, s, tmp};

use render::style;

fn out_dir(name: &str) -> PathBuf {
    tmp("render", name)
}

/// A real picture: the asked width, a height within the aspect limits (the map area's, plus
/// the header and footer strips), many colours, and at least 1/`road_share` of it road surface.
fn plausible_with(png: &Png, width: u32, road_share: usize) {
    assert_eq!(png.width, width);
    let aspect = f64::from(png.height) / f64::from(width);
    assert!((0.24..=2.1).contains(&aspect), "aspect {aspect}");
    assert!(png.colors().len() > 10, "only {} colours", png.colors().len());
    assert!(png.count(style::ROAD) * road_share > png.rgba.len() / 4, "little road");
}

fn plausible(png: &Png, width: u32) {
    plausible_with(png, width, 200)
}

fn gif_frames(path: &Path) -> usize {
    let bytes = std::fs::read(path).unwrap();
    let mut d = gif::DecodeOptions::new().read_info(bytes.as_slice()).unwrap();
    let mut n = 0;
    while d.read_next_frame().unwrap().is_some() {
        n += 1;
    }
    n
}

fn minimal() -> Option<PathBuf> {
    testkit::shared_dir().map(|d| d.join("tools/examples/minimal_2020a.xml"))
}

#[test]
fn minimal_example_as_png_svg_gif_and_several_stills() {
    let Some(xml) = minimal() else { return };
    let dir = out_dir("minimal");
    let png = dir.join("m.png");
    ok(&osc2cr(&["render", s(&xml), "-o", s(&png), "--ego", "21"]));
    let p = Png::read(&png);
    plausible(&p, 1200);
    assert!(p.count(style::EGO) > 50, "the chosen ego is drawn");

    let several = dir.join("s.png");
    ok(&osc2cr(&["render", s(&xml), "-o", s(&several), "--time", "0", "--time", "0.3", "--width", "600"]));
    let (a, b) = (Png::read(&dir.join("s_t0.0.png")), Png::read(&dir.join("s_t0.3.png")));
    plausible(&a, 600);
    assert_ne!(a.rgba, b.rgba, "the car moved");
    assert!(!several.exists());

    let svg = dir.join("m.svg");
    ok(&osc2cr(&["render", s(&xml), "-o", s(&svg), "--time", "0.1"]));
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(doc.root_element().attribute("width"), Some("1200"));
    assert!(text.contains(">t = 0.1 s</text>"));

    let gif = dir.join("m.gif");
    ok(&osc2cr(&["render", s(&xml), "-o", s(&gif)]));
    // the car has states at steps 0..=3
    assert_eq!(gif_frames(&gif), 4);
}

#[test]
fn bad_requests_exit_2_with_a_reason() {
    let Some(xml) = minimal() else { return };
    let dir = out_dir("bad");
    let cases: [(Vec<String>, &str); 4] = [
        (vec![s(&xml).into(), "-o".into(), s(&dir.join("x.jpg")).into()], ".png, .svg or .gif"),
        (vec![s(&xml).into(), "-o".into(), s(&dir.join("x.png")).into(), "--ego".into(), "999".into()], "--ego 999"),
        (vec!["/no/such/file.xml".into(), "-o".into(), s(&dir.join("x.png")).into()], "/no/such/file.xml"),
        (vec![s(&xml).into(), "-o".into(), s(&dir.join("x.gif")).into(), "--time".into(), "1".into()], "--time"),
    ];
    for (args, expect) in cases {
        let mut all = vec!["render".to_string()];
        all.extend(args);
        let refs: Vec<&str> = all.iter().map(String::as_str).collect();
        let o = osc2cr(&refs);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains(expect), "{all:?}: {err}");
    }
    assert!(!dir.join("x.png").exists(), "nothing written on failure");
}

#[test]
fn corpus_maps_render() {
    let Some(shared) = testkit::shared_dir() else { return };
    let dir = out_dir("maps");
    for name in ["esmini/xodr/fabriksgatan.xodr", "esmini/xodr/multi_intersections.xodr", "esmini/xodr/curves.xodr"] {
        let xodr = shared.join("corpus").join(name);
        let stem = xodr.file_stem().unwrap().to_str().unwrap().to_string();
        let xml = dir.join(format!("{stem}.xml"));
        ok(&osc2cr(&["map", s(&xodr), "-o", s(&xml)]));
        let png = dir.join(format!("{stem}.png"));
        ok(&osc2cr(&["render", s(&xml), "-o", s(&png), "--width", "800"]));
        let size = std::fs::metadata(&png).unwrap().len();
        assert!((5_000..5_000_000).contains(&size), "{name}: {size} bytes");
        plausible(&Png::read(&png), 800);
        let svg = dir.join(format!("{stem}.svg"));
        ok(&osc2cr(&["render", s(&xml), "-o", s(&svg), "--width", "800"]));
        roxmltree::Document::parse(&std::fs::read_to_string(&svg).unwrap()).unwrap();
    }
}

#[test]
fn pedestrian_collision_converts_and_renders() {
    let Some(shared) = testkit::shared_dir() else { return };
    let xosc = shared.join("corpus/esmini/xosc/pedestrian_collision.xosc");
    let dir = out_dir("pedestrian");
    let png = dir.join("p.png");
    // 5.2 s: the pedestrian is in the car's lane just ahead of it; at 5.5 s (the collision)
    // the car's box covers it.
    ok(&osc2cr(&["render", s(&xosc), "-o", s(&png), "--time", "5.2"]));
    let p = Png::read(&png);
    // the whole junction map fills the picture: thin roads
    plausible_with(&p, 1200, 1000);
    // the converter keeps the ego as an obstacle starting at the planning problem: found
    assert!(p.count(style::EGO) > 0, "ego drawn");
    let ped = style::dynamic_color(commonroad::DynamicObstacleType::Pedestrian);
    assert!(p.count(ped) > 0, "pedestrian drawn");
    let gif = dir.join("p.gif");
    ok(&osc2cr(&["render", s(&xosc), "-o", s(&gif), "--width", "600"]));
    assert!(gif_frames(&gif) > 1);
    assert!(std::fs::metadata(&gif).unwrap().len() < 10_000_000);
}
