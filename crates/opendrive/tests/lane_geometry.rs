//! Lane borders, lane centres, world positions and links on small hand-written maps,
//! checked against hand computation.

use opendrive::{parse_str, ContactPoint, LaneRef, TrafficRule};
use std::path::Path;

const MAP: &str = r#"<?xml version="1.0"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="6" name="t"><offset x="0" y="0" z="0" hdg="0"/></header>
  <road id="A" length="100" junction="-1" rule="LHT">
    <link><successor elementType="road" elementId="B" contactPoint="start"/></link>
    <type s="0" type="motorway"><speed max="130" unit="km/h"/></type>
    <planView><geometry s="0" x="10" y="5" hdg="0.3" length="100"><line/></geometry></planView>
    <elevationProfile><elevation s="0" a="1" b="0.02" c="0" d="0"/></elevationProfile>
    <lanes>
      <laneOffset s="0" a="0.5" b="0" c="0" d="0"/>
      <laneSection s="0">
        <left>
          <lane id="2" type="sidewalk"><width sOffset="0" a="2" b="0.01" c="0" d="0"/></lane>
          <lane id="1" type="driving"><link><successor id="1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
        </left>
        <center><lane id="0" type="none"/></center>
        <right>
          <lane id="-1" type="driving"><link><successor id="-1"/></link>
            <width sOffset="0" a="3" b="0" c="0" d="0"/><width sOffset="50" a="3" b="0" c="0.001" d="0"/></lane>
          <lane id="-2" type="border"><border sOffset="0" a="-7" b="0" c="0" d="0"/></lane>
        </right>
      </laneSection>
    </lanes>
  </road>
  <road id="B" length="157.07963267948966" junction="-1">
    <link><predecessor elementType="road" elementId="A" contactPoint="end"/><successor elementType="junction" elementId="J"/></link>
    <planView><geometry s="0" x="105.5336489125606" y="34.552020666133956" hdg="0.3" length="157.07963267948966"><arc curvature="0.01"/></geometry></planView>
    <lanes>
      <laneSection s="0">
        <left><lane id="1" type="driving"><link><predecessor id="1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
        <center><lane id="0" type="none"/></center>
        <right><lane id="-1" type="driving"><link><predecessor id="-1"/></link><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right>
      </laneSection>
    </lanes>
  </road>
  <road id="C" length="20" junction="J">
    <link><predecessor elementType="road" elementId="B" contactPoint="end"/></link>
    <planView><geometry s="0" x="171.51527715898723" y="159.6376902448285" hdg="1.8707963267948966" length="20"><line/></geometry></planView>
    <lanes><laneSection s="0">
      <center><lane id="0" type="none"/></center>
      <right><lane id="-1" type="driving"><link><predecessor id="-1"/></link><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right>
    </laneSection></lanes>
  </road>
  <junction id="J" name="j">
    <connection id="0" incomingRoad="B" connectingRoad="C" contactPoint="start"><laneLink from="-1" to="-1"/></connection>
  </junction>
</OpenDRIVE>"#;

fn net() -> opendrive::RoadNetwork {
    parse_str(MAP, Path::new("mem.xodr")).expect("map parses").network
}

#[test]
fn width_borders_are_cumulative_from_the_lane_offset() {
    let n = net();
    let a = n.road("A").expect("road A");
    for &s in &[0.0, 20.0, 49.0, 70.0, 100.0] {
        let base = 0.5;
        let l1 = a.lane_borders(0, 1, s).expect("lane 1");
        assert!((l1.inner - base).abs() < 1e-12 && (l1.outer - (base + 3.5)).abs() < 1e-12);
        let l2 = a.lane_borders(0, 2, s).expect("lane 2");
        assert!((l2.outer - (base + 3.5 + 2.0 + 0.01 * s)).abs() < 1e-12, "s={s}");
        let w1 = if s < 50.0 { 3.0 } else { 3.0 + 0.001 * (s - 50.0).powi(2) };
        let r1 = a.lane_borders(0, -1, s).expect("lane -1");
        assert!((r1.outer - (base - w1)).abs() < 1e-12, "s={s}");
        // border record: outer t = lane offset + border value
        let r2 = a.lane_borders(0, -2, s).expect("lane -2");
        assert!((r2.outer - (base - 7.0)).abs() < 1e-12 && (r2.inner - r1.outer).abs() < 1e-12);
        assert!((a.lane_center_t(0, 1, s).unwrap_or(f64::NAN) - (base + 1.75)).abs() < 1e-12);
    }
    assert!(a.lane_borders(0, 3, 10.0).is_none());
}

