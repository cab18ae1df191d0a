//! (road, lane, s, offset) → world → (road, lane, s, t) → world on every corpus map, at
//! seeded random stations: the point comes back within 1 mm.

use crate::common;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

#[test]
fn world_road_world_round_trip_on_corpus() {
    let Some(files) = common::corpus_xodr() else { return };
    let mut rng = ChaCha8Rng::seed_from_u64(20240611);
    let mut worst = 0.0f64;
    let mut total = 0usize;
    for f in &files {
        let net = opendrive::load(f).expect("corpus map loads").network;
        let mut done = 0;
        let mut tries = 0;
        while done < 300 && tries < 10_000 {
            tries += 1;
            let ri = rng.gen_range(0..net.roads.len());
            let road = &net.roads[ri];
            if road.length <= 0.0 {
                continue;
            }
            let s = rng.gen_range(0.0..road.length);
            let sec = road.section_index_at(s);
            let mut lanes = road.side_borders(sec, true, s);
            lanes.extend(road.side_borders(sec, false, s));
            lanes.retain(|(_, b)| b.width() > 0.05);
            if lanes.is_empty() {
                continue;
            }
            let (lane, b) = lanes[rng.gen_range(0..lanes.len())];
            let offset = rng.gen_range(-0.4..0.4) * b.width();
            let p = net.lane_to_world(ri, lane, s, offset).expect("lane exists");
            let q = net.world_to_lane(p.x, p.y, Some(ri)).expect("located");
            // The hint road contains the point, so it must be chosen, with the same lane.
            assert_eq!((q.road, q.lane_id), (ri, lane), "{} road {} s {s} lane {lane} off {offset}: {q:?}", f.display(), road.id);
            assert!(q.is_on_road());
            let back = net.road_to_world(q.road, q.s, q.t).expect("pose");
            let err = (back.x - p.x).hypot(back.y - p.y);
            assert!(err < 1e-3, "{}: error {err} m at road {} s {s}", f.display(), road.id);
            assert!((q.s - s).abs() < 1e-6 && (q.offset - offset).abs() < 1e-6, "{}: {q:?} vs s {s} off {offset}", f.display());
            worst = worst.max(err);
            // Without a hint the point is still found on some road, on a lane containing it.
            let free = net.world_to_lane(p.x, p.y, None).expect("located");
            assert!(free.is_on_road());
            let back = net.road_to_world(free.road, free.s, free.t).expect("pose");
            worst = worst.max((back.x - p.x).hypot(back.y - p.y));
            done += 1;
        }
        total += done;
    }
    eprintln!("round trip: {total} stations, worst world error {worst:.3e} m");
    assert!(worst < 1e-3);
}
