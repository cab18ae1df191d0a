//! esmini's ghost restart. Every ghost event whose start trigger watches something other than
//! the simulation time or the ghost itself gets a teleport of the ghost back to its entity as
//! its first action (`ScenarioEngine::CreateGhostTeleport`, "AddedGhostTeleport"). Started
//! before time 0 it is a plain teleport onto the entity; started later it restarts the ghost
//! (`TeleportAction::Start` with ghost restart): the ghost takes the entity's position and
//! speed, its trail starts afresh, and once the step is over the clock goes back by the head
//! start and runs again to where it was, only the ghost moving (`run.rs` records those steps as
//! the trace's replays, as esmini's log repeats those times). Completed events that teleport
//! the ghost become ready again (`ScenarioEngine::ResetEvents`), so restarts can chain.

use crate::dynamics::ESMINI_SMALL_NUMBER;
use crate::ghost::state::GhostMode;
use crate::ghost::trail::Trail;
use crate::sim::Sim;
use crate::storyboard::{Kind, State};
use crate::trace::StoryboardEvent;
use openscenario::{ActionKind, PrivateAction};

/// esmini's name of the added teleport action, as its event log shows it.
const ADDED_TELEPORT: &str = "AddedGhostTeleport";

impl<'a> Sim<'a> {
    /// Event `ev` has started and its actions are about to: run its added ghost teleport first,
    /// if it has one (esmini inserts it at the front of the event's actions).
    pub(crate) fn ghost_event_starts(&mut self, ev: usize) {
        let Some(g) = self.ghost.as_ref() else { return };
        let Some((_, note)) = g.restart_events.iter().find(|(e, _)| *e == ev).cloned() else { return };
        let ghost = g.entity;
        // Event::Start: a starting action ends the running ones of its entity on a shared
        // domain; a teleport holds both.
        self.run_added_teleport(note, Some(ghost));
    }

    /// esmini's `ScenarioEngine::InjectGhostRestart`, from an action of event `ev` that
    /// releases an override (`actions/override_controller.rs`): an added teleport is put at the
    /// front of the event's actions and started at once — outside `Event::Start`, so no running
    /// action of the ghost is ended — and stays there, so the event restarts the ghost whenever
    /// it starts again and counts as one with a teleport for `ResetEvents`.
    pub(crate) fn inject_ghost_restart(&mut self, ev: usize, note: crate::Diagnostic) {
        let Some(g) = self.ghost.as_mut() else { return };
        if !g.restart_events.iter().any(|(e, _)| *e == ev) {
            g.restart_events.push((ev, note.clone()));
        }
        self.run_added_teleport(note, None);
    }

    /// The added teleport's run: `TeleportAction::Start` of the ghost onto its entity (a restart
    /// once the clock is past 0), after ending the running actions of `ending` if given.
    fn run_added_teleport(&mut self, note: crate::Diagnostic, ending: Option<usize>) {
        let Some(g) = self.ghost.as_ref() else { return };
        let (ghost, owner) = (g.entity, g.owner);
        self.log_added_teleport("init", "start", "running");
        // Event::Start: after a teleport of the ghost the event's other actions start at the
        // time less the head start (`ghost_event_started` ends this).
        if let Some(g) = self.ghost.as_mut() {
            g.start_shift = g.headstart;
        }
        if let Some(e) = ending {
            self.end_running_actions_of(e);
        }
        let Some(src) = self.entities.get(owner).cloned() else { return };
        // TeleportAction::Start: a restart only once the clock is past 0.
        let restart = self.time > ESMINI_SMALL_NUMBER;
        if let Some(en) = self.entities.get_mut(ghost) {
            if restart {
                // Position::Duplicate of the entity's position (its status too: the ghost is at
                // a road's end only if the entity is, unlike a TeleportTo), and its speed.
                en.at_road_end = src.at_road_end;
                en.x = src.x;
                en.y = src.y;
                en.z = src.z;
                en.h = src.h;
                en.lane = src.lane;
                en.on_road = src.on_road;
                en.yaw_offset = src.yaw_offset;
                en.parallel_lane = None;
                en.route = src.route.clone();
                en.route_broken = src.route_broken;
                en.speed = src.speed;
            } else {
                // A relative object position with no offsets: the entity's pose. It is a real
                // position, so a ghost its Init left nowhere (a TrajectoryPosition copy) is on
                // the map again and its moves no longer fail (Position::TeleportTo).
                en.set_world(self.net, src.x, src.y, None, src.h);
                en.roadless = false;
            }
            // Both branches mark the move (esmini's dirty bits): no default controller this step.
            en.teleported = true;
            en.moved_by_action = true;
        }
        if restart {
            if let Some(g) = self.ghost.as_mut() {
                g.mode = GhostMode::Restart;
                g.trail = Trail::default();
            }
            // Without a head start no time rewinds: nothing to note.
            let rewinds = self.ghost.as_ref().is_some_and(|g| g.headstart > 0.0);
            if rewinds && !self.warnings.contains(&note) {
                self.warnings.push(note);
            }
            self.reset_ghost_events();
        }
        self.log_added_teleport("running", "end", "complete");
    }

