//! Ghosts, as esmini makes them for FollowGhostController (and FollowReferenceController
//! without a reference entity): a copy of the controlled entity, named `<name>_ghost`, that
//! runs the storyboard's motion actions in the entity's place while the entity follows it.
//!
//! At setup (first such entity only, as esmini): the ghost gets copies of the entity's Init
//! actions (all but ActivateController, run after the others); the story's speed, speed
//! profile, lane change, lane offset, synchronize, trajectory, route, teleport and acquire
//! position actions on the entity move to the ghost, and their relative lane, lane offset and
//! speed targets and speed profile entity naming the entity name the ghost instead
//! (ReplaceObjectRefs); in every act's start trigger, and in the start trigger of
//! each event that now moves the ghost, SimulationTime conditions fire `headstart` seconds
//! earlier and the entity's collision / reach-position / traveled-distance / speed /
//! acceleration / end-of-road / off-road / stand-still conditions watch the ghost instead.
//! esmini also gives an event whose trigger depends on anything else a teleport of the ghost
//! back to the entity; when it fires after time 0 esmini restarts the ghost (rewinds time by
//! the head start, freezes the entity, logs the rewound steps again): `restart.rs`.
//!
//! The run then starts at −headstart: until time 0 only the ghost moves (the default
//! controller leaves every other entity alone, no controller steps, and only the ghost's
//! actions step: others start but wait), so at 0 the ghost leads by the head start. After every step the ghost's trail is sampled (`trail.rs`) on
//! esmini's accumulated clock, whose rounding decides which steps are sampled.

mod restart;
pub(crate) mod state;
pub(crate) mod trail;

use self::state::{Ghost, GhostMode};
use crate::actions::state::ActionSlot;
use crate::controllers::state::ControllerRt;
use crate::ghost::trail::Trail;
use crate::sim::Sim;
use crate::storyboard::{Kind, Node};
use openscenario::{ActionKind, ConditionKind, EntityCondition, PrivateAction, ValueCondition};

/// Actions esmini hands over to the ghost.
fn moves_to_ghost(p: &PrivateAction) -> bool {
    matches!(
        p,
        PrivateAction::Speed { .. }
            | PrivateAction::SpeedProfile { .. }
            | PrivateAction::LaneChange { .. }
            | PrivateAction::LaneOffset { .. }
            | PrivateAction::Synchronize { .. }
            | PrivateAction::FollowTrajectory { .. }
            | PrivateAction::AssignRoute(_)
            | PrivateAction::Teleport(_)
            | PrivateAction::AcquirePosition(_)
    )
}

/// Entity conditions that watch the ghost instead of the entity.
fn watches_ghost(c: &EntityCondition) -> bool {
    matches!(
        c,
        EntityCondition::Collision { .. }
            | EntityCondition::ReachPosition { .. }
            | EntityCondition::TraveledDistance { .. }
            | EntityCondition::Speed { .. }
            | EntityCondition::Acceleration { .. }
            | EntityCondition::EndOfRoad { .. }
            | EntityCondition::Offroad { .. }
            | EntityCondition::StandStill { .. }
    )
}

