//! The router's tests, one binary: routes on hand-written networks and on corpus maps.

mod common;

mod corpus_maps;
mod hand_networks;
