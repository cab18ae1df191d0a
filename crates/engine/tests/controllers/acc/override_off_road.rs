//! An ACC in override mode moves its entity with Object::MoveAlongS, which does nothing for a
//! position on no road (Position::MoveAlongS returns an error when there are no roads or the
//! position's road is undefined): the entity stays where it is while the controller keeps
//! reporting its speed. Fixture `acc_override_off_road.xosc` (no road network): Ego's ACC
//! (set speed 12 m/s) from 4 m/s at (10, 5). Expected values: esmini 3.6.0 on the same fixture
//! (osc2cr drove Ego along its heading before).

use crate::common::oracle::run_fixture_scenario;
use crate::common::*;

#[test]
fn an_acc_in_override_mode_does_not_move_an_entity_on_no_road() {
    let run = run_fixture_scenario("acc_override_off_road.xosc", 6.0);
    for (t, v) in [(1.0, 7.5), (3.0, 11.972), (6.0, 12.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, 10.0, 1e-9) && close(e.y, 5.0, 1e-9) && close(e.speed, v, 2e-3), "t {t}: {e:?}");
    }
}
