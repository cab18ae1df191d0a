//! The ALKS_R157SM_Controller's ReferenceDriver model (ControllerALKS_R157SM::ReferenceDriver),
//! against esmini 3.6.0's runs of the same fixtures (`--fixed_timestep 0.01`).
//!
//! `alks_r157_reference_driver_brakes.xosc` (straight road, cruise off): two followers at
//! 20 m/s 30 m behind leads that brake at 8 m/s² from 1 s. After perceiving the deceleration
//! (0.4 s) and reacting (0.75 s) the follower ramps its braking up to 0.774 × 9.81 m/s² (the
//! model's max_dec_, not 0.774 × 9.8), and the AEB adds its ramp to 0.85 × 9.81 m/s² once the
//! TTC is under 1.5 s — only when the lead covers the follower's front face within the overlap
//! tolerance, 0.1 m by default (Object::OverlappingFront): the aligned lead does, the one
//! 0.15 m to the side does not, so that follower stops braking when the gap opens again.
//!
//! `alks_r157_motorbike_wandering.xosc`: a car and a motorbike, each 0.3 m from its lane's
//! centre towards a follower's lane, drift towards it. The wandering trigger
//! (WanderingTrigger::Update) lowers its 0.375 m threshold by that offset for the car, not for
//! the motorbike: the car is perceived cutting in and braked for, the motorbike later, too late
//! to be critical.

use crate::common::*;

#[test]
fn the_reference_driver_brakes_to_its_max_deceleration_and_its_aeb_needs_the_lead_in_front() {
    let run = run_fixture("alks_r157_reference_driver_brakes.xosc", "straight.xodr");
    assert_esmini_x_speed(
        &run,
        &[
            ("AlignedEgo", 2.50, 99.917035, 19.281722),
            ("AlignedEgo", 3.00, 108.607598, 15.358036),
            ("AlignedEgo", 3.50, 115.223457, 11.188786),
            ("AlignedEgo", 4.00, 119.754691, 7.019536),
            ("AlignedEgo", 5.00, 122.674256, 0.0),
            ("AlignedEgo", 6.50, 122.674256, 0.0),
            ("OffsetEgo", 2.50, 449.917174, 19.290060),
            ("OffsetEgo", 3.00, 458.779182, 15.937777),
            ("OffsetEgo", 3.50, 465.779970, 12.141307),
            ("OffsetEgo", 4.00, 470.882524, 8.344837),
            ("OffsetEgo", 5.00, 475.537192, 2.194556),
            ("OffsetEgo", 6.50, 478.829026, 2.194556),
        ],
        1e-5,
    );
}

#[test]
fn the_wandering_trigger_keeps_its_threshold_for_a_motorbike() {
    let run = run_fixture("alks_r157_motorbike_wandering.xosc", "straight.xodr");
    assert_esmini_x_speed(
        &run,
        &[
            ("CarEgo", 2.50, 100.0, 20.0),
            ("CarEgo", 3.00, 109.798028, 19.202741),
            ("CarEgo", 4.00, 129.000769, 19.202741),
            ("CarEgo", 6.00, 167.406252, 19.202741),
            ("BikeEgo", 3.00, 460.0, 20.0),
            ("BikeEgo", 6.00, 520.0, 20.0),
        ],
        1e-5,
    );
}
