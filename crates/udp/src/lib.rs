//! `udp`: esmini's UDPDriverController protocol, so that a client written for esmini 3.6.0
//! drives a scenario's entities in osc2cr unchanged. It owns the message layouts (`input_mode`) and their
//! decoding (`message`), the checks a datagram must pass and how a rejection is said
//! (`validate`, `frame_order`, `rejection`), esmini's object ids and port numbering and the
//! controller's properties (`object_ids`, `controller_properties`), what one step reads from a
//! port in asynchronous and synchronous mode (`receive`), the translation of messages into the
//! engine's inputs following esmini's controller step (`translate`), the pace against the wall
//! clock (`pacing`), the OSI GroundTruth sent to esmini's OSI clients and told to the observer
//! (`osi_out`), and the server loop over a `convert::ClosedLoop` (`serve`) with what it
//! hands back (`outcome`).
//!
//! It does not know how the run becomes CommonRoad (`convert` does that), how the engine moves
//! an entity (`engine`), nor the command line: it prints nothing and writes no file — rejected
//! datagrams, notes and the conversion are returned as data and told to an `Observer`
//! (`observer`).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

pub mod controller_properties;
pub mod frame_order;
pub mod input_mode;
pub mod message;
pub mod object_ids;
pub mod observer;
pub mod osi_out;
pub mod outcome;
pub mod pacing;
pub mod receive;
pub mod rejection;
pub mod serve;
pub mod translate;
pub mod validate;

pub use controller_properties::{ExecMode, DEFAULT_BASE_PORT};
pub use message::{decode, Body, Header, InputMode, Message};
pub use observer::{Listening, Observer, Silent};
pub use outcome::{EntityReport, Outcome};
pub use pacing::Pace;
pub use receive::SYNCHRONOUS_TIMEOUT;
pub use rejection::{Reason, Rejection};
pub use serve::{serve, Error, ServeOptions};
pub use validate::accept;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
