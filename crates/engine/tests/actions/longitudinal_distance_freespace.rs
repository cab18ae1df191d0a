//! LongitudinalDistanceAction with freespace to a reference that faces the actor, against
//! esmini 3.6.0's own run of `fixtures/long_distance_freespace_facing.xosc` (straight road,
//! `esmini-3.6.0 --fixed_timestep 0.01`, its CSV log's values, 6 decimals). LongDistanceAction::Step
//! measures a freespace distance with Object::FreeSpaceDistance whatever the coordinate
//! system: the bounding boxes' gap along the actor's heading. Follow1 keeps 20 m (lane
//! coordinates) to Lead1, which stands facing it, so the gap runs to Lead1's front; Follow2
//! keeps 20 m (road coordinates) to Lead2, which faces the same way (its rear).

use crate::common::*;

/// (entity, time, x, speed) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64)] = &[
    ("Follow1", 1.0, 115.49, 16.96),
    ("Follow1", 2.19, 138.375777, 20.400906),
    ("Follow1", 4.0, 170.360117, 14.970906),
    ("Follow1", 8.0, 206.183743, 2.970906),
    ("Follow1", 12.0, 194.007368, -9.029094),
    ("Follow2", 1.0, 615.49, 16.96),
    ("Follow2", 2.19, 638.48092, 21.093961),
    ("Follow2", 4.0, 671.793988, 15.705385),
    ("Follow2", 8.0, 710.555526, 3.705385),
    ("Follow2", 12.0, 701.317065, -8.294615),
];

#[test]
fn a_freespace_distance_to_a_reference_facing_the_actor_runs_to_its_front_as_in_esminis_log() {
    let run = run_straight_fixture("long_distance_freespace_facing.xosc", 12.0);
    assert_esmini_x_speed(&run, ESMINI, 2e-6);
}
