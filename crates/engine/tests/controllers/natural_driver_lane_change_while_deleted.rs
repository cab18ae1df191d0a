//! A NaturalDriver's lane change runs on while its entity is deleted. The driver carries out a
//! lane change by injecting a LaneChangeAction (ControllerNaturalDriver::Step,
//! InjectLaneChangeAction), and esmini's ScenarioEngine::step steps injected actions whatever
//! their entity: one started before a DeleteEntityAction ends on its own clock while the entity
//! is away, and once an AddEntityAction brings the entity back the driver can start the next.
//!
//! Fixture `natural_driver_lane_change_while_deleted.xosc` on straight.xodr: the Ego (override
//! mode, lane changes of 2 s) starts changing to lane −2 at once to pass the slower Target, is
//! deleted at 1 s and added back at 2.5 s in lane −1 at s = 30, where it is put as the action
//! says and changes lane again. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "natural_driver_lane_change_while_deleted.xosc";

#[test]
fn an_injected_lane_change_runs_on_while_its_entity_is_deleted() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego", 0.99, 24.729603, -3.445031, 6.099091);
    assert_esmini_pose_at(&run, "Ego", 2.51, 30.156134, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego", 3.0, 37.487035, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego", 5.0, 65.922858, -5.248057, 6.271157);
    assert_esmini_pose_at(&run, "Ego", 8.0, 114.496485, -5.25, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}