impl<'a> Sim<'a> {
    /// Create the ghost of the first entity whose controller needs one (after `build`).
    pub(crate) fn setup_ghost(&mut self) {
        self.check_follow_references();
        let n = self.scenario.entities.len();
        let found = (0..n).find_map(|e| {
            self.controllers_of(e).find_map(|c| match c {
                ControllerRt::FollowGhost(f) => Some((e, f.headstart)),
                ControllerRt::FollowReference(f) if f.uses_ghost() => Some((e, 0.0)),
                _ => None,
            })
        });
        let Some((owner, headstart)) = found else { return };
        self.warn_other_followers(owner);
        let Some(mut copy) = self.entities.get(owner).cloned() else { return };
        copy.name.push_str("_ghost");
        copy.controller_active = false;
        self.entities.push(copy);
        let ghost = self.entities.len() - 1;
        self.share_hitch_with_ghost(ghost, owner);

        // Init actions: copies for the ghost, after all others.
        for k in 0..self.init_actions.len() {
            let slot = self.init_actions[k];
            let a = &self.actions[slot];
            let copy_it = a.actors == [owner] && matches!(&a.model.kind, ActionKind::Private(p) if !matches!(p, PrivateAction::ActivateController { .. }));
            if !copy_it {
                continue;
            }
            let model = a.model;
            let name = format!("{}_ghost-copy", self.nodes[a.node].name);
            let node = self.nodes.len();
            self.nodes.push(Node::new(Kind::Action, &name, None));
            let mut copy = ActionSlot::new(node, model, vec![ghost]);
            copy.ghost_copy = true;
            self.actions.push(copy);
            self.nodes[node].action = Some(self.actions.len() - 1);
            self.init_actions.push(self.actions.len() - 1);
        }

        // Story actions that move the entity move the ghost; their events' triggers follow.
        let mut events = Vec::new();
        for slot in 0..self.actions.len() {
            if self.init_actions.contains(&slot) {
                continue;
            }
            let a = &mut self.actions[slot];
            let hands_over = matches!(&a.model.kind, ActionKind::Private(p) if moves_to_ghost(p));
            if !hands_over || !a.actors.contains(&owner) {
                continue;
            }
            for actor in &mut a.actors {
                if *actor == owner {
                    *actor = ghost;
                }
            }
            a.ghost_refs = Some((owner, ghost));
            if let Some(ev) = self.nodes[a.node].parent.filter(|&p| self.nodes[p].kind == Kind::Event) {
                if !events.contains(&ev) {
                    events.push(ev);
                }
            }
        }
        let restart_events = self.ghost_restart_events(owner, &events);
        // ScenarioEngine::SetupGhost hands an Act's start trigger to the ghost only when the
        // entity is an actor of one of the Act's maneuver groups; an Act of other entities
        // starts on the clock of the run (its SimulationTime stays unshifted).
        let owner_acts: Vec<bool> = self
            .scenario
            .storyboard
            .stories
            .iter()
            .flat_map(|story| &story.acts)
            .map(|act| act.maneuver_groups.iter().any(|mg| mg.actors.iter().any(|a| self.entity_index(a) == Some(owner))))
            .collect();
        let acts = (0..self.nodes.len()).filter(|&n| self.nodes[n].kind == Kind::Act);
        let acts = acts.zip(owner_acts).filter_map(|(n, owns)| owns.then_some(n));
        let triggers: Vec<usize> = acts.chain(events).filter_map(|n| self.nodes[n].start_trigger).collect();
        for t in triggers {
            self.hand_trigger_to_ghost(t, owner, ghost, headstart);
        }
        // esmini's ScenarioEngine::parseScenario starts a positive head start in RESTART mode;
        // its first UpdateGhostMode rewinds the clock by it (here: the clock starts there).
        let mode = if headstart > 0.0 { GhostMode::Restarting } else { GhostMode::Normal };
        self.ghost = Some(Ghost {
            entity: ghost,
            owner,
            headstart,
            trail: Trail::default(),
            clock: 0.0 - headstart,
            true_clock: 0.0,
            mode,
            restart_events,
            start_shift: 0.0,
            unmeasured: false,
        });
    }

    /// esmini's ghost is a copy of its vehicle (Vehicle's copy constructor): with no trailer on
    /// the owner's hitch yet, the copy keeps the very same TrailerHitch, so a trailer connected
    /// later (a ConnectTrailerAction in the Init) hangs on both and the ghost pulls it too. (An
    /// owner already towing gets a ghost with a copy of its trailer in esmini; not modelled:
    /// that ghost has no hitch here.)
    fn share_hitch_with_ghost(&mut self, ghost: usize, owner: usize) {
        let t = &mut self.trailers;
        if t.links.len() != ghost {
            return;
        }
        let hitch = t.hitch.get(owner).copied().flatten();
        let shared = hitch.is_some() && t.links.get(owner).copied().flatten().is_none();
        t.hitch.push(if shared { hitch } else { None });
        t.coupler.push(t.coupler.get(owner).copied().flatten());
        t.links.push(None);
        t.towed_by.push(None);
        if shared {
            t.shared_hitch = Some((ghost, owner));
        }
    }

    /// esmini gives only the first such entity a ghost; the others' controllers do nothing.
    fn warn_other_followers(&mut self, owner: usize) {
        for e in owner + 1..self.scenario.entities.len() {
            let needs_ghost = self.controllers_of(e).any(|c| match c {
                ControllerRt::FollowGhost(_) => true,
                ControllerRt::FollowReference(f) => f.uses_ghost(),
                _ => false,
            });
            if let (true, Some(m)) = (needs_ghost, self.scenario.entities.get(e)) {
                let msg = format!(
                    "entity `{}`: only the first entity with a ghost-following controller gets a ghost (esmini); its controller leaves it standing",
                    m.name
                );
                self.warnings.push(crate::Diagnostic::at(&m.origin, msg));
            }
        }
    }

    fn hand_trigger_to_ghost(&mut self, t: usize, owner: usize, ghost: usize, headstart: f64) {
        let Some(trig) = self.triggers.get_mut(t) else { return };
        for c in trig.groups.iter_mut().flatten() {
            match &c.model.kind {
                ConditionKind::ByValue(ValueCondition::SimulationTime { .. }) => c.time_shift = headstart,
                ConditionKind::ByEntity { condition, .. } if watches_ghost(condition) => {
                    for e in &mut c.triggering {
                        if *e == owner {
                            *e = ghost;
                        }
                    }
                }
                _ => {}
            }
        }
    }

