//! A freespace distance measures between towing chains (esmini's Object::Distance): from the
//! measuring vehicle's front-most tow vehicle and each trailer behind it to the referenced
//! vehicle and each trailer behind that, the nearest pair of boxes; in road coordinates the
//! referenced vehicle's trailers are left out (fixture `freespace_towing_chains.xosc`; esmini
//! 3.6.0 logs 11.03, 21.04, 15.50 and 9.70 m and starts all four events at 0.51 s).

use crate::common::*;

#[test]
fn freespace_distances_measure_from_the_whole_towing_chain() {
    let run = run_straight_fixture("freespace_towing_chains.xosc", 1.0);
    for name in ["CarToFollower", "TrailerToLeader", "FollowerToCarRoad", "CarToPoint"] {
        assert_eq!(event_time(&run, name, "start"), Some(0.51), "{name}");
    }
}
