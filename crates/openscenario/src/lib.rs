//! `openscenario`: reads ASAM OpenSCENARIO XML 1.0–1.3 files (and mixtures of versions) into one
//! typed, fully resolved model — parameters and `${...}` expressions evaluated, catalog
//! references replaced by their entries, relative paths made absolute — plus parameter value
//! distributions as lazy sequences of parameter sets.
//!
//! It owns the file format and nothing else: it does not load the OpenDRIVE road network it
//! names, does not simulate, and knows nothing of CommonRoad. Errors carry file, line and
//! column; warnings are returned as data.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod attr;
mod catalog;
mod catalog_file;
pub mod distribution;
mod error;
mod esmini_fallback;
pub mod expr;
mod load;
pub mod model;
mod params;
mod read;
pub mod references;
mod unread;
pub mod validate;
mod xml;

pub use attr::XmlEnum;
pub use catalog::CatalogKind;
pub use catalog_file::{CatalogEntry, CatalogFile};
pub use distribution::{Distribution, ParameterSet};
pub use error::{Diagnostic, Error, ErrorKind, Location};
pub use load::{load, load_scenario, load_str, Content, LoadOptions, Loaded, CATALOG_NOT_CHECKED};
pub use model::*;
pub use params::{ParameterDeclaration, ParameterType};
pub use unread::NO_BEARING;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
