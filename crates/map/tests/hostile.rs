//! Hostile geometry converts without panicking and in bounded time.

/// Converts one road `length` m long on an arc of `curvature`, with the `left` and `right`
/// lanes in its one lane section (the centre lane given).
fn arc_road(length: f64, curvature: f64, left: &str, right: &str) -> map::MapResult {
    let xodr = format!(
        r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
      <road id="1" length="{length}" junction="-1">
        <planView><geometry s="0" x="0" y="0" hdg="0" length="{length}"><arc curvature="{curvature}"/></geometry></planView>
        <lanes><laneSection s="0">
          {left}
          <center><lane id="0" type="none"/></center>
          {right}
        </laneSection></lanes>
      </road></OpenDRIVE>"#
    );
    let t0 = std::time::Instant::now();
    let loaded = opendrive::parse_str(&xodr, std::path::Path::new("hostile.xodr")).expect("parses");
    eprintln!("load {:?}", t0.elapsed());
    map::convert(&loaded.network, &map::MapOptions::default())
}

#[test]
fn extreme_curvature_and_length_do_not_panic() {
    let left = r#"<left><lane id="1" type="driving"><width sOffset="0" a="3" b="1e6" c="-1e3" d="1"/></lane></left>"#;
    let right = r#"<right><lane id="-1" type="driving"><width sOffset="0" a="-5" b="0" c="0" d="0"/></lane>
                 <lane id="-2" type="rail"><width sOffset="0" a="2" b="0" c="0" d="0"/></lane></right>"#;
    let t0 = std::time::Instant::now();
    let r = arc_road(300.0, 10.0, left, right);
    eprintln!("convert {:?}", t0.elapsed());
    assert!(t0.elapsed().as_secs() < 30);
    // lane -1 has negative width everywhere (clamped to zero → skipped), lane -2 is a rail
    assert!(r.warnings.iter().any(|w| w.message.contains("zero width")));
    assert!(r.warnings.iter().any(|w| w.message.contains("`rail`")));
    for l in &r.network.lanelets {
        // the station budget per section (plus one pending half per recursion level)
        assert!(l.bounds.len() <= map::MAX_STATIONS + 64, "{}", l.bounds.len());
    }
}

#[test]
fn a_border_that_needs_too_many_points_is_capped_and_said() {
    // a cubic width of 5·s³ m on an arc (found by fuzzing): at 5 mm its border would need
    // ~100,000 points
    let r = arc_road(1175.0, 0.0015, "", r#"<right><lane id="-1" type="driving"><width sOffset="0" a="3.4" b="0" c="0" d="5"/></lane></right>"#);
    assert!(r.network.lanelets.iter().all(|l| l.bounds.len() <= map::MAX_STATIONS + 64));
    let most = r.network.lanelets.iter().map(|l| l.bounds.len()).max().unwrap_or(0);
    assert!(r.warnings.iter().any(|w| w.message.contains("sampled at that cap")), "{most} points: {:?}", r.warnings);
}
