//! The CommonRoad 2024 format (protobuf): the message types of commonroad-io 2026.1, generated
//! from `proto/commonroad_2024.binpb` (`proto/README.md` says how it was extracted).

pub mod messages;