#[test]
fn lane_to_world_on_a_line_and_an_arc() {
    let n = net();
    let ia = n.road_index("A").expect("A");
    // line: reference point at s plus t along the left normal
    let (s, off) = (40.0, 0.25);
    let p = n.lane_to_world(ia, 1, s, off).expect("pose");
    let t = 0.5 + 1.75 + off;
    let (h, x0, y0) = (0.3f64, 10.0, 5.0);
    assert!((p.x - (x0 + s * h.cos() - t * h.sin())).abs() < 1e-12);
    assert!((p.y - (y0 + s * h.sin() + t * h.cos())).abs() < 1e-12);
    assert!((p.z - (1.0 + 0.02 * s)).abs() < 1e-12);
    assert!((p.heading - 0.3).abs() < 1e-15);
    // B: arc of radius 100 starting where A ends; a point at t lies at radius 100 - t
    let ib = n.road_index("B").expect("B");
    let (bx, by) = (10.0 + 100.0 * h.cos(), 5.0 + 100.0 * h.sin());
    let (cx, cy) = (bx - 100.0 * h.sin(), by + 100.0 * h.cos());
    for &s in &[0.0, 30.0, 78.5, 157.0] {
        let q = n.lane_to_world(ib, -1, s, 0.0).expect("pose");
        let r = ((q.x - cx).powi(2) + (q.y - cy).powi(2)).sqrt();
        assert!((r - 101.5).abs() < 1e-9, "s={s} r={r}");
        assert!((q.heading - (0.3 + 0.01 * s)).abs() < 1e-12);
    }
}

#[test]
fn world_to_lane_recovers_road_coordinates() {
    let n = net();
    let ib = n.road_index("B").expect("B");
    let p = n.lane_to_world(ib, 1, 60.0, -0.4).expect("pose");
    let q = n.world_to_lane(p.x, p.y, None).expect("found");
    assert_eq!((q.road, q.lane_id), (ib, 1));
    assert!((q.s - 60.0).abs() < 1e-9 && (q.offset + 0.4).abs() < 1e-9 && q.is_on_road());
    // a point 10 m beyond the right edge of road B: nearest lane -1, distance 10
    let far = n.road_to_world(ib, 80.0, -13.0).expect("pose");
    let r = n.world_to_lane(far.x, far.y, None).expect("found");
    assert_eq!((r.road, r.lane_id), (ib, -1));
    assert!((r.distance - 10.0).abs() < 1e-9, "{r:?}");
    assert!(n.lanes_containing(far.x, far.y).is_empty());
}

#[test]
fn header_offset_moves_the_roads_as_esmini_does() {
    // esmini's OpenDrive::LoadOpenDriveFile: each geometry start is shifted by (x, y), then
    // rotated by hdg about the origin; the heading turns by hdg; elevations rise by z.
    let map = r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"><offset x="-1000" y="-500" z="2" hdg="0.5"/></header>
<road id="1" length="100" junction="-1"><planView><geometry s="0" x="1010" y="520" hdg="0.25" length="100"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="1" b="0" c="0" d="0"/></elevationProfile>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;
    let n = parse_str(map, Path::new("offset.xodr")).expect("parses").network;
    let off = n.header.offset.expect("offset");
    assert_eq!((off.x, off.y, off.z, off.hdg), (-1000.0, -500.0, 2.0, 0.5));
    // start: (1010 - 1000, 520 - 500) = (10, 20), rotated by 0.5 rad
    let (s, c) = 0.5f64.sin_cos();
    let p = n.road_to_world(0, 0.0, 0.0).expect("pose");
    assert!((p.x - (10.0 * c - 20.0 * s)).abs() < 1e-9 && (p.y - (10.0 * s + 20.0 * c)).abs() < 1e-9, "{p:?}");
    assert!((p.heading - 0.75).abs() < 1e-12, "heading 0.25 + 0.5: {p:?}");
    assert!((p.z - 3.0).abs() < 1e-12, "elevation 1 + 2: {p:?}");
    assert_eq!(off.apply(1.0, 2.0, 3.0).2, 5.0);
}

