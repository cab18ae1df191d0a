//! Strict reading: what it rejects, and that it rejects nothing esmini accepts in the corpus.

mod corpus;
mod problems;
