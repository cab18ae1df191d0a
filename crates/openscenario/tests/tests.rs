//! The OpenSCENARIO reader's tests, one binary whose modules are its features: `load/` (the
//! corpus, malformed and mutated input, resolution of parameters and catalogs), `strict/` (what
//! a strict reading rejects), `expressions`, `distributions`, `validate` (the schema pass) and
//! `schema_coverage` (nothing unread passes unannounced). `common` loads scenarios written inline;
//! the coverage table is in `data/`.

mod common;

mod distributions;
mod expressions;
mod expressions_where_allowed;
mod load;
mod schema_coverage;
mod strict;
mod validate;