#[test]
fn model_fields_are_read() {
    let n = net();
    let a = n.road("A").expect("A");
    assert_eq!(a.rule, TrafficRule::LeftHand);
    assert_eq!(n.road("B").map(|r| r.rule), Some(TrafficRule::RightHand));
    let t = a.type_at(10.0).expect("type");
    assert_eq!(t.kind, opendrive::RoadKind::Motorway);
    let v = t.speed.as_ref().and_then(|s| s.max_mps).expect("speed");
    assert!((v - 130.0 / 3.6).abs() < 1e-12);
    assert_eq!(n.road("C").and_then(|r| r.junction.clone()).as_deref(), Some("J"));
    assert_eq!(a.lane_sections[0].left.iter().map(|l| l.id).collect::<Vec<_>>(), vec![1, 2]);
    assert_eq!(a.lane_sections[0].lane(2).map(|l| l.kind), Some(opendrive::LaneType::Sidewalk));
}

#[test]
fn links_across_roads_and_junctions() {
    let n = net();
    let (ia, ib, ic) = (n.road_index("A").unwrap_or(9), n.road_index("B").unwrap_or(9), n.road_index("C").unwrap_or(9));
    let succ = n.lane_successors(LaneRef { road: ia, section: 0, lane: -1 });
    assert_eq!(succ, vec![LaneRef { road: ib, section: 0, lane: -1 }]);
    let back = n.lane_predecessors(LaneRef { road: ib, section: 0, lane: 1 });
    assert_eq!(back, vec![LaneRef { road: ia, section: 0, lane: 1 }]);
    // B's end → junction J → C's start, lane -1 → -1 (found both via the connection and via C's own link)
    let j = n.lane_successors(LaneRef { road: ib, section: 0, lane: -1 });
    assert_eq!(j, vec![LaneRef { road: ic, section: 0, lane: -1 }]);
    assert!(n.lane_successors(LaneRef { road: ib, section: 0, lane: 1 }).is_empty());
    let ends = n.roads_at(ib, ContactPoint::End);
    assert_eq!(ends, vec![opendrive::RoadEnd { road: ic, contact: ContactPoint::Start }]);
    let pred_c = n.lane_predecessors(LaneRef { road: ic, section: 0, lane: -1 });
    assert_eq!(pred_c, vec![LaneRef { road: ib, section: 0, lane: -1 }]);
}

/// `<lane><height>` records are kept sorted (equal sOffsets in file order, as esmini's
/// Lane::AddLaneHeight inserts them) and read as esmini's Lane::GetHeightBySAndOffset: the
/// record at s (the first before it starts), interpolated towards the next one, and across the
/// lane from the inner border (0) to the outer one (1), clamped.
#[test]
fn lane_heights_interpolate_along_and_across_the_lane() {
    let map = r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6" name="h"/>
  <road id="1" length="100" junction="-1">
    <planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
    <lanes><laneSection s="0">
      <center><lane id="0" type="none"/></center>
      <right><lane id="-1" type="sidewalk"><width sOffset="0" a="2" b="0" c="0" d="0"/>
        <height sOffset="50" inner="0.3" outer="0.5"/><height sOffset="10" inner="0.1" outer="0.2"/></lane></right>
    </laneSection></lanes>
  </road>
</OpenDRIVE>"#;
    let loaded = parse_str(map, Path::new("h.xodr")).expect("parses");
    let lane = &loaded.network.roads[0].lane_sections[0].right[0];
    let at: Vec<f64> = lane.heights.iter().map(|h| h.s_offset).collect();
    assert_eq!(at, [10.0, 50.0], "sorted by sOffset");
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    // lane −1: its inner border is the reference line, so an offset to the right (−) is outward
    assert!(close(lane.height_at(10.0, 0.0, 2.0), 0.15), "the middle at the first record");
    assert!(close(lane.height_at(30.0, -1.0, 2.0), 0.35), "the outer border half way: 0.2 + (0.5 − 0.2)/2");
    assert!(close(lane.height_at(30.0, 1.0, 2.0), 0.2), "the inner border half way: 0.1 + (0.3 − 0.1)/2");
    assert!(close(lane.height_at(80.0, 3.0, 2.0), 0.3), "beyond the inner border: clamped, the last record");
    assert!(close(lane.height_at(0.0, 0.0, 2.0), 0.0875), "before the first record: extrapolated, 0.15 − (0.4 − 0.15)/4");
}
