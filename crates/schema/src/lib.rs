//! `schema`: the ASAM OpenSCENARIO XML schemas 1.0–1.3 as tables a checker can walk.
//!
//! It owns the schema files (embedded, unmodified, in `xsd/`) and their reading: for each version,
//! every complex type's content model (sequences, choices, `all` groups, named groups, with their
//! occurrence bounds), its attributes (type, required, deprecated), and every simple type reduced to
//! a primitive kind, an optional enumeration, and whether `$parameter` or `${expression}` values are
//! allowed. Tables are derived from the XSD at first use rather than written by hand, so they are
//! complete by construction; `cargo test -p osc2cr-schema` checks them against the schemas.
//!
//! It checks nothing by itself: [`content::match_children`] and [`simple::check_literal`] are the
//! two questions a validator asks; the walk over a document lives in `openscenario::validate`.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

pub mod content;
mod model;
mod parse;
pub mod simple;

pub use model::{AttributeDecl, ComplexType, ElementDecl, Literal, Particle, Primitive, Schema, SimpleKind, Term};

use std::sync::OnceLock;

/// The schema of OpenSCENARIO 1.`minor` (0 to 3), or `None` for a version this crate has no schema of.
pub fn for_minor(minor: u16) -> Option<&'static Schema> {
    static SCHEMAS: [OnceLock<Schema>; 4] = [OnceLock::new(), OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let text = match minor {
        0 => include_str!("../xsd/OpenSCENARIO-1.0.xsd"),
        1 => include_str!("../xsd/OpenSCENARIO-1.1.xsd"),
        2 => include_str!("../xsd/OpenSCENARIO-1.2.xsd"),
        3 => include_str!("../xsd/OpenSCENARIO-1.3.xsd"),
        _ => return None,
    };
    let slot = SCHEMAS.get(usize::from(minor))?;
    // The embedded schemas are fixed at build time and tested to parse; a failure is a build defect.
    Some(slot.get_or_init(|| parse::parse(minor, text).unwrap_or_else(|e| panic!("embedded OpenSCENARIO 1.{minor} schema: {e}"))))
}

/// The newest schema this crate has (used when a file declares a later minor version).
pub const NEWEST_MINOR: u16 = 3;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
