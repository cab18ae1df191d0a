//! The maps the generator places entities on: two written by the tool itself (so it works
//! without the corpus), and, when asked, OpenDRIVE files of a folder.

use std::path::{Path, PathBuf};

/// Lane width of the built-in maps, m.
pub const LANE_WIDTH: f64 = 3.5;

/// A place an entity may start: a driving lane of a road, and the span of `s` that keeps it
/// on that road for a while.
#[derive(Debug, Clone, PartialEq)]
pub struct Spot {
    pub road: String,
    /// Driving lanes of the road's first section, right lanes (negative ids) only: the
    /// generator drives along the reference line.
    pub lanes: Vec<i32>,
    pub s_min: f64,
    pub s_max: f64,
}

/// A map: its file name as scenarios refer to it, where it is, and where entities may start.
#[derive(Debug, Clone, PartialEq)]
pub struct MapChoice {
    pub name: String,
    pub path: PathBuf,
    pub spots: Vec<Spot>,
    /// World coordinates are easy on this map (a straight road along +x from the origin): the
    /// generator may use WorldPositions on it.
    pub straight: bool,
}

fn road(id: &str, length: f64, geometry: &str) -> String {
    let lanes = |ids: [i32; 3]| -> String {
        ids.iter()
            .map(|i| format!(r#"<lane id="{i}" type="driving" level="false"><link/><width sOffset="0" a="{LANE_WIDTH}" b="0" c="0" d="0"/><roadMark sOffset="0" type="solid" weight="standard" color="standard" width="0.12"/></lane>"#))
            .collect::<Vec<_>>()
            .join("\n")
    };
    format!(
        r#"<road name="r{id}" length="{length}" id="{id}" junction="-1"><link/>
<type s="0" type="motorway"><speed max="130" unit="km/h"/></type>
<planView>{geometry}</planView>
<elevationProfile/><lateralProfile/>
<lanes><laneSection s="0">
<left>{}</left>
<center><lane id="0" type="none" level="false"><roadMark sOffset="0" type="solid" weight="standard" color="standard" width="0.12"/></lane></center>
<right>{}</right>
</laneSection></lanes></road>"#,
        lanes([3, 2, 1]),
        lanes([-1, -2, -3])
    )
}

/// Plan view of the curved road: 300 m straight, 400 m of a left arc (radius 250 m), 400 m of
/// a right arc back to heading 0, 400 m straight. Arc ends are computed, not typed in.
fn curve_plan_view() -> String {
    let k = 0.004;
    let (mut x, mut y, mut h) = (0.0f64, 0.0f64, 0.0f64);
    let mut out = String::new();
    let mut s = 0.0;
    for (len, curvature) in [(300.0, 0.0), (400.0, k), (400.0, -k), (400.0, 0.0)] {
        let shape = if curvature == 0.0 { "<line/>".to_string() } else { format!(r#"<arc curvature="{curvature}"/>"#) };
        out.push_str(&format!(r#"<geometry s="{s}" x="{x:.10}" y="{y:.10}" hdg="{h:.10}" length="{len}">{shape}</geometry>"#));
        if curvature == 0.0 {
            x += len * h.cos();
            y += len * h.sin();
        } else {
            let h1 = h + curvature * len;
            x += (h1.sin() - h.sin()) / curvature;
            y += (h.cos() - h1.cos()) / curvature;
            h = h1;
        }
        s += len;
    }
    out
}

fn document(name: &str, road: String) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
<header revMajor="1" revMinor="6" name="{name}" version="1.00" north="0" south="0" east="0" west="0"/>
{road}
</OpenDRIVE>
"#
    )
}

/// The built-in maps, written into `dir`: a 2 km straight road and a road that curves left
/// then right, both with three lanes each way.
pub fn builtin(dir: &Path) -> std::io::Result<Vec<MapChoice>> {
    let straight = document("straight", road("1", 2000.0, r#"<geometry s="0" x="0" y="0" hdg="0" length="2000"><line/></geometry>"#));
    let curve = document("curve", road("1", 1500.0, &curve_plan_view()));
    let mut out = Vec::new();
    for (name, text, straight) in [("straight", straight, true), ("curve", curve, false)] {
        let path = dir.join(format!("{name}.xodr"));
        std::fs::write(&path, text)?;
        let length = if straight { 2000.0 } else { 1500.0 };
        out.push(MapChoice {
            name: format!("{name}.xodr"),
            path,
            spots: vec![Spot { road: "1".into(), lanes: vec![-1, -2, -3], s_min: 20.0, s_max: length * 0.4 }],
            straight,
        });
    }
    Ok(out)
}

/// Maps of a folder (e.g. the corpus' OpenDRIVE files): every road outside junctions, at least
/// 150 m long, with a right driving lane, is a spot. Files that do not load are passed over.
pub fn from_folder(dir: &Path, max_maps: usize) -> Vec<MapChoice> {
    let mut files: Vec<PathBuf> = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xodr")) {
                files.push(p);
            }
        }
    }
    files.sort();
    let mut out = Vec::new();
    for path in files {
        if out.len() >= max_maps {
            break;
        }
        let Ok(loaded) = opendrive::network::load(&path) else { continue };
        let net = loaded.network;
        if net.header.offset.is_some() {
            continue;
        }
        let mut spots = Vec::new();
        for r in &net.roads {
            if r.junction.is_some() || r.length < 150.0 || r.lane_sections.len() != 1 {
                continue;
            }
            let Some(sec) = r.lane_sections.first() else { continue };
            let lanes: Vec<i32> = sec.right.iter().filter(|l| l.kind == opendrive::LaneType::Driving).map(|l| l.id).collect();
            if lanes.is_empty() {
                continue;
            }
            spots.push(Spot { road: r.id.clone(), lanes, s_min: 10.0, s_max: (r.length * 0.4).max(10.0) });
        }
        if !spots.is_empty() {
            let name = path.to_string_lossy().to_string();
            out.push(MapChoice { name, path, spots, straight: false });
        }
    }
    out
}
