//! Who pulls whom: the trailer couplings of a run.

/// Who tows whom, and each entity's hitch and coupler positions (m ahead of its reference
/// point), indexed like the run's entities (scenario entities, then inline trailers).
#[derive(Debug, Clone, Default)]
pub(crate) struct Trailers {
    /// The hitch side, `links[tow] = Some(trailer)` (esmini's TrailerHitch::trailer_vehicle_).
    pub links: Vec<Option<usize>>,
    /// The coupler side, `towed_by[trailer] = Some(tow)` (TrailerCoupler::tow_vehicle_). The
    /// two sides disagree after a ConnectTrailerAction on a trailer another vehicle tows, or
    /// from a vehicle without a hitch: esmini sets each side it can and clears neither.
    pub towed_by: Vec<Option<usize>>,
    pub hitch: Vec<Option<f64>>,
    pub coupler: Vec<Option<f64>>,
    /// `(ghost, owner)` when the ghost shares its owner's hitch: esmini's ghost is a copy of the
    /// vehicle (Vehicle's copy constructor) that keeps the same TrailerHitch when no trailer was
    /// on it yet, so a trailer connected to either later is on both hitches.
    pub shared_hitch: Option<(usize, usize)>,
}

impl Trailers {
    /// Where the hitch side of `e` is kept: its owner's for a ghost sharing it.
    pub(crate) fn hitch_slot(&self, e: usize) -> usize {
        match self.shared_hitch {
            Some((ghost, owner)) if ghost == e => owner,
            _ => e,
        }
    }

    /// The trailer on `e`'s hitch.
    pub(crate) fn trailer_of(&self, e: usize) -> Option<usize> {
        self.links.get(self.hitch_slot(e)).copied().flatten()
    }
}
