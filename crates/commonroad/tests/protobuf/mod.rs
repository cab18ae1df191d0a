//! CommonRoad 2024 protobuf: read back by commonroad-io, generated code held to its sources.

mod generated;
mod read;
mod read_back;
mod sign_names_generated;
