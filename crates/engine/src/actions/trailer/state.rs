//! Who pulls whom: the trailer couplings of a run.

/// Who tows whom, and each entity's hitch and coupler positions (m ahead of its reference
/// point), indexed like the run's entities (scenario entities, then inline trailers).
#[derive(Debug, Clone, Default)]
pub(crate) struct Trailers {
    /// `links[tow] = Some(trailer)`.
    pub links: Vec<Option<usize>>,
    pub hitch: Vec<Option<f64>>,
    pub coupler: Vec<Option<f64>>,
}