    /// When the run starts: −headstart with a ghost, else 0.
    pub(crate) fn time_origin(&self) -> f64 {
        self.ghost.as_ref().map_or(0.0, |g| -g.headstart)
    }

    /// Whether the step starting at the current time is part of the ghost's head start or of
    /// a rewound run after a restart (esmini's RESTARTING mode).
    pub(crate) fn ghost_restarting(&self) -> bool {
        self.ghost.as_ref().is_some_and(|g| g.mode == GhostMode::Restarting)
    }

    /// Whether an action instance on entity `e` steps while the ghost runs ahead: only the
    /// ghost's do. esmini's `StoryBoard::Step` skips the Init actions of every other object
    /// (and all global ones) while its ghost mode is RESTARTING, and `Event::Step` likewise the
    /// story's; they still start, and a Start that sets a state (a step SpeedAction) sets it.
    pub(crate) fn steps_during_restart(&self, e: usize) -> bool {
        self.ghost.as_ref().is_some_and(|g| g.entity == e)
    }

    /// During the head start only the ghost moves.
    pub(crate) fn hold_during_restart(&mut self) {
        let ghost = self.ghost.as_ref().map(|g| g.entity);
        for (i, en) in self.entities.iter_mut().enumerate() {
            if Some(i) != ghost {
                en.moved_by_action = true;
            }
        }
    }

    /// Sample the ghost's trail after a step of `dt` (0 for the first frame); not in the step
    /// of a restart (esmini's `prepareGroundTruth` skips the ghost in RESTART mode).
    pub(crate) fn record_ghost_trail(&mut self, dt: f64) {
        let Some(g) = self.ghost.as_mut() else { return };
        g.clock += dt;
        if g.clock > g.true_clock {
            g.true_clock = g.clock;
        }
        if g.mode == GhostMode::Restart {
            return;
        }
        if let Some(en) = self.entities.get(g.entity).filter(|en| en.active) {
            g.trail.sample(g.clock, en.x, en.y, en.speed);
        }
    }

    /// esmini's `ScenarioEngine::UpdateGhostMode`, at the end of a frame: a restart rewinds the
    /// clock by the head start (true: a rewound run begins); a rewound run ends when the clock
    /// is back at the latest time reached.
    pub(crate) fn update_ghost_mode(&mut self) -> bool {
        let Some(g) = self.ghost.as_mut() else { return false };
        match g.mode {
            GhostMode::Restart => {
                g.clock -= g.headstart;
                self.clock -= g.headstart;
                g.mode = GhostMode::Restarting;
                true
            }
            GhostMode::Restarting if g.clock > g.true_clock - crate::dynamics::ESMINI_SMALL_NUMBER => {
                g.mode = GhostMode::Normal;
                false
            }
            _ => false,
        }
    }

    /// esmini's `ReplaceObjectInTrigger` gives each ghost event whose start trigger has an
    /// entity condition other than a ghost-watched one on the entity itself, or one of its
    /// by-value conditions other than SimulationTime (Parameter, Variable, TrafficSignal; a
    /// StoryboardElementState condition is a kind of its own there) an `AddedGhostTeleport`
    /// (`restart.rs`): these events, each with the note (at its first such condition)
    /// given when it restarts the ghost.
    fn ghost_restart_events(&self, owner: usize, events: &[usize]) -> Vec<(usize, crate::Diagnostic)> {
        let mut out = Vec::new();
        for &ev in events {
            let Some(t) = self.nodes[ev].start_trigger else { continue };
            let Some(trig) = self.triggers.get(t) else { continue };
            let restarts = |c: &&crate::conditions::state::ConditionRt| match &c.model.kind {
                ConditionKind::ByValue(v) => {
                    matches!(v, ValueCondition::Parameter { .. } | ValueCondition::Variable { .. } | ValueCondition::TrafficSignal { .. })
                }
                ConditionKind::ByEntity { condition, .. } if watches_ghost(condition) => c.triggering.iter().any(|&e| e != owner),
                ConditionKind::ByEntity { .. } => true,
                ConditionKind::Unsupported { .. } => false,
            };
            let Some(c) = trig.groups.iter().flatten().find(restarts) else { continue };
            let msg = format!(
                "condition `{}`: event `{}` started after time 0, where esmini restarts the ghost from its entity: time rewinds by the head start and the rewound steps are logged again (the trace CSV repeats those times, as esmini's log does; the CommonRoad conversion keeps the first pass)",
                c.model.name, self.nodes[ev].name
            );
            out.push((ev, crate::Diagnostic::at(&c.model.origin, msg)));
        }
        out
    }
}
