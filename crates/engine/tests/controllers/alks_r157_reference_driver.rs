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
