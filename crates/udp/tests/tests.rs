//! The UDP driver server's tests, one binary: each input mode, ports, rejections, dead reckoning,
//! determinism, hostile datagrams, and esmini 3.6.0 itself as the oracle. `common` runs a server
//! in lockstep; scenarios are in `fixtures/`.

mod common;

mod dead_reckoning;
mod determinism;
mod esmini_oracle;
mod input_modes;
mod never_panics;
mod ports;
mod rejections;
