//! What the storyboard's actions hold while a run goes on: one slot per action, one instance
//! per actor while it runs, and what each kind of running action remembers between steps (each
//! action's own `state` module). Data only: the modules of `actions/` change it.

use openscenario::{Action, ActionKind, PrivateAction};

/// Control domains an action takes over (bits).
pub(crate) const LONG: u8 = 1;
pub(crate) const LAT: u8 = 2;

/// What an action instance is doing.
#[derive(Debug, Clone)]
pub(crate) enum ActionRt {
    Speed(super::speed::state::SpeedRt),
    LaneChange(super::lane_change::state::LaneChangeRt),
    LaneOffset(super::lane_offset::state::LaneOffsetRt),
    FollowTrajectory(Box<super::follow_trajectory::state::FollowTrajectoryRt>),
    SpeedProfile(super::speed_profile::state::SpeedProfileRt),
    Synchronize(Box<super::synchronize::state::SynchronizeRt>),
    LongDistance(Box<super::long_distance::state::LongDistanceRt>),
    LatDistance(Box<super::lat_distance::state::LatDistanceRt>),
    /// Nothing left to do.
    Done,
    /// Started on an entity driven from outside: runs without effect and never ends
    /// (external/overridden.rs).
    Overridden,
    /// Started, without anything left to do, and never ends: esmini's AssignControllerAction,
    /// whose Step does nothing and which nothing ends, and an ActivateControllerAction that
    /// found no controller to activate (its event runs on until the stop).
    Lingers,
    /// Ended in its start, as esmini's actions that call `OSCAction::End` from `Start`: the
    /// action is complete before the triggers later in the storyboard are evaluated.
    EndedAtStart,
}

#[derive(Debug, Clone)]
pub(crate) struct Instance {
    pub entity: Option<usize>,
    pub rt: ActionRt,
}

#[derive(Debug, Clone)]
pub(crate) struct ActionSlot<'a> {
    pub node: usize,
    pub model: &'a Action,
    pub actors: Vec<usize>,
    pub instances: Vec<Instance>,
    pub running: bool,
    pub warned: bool,
    /// An Init action copied for a ghost (`ghost/`): esmini copied its position with
    /// Position::Duplicate, which leaves a trajectory out.
    pub ghost_copy: bool,
    /// A story action handed over to a ghost (`ghost/`): its references to the entity name
    /// the ghost (entity, ghost), as esmini's OSCPrivateAction::ReplaceObjectRefs does.
    pub ghost_refs: Option<(usize, usize)>,
    /// Per actor, what esmini's action object keeps from the last execution for the next one
    /// (its event or maneuver group started again).
    pub kept: Vec<(usize, Kept)>,
}

/// State an action's esmini object keeps across executions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Kept {
    LatDistance(super::lat_distance::state::LatDistanceKept),
    LongDistance(super::long_distance::state::LongDistanceKept),
    Synchronize(super::synchronize::state::SynchronizeKept),
    Speed(super::speed::state::SpeedKept),
}

impl<'a> ActionSlot<'a> {
    pub(crate) fn new(node: usize, model: &'a Action, actors: Vec<usize>) -> Self {
        ActionSlot { node, model, actors, instances: Vec::new(), running: false, warned: false, ghost_copy: false, ghost_refs: None, kept: Vec::new() }
    }

    /// Record what instance `rt` of actor `e` leaves for the next execution.
    pub(crate) fn keep(&mut self, e: usize, rt: &ActionRt) {
        let kept = match rt {
            ActionRt::LatDistance(r) => Kept::LatDistance(r.kept()),
            ActionRt::LongDistance(r) => Kept::LongDistance(r.kept()),
            ActionRt::Synchronize(r) => Kept::Synchronize(r.kept()),
            ActionRt::Speed(r) => match r.distance_span {
                Some(span) => Kept::Speed(super::speed::state::SpeedKept { param_target: span }),
                None => return,
            },
            _ => return,
        };
        match self.kept.iter_mut().find(|(k, _)| *k == e) {
            Some(slot) => slot.1 = kept,
            None => self.kept.push((e, kept)),
        }
    }

    /// What actor `e`'s last execution left, if anything.
    pub(crate) fn kept_for(&self, e: usize) -> Option<Kept> {
        self.kept.iter().find(|(k, _)| *k == e).map(|&(_, k)| k)
    }

    /// Control domains the action takes over.
    pub(crate) fn domains(&self) -> u8 {
        match &self.model.kind {
            ActionKind::Private(p) => match p {
                PrivateAction::Speed { .. }
                | PrivateAction::SpeedProfile { .. }
                | PrivateAction::LongitudinalDistance { .. }
                | PrivateAction::Synchronize { .. } => LONG,
                PrivateAction::LaneChange { .. } | PrivateAction::LaneOffset { .. } => LAT,
                // esmini 3.6's LatDistanceAction passes the domain index ControlDomains::DOMAIN_LAT
                // (1) where a mask is wanted, and mask 1 is DOMAIN_MASK_LONG: starting one ends a
                // running speed action of the entity, not its lane change (Event::Start).
                PrivateAction::LateralDistance { .. } => LONG,
                // Without timing the speed stays with the longitudinal actions (esmini runs a
                // SpeedProfileAction alongside such a trajectory).
                PrivateAction::FollowTrajectory { time_reference: openscenario::TimeReference::None, .. } => LAT,
                PrivateAction::FollowTrajectory { .. } => LONG | LAT,
                // esmini's TeleportAction holds both domains (DOMAIN_MASK_LAT_AND_LONG): starting
                // one ends a running lane change or speed change of the entity; its
                // AcquirePositionAction holds the longitudinal one.
                PrivateAction::Teleport(_) => LONG | LAT,
                PrivateAction::AcquirePosition(_) => LONG,
                PrivateAction::OverrideControllerValue(values) => crate::actions::override_controller::state::domains(values),
                _ => 0,
            },
            _ => 0,
        }
    }
}
