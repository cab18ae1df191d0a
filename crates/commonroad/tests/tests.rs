//! The CommonRoad model's tests, one binary whose modules are its parts: `model/` (checked
//! constructors, `validate`), `xml/` (the 2020a writer against the XSD, number format, escaping,
//! atomic writes, reading back, `cr_check.py`) and `protobuf/` (the 2024 writer read back by
//! commonroad-io, the generated types and sign names held to their sources). `common` builds the
//! small models they write.

mod common;

mod model;
mod protobuf;
mod xml;
