//! The messages of the CommonRoad 2024 format, one module per protobuf package: prost-build's
//! output for `proto/commonroad_2024.binpb` (checked in under `generated/`; the test
//! `tests/protobuf/generated.rs` regenerates it and fails when the two differ).

#![allow(clippy::all, clippy::pedantic, missing_docs)]

/// `commonroad_common`: points, shapes, occupancies, states, meta information, sign ids.
pub mod commonroad_common {
    include!("generated/commonroad_common.rs");
}

/// `commonroad_dynamic`: the dynamic file (obstacles, traffic-light cycles, environment).
pub mod commonroad_dynamic {
    include!("generated/commonroad_dynamic.rs");
}

/// `commonroad_map`: the map file (lanelets, bounds, stop lines, signs, lights, intersections).
pub mod commonroad_map {
    include!("generated/commonroad_map.rs");
}

/// `commonroad_scenario`: the scenario file (meta information, planning problems, tags).
pub mod commonroad_scenario {
    include!("generated/commonroad_scenario.rs");
}
