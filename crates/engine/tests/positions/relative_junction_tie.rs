//! A relative lane or road position moved back into a junction whose arms turn equally far
//! from the lane's driving direction, as esmini 3.6 places it: Position::MoveToConnectingRoad
//! breaks the tie with a draw from the run's seeded generator (GetRand().GetNumberBetween), the
//! same generator the default controller draws from, so a teleport takes the arm esmini takes
//! (it took the first arm, without a draw). Fixture `relative_position_junction_tie.xosc`
//! (t_junction_one_way.xodr; cars placed relative to two cars on the stem, ds and dsLane, lane
//! and road positions); the numbers are esmini 3.6.0's run of it (seed 0), and where esmini runs
//! here the whole run is compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn a_tie_at_a_junction_is_drawn_as_esmini_draws_it() {
    let run = run_fixture_scenario("relative_position_junction_tie.xosc", 5.0);
    assert_esmini_pose_at(&run, "Behind", 0.0, 111.013104, -2.430442, 4.012389);
    assert_esmini_pose_at(&run, "BehindRoad", 0.0, 109.177533, -5.424334, 4.312389);
    assert_esmini_pose_at(&run, "AheadUp", 0.0, 114.25217, -4.081812, 0.770796);
    assert_esmini_pose_at(&run, "BehindAgain", 0.0, 110.127196, -4.606463, 4.212389);
    assert_matches_esmini("relative_position_junction_tie.xosc", &run, 1e-3);
}
