//! What an ACC controller remembers: set speed, time gap, mode, whether it is active.

#[derive(Debug, Clone)]
pub(crate) struct AccRt {
    pub active: bool,
    pub(super) time_gap: f64,
    pub(super) set_speed: f64,
    pub(super) set_speed_given: bool,
    pub(super) lateral_dist: f64,
    pub(super) current_speed: f64,
    pub(in crate::controllers) override_mode: bool,
    /// An action moved the entity this step (seen before the default controller ran).
    pub(in crate::controllers) moved_by_action: bool,
    /// In override mode: its last move ended at the end of the road, and whether the end of
    /// road was already seen one step before (esmini's `Object::IsEndOfRoad`).
    pub(super) at_end: bool,
    pub(super) end_seen: bool,
}
