//! Whether a vehicle on the next road is in the ACC's lane is esmini's Position::Delta
//! dLaneId: the lane the link leads to, walked through the next road's lane sections from the
//! end esmini takes the path to enter by — the far end when the last road before it is left at
//! its end (a path along s), so a lane id that changes between the sections changes the
//! answer. Fixture `acc_lead_after_section_walk.xosc` on `section_border_after_link.xodr`
//! (road 1, 100 m, lanes −1 and −2, continues as road 2, 200 m; road 2's lane −2 ends at
//! s = 100, where its border lane −3 becomes lane −2): Ego (override ACC, set speed 30 m/s)
//! on road 1, lane −2, s = 70 at 10 m/s with Lead on road 2, lane −2, s = 10 at 10 m/s;
//! Ego2 the same on lane −1. esmini walks Ego's lane −2 back from road 2's end to −3
//! (dLaneId 1: no lead) and cruises up at 0.7 × maxAcceleration, while Ego2 follows Lead2.
//! Expected values: esmini 3.6.0 on the same fixture (osc2cr found Lead in Ego's lane).

use crate::common::*;

/// (t, x, speed) rows of esmini's run.
type Rows = [(f64, f64, f64); 3];

/// Ego's and Ego2's rows of esmini's run, each within 1e-4.
fn assert_rows(map: &str, rows: [(&str, Rows); 2]) {
    let run = run_fixture("acc_lead_after_section_walk.xosc", map);
    for (name, rows) in rows {
        for (t, x, v) in rows {
            let e = at(&run, name, t);
            assert!(close(e.x, x, 1e-4) && close(e.speed, v, 1e-4), "{map} {name} t {t}: {e:?}");
        }
    }
}

#[test]
fn a_lane_id_walked_through_the_next_roads_sections_hides_the_lead() {
    assert_rows(
        "section_border_after_link.xodr",
        [
            ("Ego", [(0.01, 70.1007, 10.07), (0.5, 75.8925, 13.5), (1.0, 83.535, 17.0)]),
            ("Ego2", [(0.01, 70.101, 10.1), (0.5, 76.275, 15.0), (1.0, 84.822396, 18.292903)]),
        ],
    );
}

#[test]
fn a_direct_junction_leads_by_its_linked_road() {
    // The same cars on `direct_junction_two_roads.xodr`: road 1 runs into road 2 (one lane
    // section) through a direct junction, whose connection names road 2 as `linkedRoad`
    // (esmini reads a direct junction's connecting road from it). Both leads are in their
    // ACC's lane: esmini follows each (osc2cr found no connecting lane and lost Ego's lead).
    let follow = [(0.01, 70.101, 10.1), (0.5, 76.275, 15.0), (1.0, 84.822396, 18.292903)];
    assert_rows("direct_junction_two_roads.xodr", [("Ego", follow), ("Ego2", follow)]);
}