    /// The event's actions have started.
    pub(crate) fn ghost_event_started(&mut self) {
        if let Some(g) = self.ghost.as_mut() {
            g.start_shift = 0.0;
        }
    }

    /// How much earlier than the clock an action instance on entity `e` starts (`starting`) or
    /// steps: after an added teleport its event's actions start the head start earlier, and in
    /// the step of a restart the ghost's story actions step at the rewound time (esmini's
    /// `Event::Start` adjusted time and `Event::Step` in RESTART mode; Init actions keep it).
    pub(crate) fn ghost_time_shift(&self, slot: usize, e: usize, starting: bool) -> f64 {
        let Some(g) = self.ghost.as_ref() else { return 0.0 };
        if starting {
            g.start_shift
        } else if g.mode == GhostMode::Restart && e == g.entity && !self.init_actions.contains(&slot) {
            g.headstart
        } else {
            0.0
        }
    }

    /// The run ends at `t` because ghost restarts kept rewinding time (`run.rs` caps them).
    pub(crate) fn warn_endless_restarts(&mut self, t: f64) {
        let Some((_, w)) = self.ghost.as_ref().and_then(|g| g.restart_events.first()) else { return };
        let message = format!("the ghost restarts kept rewinding time (over ten rewound steps per step of the run, or a million); the run ends at {t:.2} s");
        let w = crate::Diagnostic { message, ..w.clone() };
        self.warnings.push(w);
    }

    fn log_added_teleport(&mut self, from: &str, transition: &str, to: &str) {
        self.events.push(StoryboardEvent {
            time: self.time,
            element: ADDED_TELEPORT.to_string(),
            from: from.to_string(),
            transition: transition.to_string(),
            to: to.to_string(),
        });
    }

    /// End the running actions that move entity `e` (esmini's domain conflict on a starting
    /// teleport, which holds the lateral and longitudinal domains).
    fn end_running_actions_of(&mut self, e: usize) {
        let nodes: Vec<usize> = self.actions.iter().filter(|a| a.running && a.domains() != 0 && a.actors.contains(&e)).map(|a| a.node).collect();
        for n in nodes {
            self.end_element(n);
        }
    }

    /// esmini's `ScenarioEngine::ResetEvents`, on a restart: each completed event with a
    /// teleport among its private actions (an added one, or a TeleportAction handed to the
    /// ghost) is looked at action by action, in its order (the added teleport first, then one
    /// action per actor): an action on the ghost while the event is still complete puts the
    /// event back to standby with its children and fresh triggers and zero executions; every
    /// other private action takes one execution off (so the count can fall below zero and
    /// the event run more often than its maximum, as in esmini).
    fn reset_ghost_events(&mut self) {
        let Some(g) = self.ghost.as_ref() else { return };
        let ghost = g.entity;
        let restart_events: Vec<usize> = g.restart_events.iter().map(|(e, _)| *e).collect();
        for id in 0..self.nodes.len() {
            let n = &self.nodes[id];
            if n.kind != Kind::Event || n.state != State::Complete {
                continue;
            }
            // (on the ghost, a teleport) per private action, in esmini's order.
            let mut private: Vec<(bool, bool)> = Vec::new();
            if restart_events.contains(&id) {
                private.push((true, true));
            }
            for &c in &n.children {
                let Some(slot) = self.nodes[c].action.and_then(|a| self.actions.get(a)) else { continue };
                let ActionKind::Private(p) = &slot.model.kind else { continue };
                let teleport = matches!(p, PrivateAction::Teleport(_));
                private.extend(slot.actors.iter().map(|&a| (a == ghost, teleport)));
            }
            if !private.iter().any(|&(_, teleport)| teleport) {
                continue;
            }
            for (on_ghost, _) in private {
                if on_ghost && self.nodes[id].state == State::Complete {
                    self.reset_event_to_standby(id);
                    self.nodes[id].executions = 0;
                } else {
                    self.nodes[id].executions -= 1;
                }
            }
        }
    }

    /// esmini's `StoryBoardElement::Reset(STANDBY)` of an event: it and its actions to standby
    /// (no transition logged), its triggers fresh.
    fn reset_event_to_standby(&mut self, id: usize) {
        for k in 0..self.nodes[id].children.len() {
            let c = self.nodes[id].children[k];
            self.nodes[c].state = State::Standby;
            if let Some(slot) = self.nodes[c].action {
                self.actions[slot].running = false;
            }
        }
        self.nodes[id].state = State::Standby;
        for t in [self.nodes[id].start_trigger, self.nodes[id].stop_trigger].into_iter().flatten() {
            self.triggers[t].reset(self.state_log.len());
        }
    }
}
