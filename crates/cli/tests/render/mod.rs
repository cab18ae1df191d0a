//! `osc2cr render`: the formats, and how a picture frames the action.

mod formats;
mod framing;
