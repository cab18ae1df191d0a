//! An ACC in override mode takes the speed a SpeedProfileAction sets as its new set speed:
//! esmini's ControllerACC::Step adopts any speed set from elsewhere as `setSpeed_` in either mode
//! (its additive-only test is commented out), and a SpeedProfileAction, unlike a SpeedAction
//! (LongSpeedAction::Start), does not end when a controller overrides the longitudinal domain.
//! Fixture `acc_override_speed_profile.xosc` (straight road): Ego, standing, ACC in override
//! mode with set speed 26 m/s; a SpeedProfileAction (follow mode, 2.8 m/s² at most) to 24 m/s
//! from t = 0. Expected values: esmini 3.6.0 on the same fixture.

use crate::common::*;

#[test]
fn an_overriding_acc_follows_the_speed_a_speed_profile_sets() {
    let run = run_fixture("acc_override_speed_profile.xosc", "straight.xodr");
    // esmini: the profile's ramp, not the ACC's own 3.5 m/s² to 26 m/s (which reaches x 17.0
    // at 2 s and 121.4 at 8 s)
    for (t, x, v) in [(2.0, 14.297, 4.83), (5.0, 41.423, 13.23), (8.0, 93.749, 21.63)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 6e-3), "t {t}: {e:?}");
    }
}
