//! Which OpenDRIVE lane types esmini counts as driving lanes (its "any driving" set), for the
//! questions that look at the lanes around an entity: relative clearance, NaturalDriver's
//! neighbours. (A route and the zero-width snap use their own sets.)

use opendrive::LaneType;

/// Whether vehicles drive on a lane of this type.
pub(crate) fn is_driving(kind: LaneType) -> bool {
    matches!(
        kind,
        LaneType::Driving
            | LaneType::Entry
            | LaneType::Exit
            | LaneType::OnRamp
            | LaneType::OffRamp
            | LaneType::ConnectingRamp
            | LaneType::MwyEntry
            | LaneType::MwyExit
            | LaneType::Bidirectional
    )
}
