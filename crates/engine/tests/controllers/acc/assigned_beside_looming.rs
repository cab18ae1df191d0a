//! Two controllers on one entity (fixture `acc_assigned_beside_looming.xosc`, straight road):
//! a LoomingController activated in the Init (set speed 15 m/s, the car from 10 m/s) and an ACC
//! in override mode (set speed 20 m/s) that an AssignControllerAction assigns and activates at
//! t > 2. esmini keeps both active (Object::AssignController appends to the entity's list;
//! AssignControllerAction::Start switches no other controller off) and steps both in the order
//! it made them: the car is where the looming vehicle drove, moved on by the ACC's MoveAlongS
//! (one step's travel ahead from 2.02 s), and the ACC takes the looming speed as its set speed.
//! Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn an_assigned_acc_steps_beside_the_looming_controller() {
    let run = run_fixture("acc_assigned_beside_looming.xosc", "straight.xodr");
    // (time, x, speed); was: the ACC alone from 2.01 s, up to 20 m/s (x 123.69 at 6 s)
    let expected = [
        (2.0, 47.430403, 14.997878),
        (2.01, 47.580383, 14.997984),
        (2.02, 47.880694, 15.032984),
        (2.03, 48.030628, 15.031647),
        (3.0, 62.564626, 14.998188),
        (6.0, 107.565686, 15.000225),
    ];
    for (t, x, v) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4) && close(e.y, -1.75, 1e-3), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}
