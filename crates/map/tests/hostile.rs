//! Hostile geometry converts without panicking and in bounded time.

#[test]
fn extreme_curvature_and_length_do_not_panic() {
    let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
      <road id="1" length="300" junction="-1">
        <planView><geometry s="0" x="0" y="0" hdg="0" length="300"><arc curvature="10"/></geometry></planView>
        <lanes><laneSection s="0">
          <left><lane id="1" type="driving"><width sOffset="0" a="3" b="1e6" c="-1e3" d="1"/></lane></left>
          <center><lane id="0" type="none"/></center>
          <right><lane id="-1" type="driving"><width sOffset="0" a="-5" b="0" c="0" d="0"/></lane>
                 <lane id="-2" type="rail"><width sOffset="0" a="2" b="0" c="0" d="0"/></lane></right>
        </laneSection></lanes>
      </road></OpenDRIVE>"#;
    let t0 = std::time::Instant::now();
    let loaded = opendrive::parse_str(xodr, std::path::Path::new("hostile.xodr")).expect("parses");
    eprintln!("load {:?}", t0.elapsed());
    let t0 = std::time::Instant::now();
    let r = map::convert(&loaded.network, &map::MapOptions::default());
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
    let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
      <road id="1" length="1175" junction="-1">
        <planView><geometry s="0" x="0" y="0" hdg="0" length="1175"><arc curvature="0.0015"/></geometry></planView>
        <lanes><laneSection s="0">
          <center><lane id="0" type="none"/></center>
          <right><lane id="-1" type="driving"><width sOffset="0" a="3.4" b="0" c="0" d="5"/></lane></right>
        </laneSection></lanes>
      </road></OpenDRIVE>"#;
    let loaded = opendrive::parse_str(xodr, std::path::Path::new("cubic.xodr")).expect("parses");
    let r = map::convert(&loaded.network, &map::MapOptions::default());
    assert!(r.network.lanelets.iter().all(|l| l.bounds.len() <= map::MAX_STATIONS + 64));
    let most = r.network.lanelets.iter().map(|l| l.bounds.len()).max().unwrap_or(0);
    assert!(r.warnings.iter().any(|w| w.message.contains("sampled at that cap")), "{most} points: {:?}", r.warnings);
}
