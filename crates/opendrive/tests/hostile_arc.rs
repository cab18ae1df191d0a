//! A long reference line wound into a very tight arc, with a lane whose width explodes:
//! the spatial index must stay small and fast (it used to take 0.6 s for 300 m, 76 s for
//! 100 km, in release).

use opendrive::parse_str;
use std::path::Path;
use std::time::{Duration, Instant};

fn tight_arc(length: f64) -> String {
    format!(
        r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
      <road id="1" length="{length}" junction="-1">
        <planView><geometry s="0" x="0" y="0" hdg="0" length="{length}"><arc curvature="10"/></geometry></planView>
        <lanes><laneSection s="0">
          <left><lane id="1" type="driving"><width sOffset="0" a="3" b="1e6" c="-1e3" d="1"/></lane></left>
          <center><lane id="0" type="none"/></center>
          <right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
        </laneSection></lanes>
      </road></OpenDRIVE>"#
    )
}

fn load_time(length: f64) -> (Duration, opendrive::Loaded) {
    let text = tight_arc(length);
    let t0 = Instant::now();
    let loaded = parse_str(&text, Path::new("tight.xodr")).expect("parses");
    (t0.elapsed(), loaded)
}

#[test]
fn a_3_km_arc_of_radius_10_cm_loads_quickly() {
    // Debug builds are ~20x slower than release; 3 km needs ~34,000 samples (1 cm chord
    // error at radius 0.1 m), all inside a 1 km square because of the wide lane.
    let (t, loaded) = load_time(3000.0);
    assert!(t < Duration::from_millis(700), "took {t:?}");
    // Still a usable network: a point on the right lane is found on road 0, on the lane,
    // at an s whose pose is that point. The right lane's centre is 1.75 m right of the
    // reference line, i.e. on the circle of radius 0.1 + 1.75 around the arc's centre.
    let net = &loaded.network;
    let s = 1234.567;
    let p = net.lane_to_world(0, -1, s, 0.0).expect("lane -1 exists");
    let centre_y = 0.1;
    let r = (p.x * p.x + (p.y - centre_y) * (p.y - centre_y)).sqrt();
    assert!((r - 1.85).abs() < 1e-9, "radius {r}");
    let found = net.world_to_lane(p.x, p.y, None).expect("found");
    assert_eq!(found.road, 0);
    assert!(found.is_on_road());
}

#[test]
fn a_100_km_arc_is_sampled_coarser_with_a_warning() {
    let (t, loaded) = load_time(100_000.0);
    // release: ~0.15 s; debug stays within a few seconds
    assert!(t < Duration::from_secs(8), "took {t:?}");
    let w = loaded.warnings.iter().find(|w| w.message.contains("sampled coarser")).expect("a warning");
    assert_eq!((w.location.line, w.location.col), (2, 7), "{w}");
}
