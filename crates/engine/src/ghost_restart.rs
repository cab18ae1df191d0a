//! esmini's ghost restart. Every ghost event whose start trigger watches something other than
//! the simulation time or the ghost itself gets a teleport of the ghost back to its entity as
//! its first action (`ScenarioEngine::CreateGhostTeleport`, "AddedGhostTeleport"). Started
//! before time 0 it is a plain teleport onto the entity; started later it restarts the ghost
//! (`TeleportAction::Start` with ghost restart): the ghost takes the entity's position and
//! speed, its trail starts afresh, and once the step is over the clock goes back by the head
//! start and runs again to where it was, only the ghost moving (`run.rs` records those steps as
//! the trace's replays, as esmini's log repeats those times).

use crate::dynamics::ESMINI_SMALL_NUMBER;
use crate::ghost::GhostMode;
use crate::ghost_trail::Trail;
use crate::sim::Sim;
use crate::trace::StoryboardEvent;

/// esmini's name of the added teleport action, as its event log shows it.
const ADDED_TELEPORT: &str = "AddedGhostTeleport";

impl<'a> Sim<'a> {
    /// Event `ev` has started and its actions are about to: run its added ghost teleport first,
    /// if it has one (esmini inserts it at the front of the event's actions).
    pub fn ghost_event_starts(&mut self, ev: usize) {
        let Some(g) = self.ghost.as_ref() else { return };
        let Some(k) = g.restart_events.iter().position(|(e, _)| *e == ev) else { return };
        let (ghost, owner) = (g.entity, g.owner);
        self.log_added_teleport("init", "start", "running");
        // Event::Start: a starting action ends the running ones of its entity on a shared
        // domain; a teleport holds both.
        self.end_running_actions_of(ghost);
        let Some(src) = self.entities.get(owner).cloned() else { return };
        // TeleportAction::Start: a restart only once the clock is past 0.
        let restart = self.time > ESMINI_SMALL_NUMBER;
        if let Some(en) = self.entities.get_mut(ghost) {
            if restart {
                // Position::Duplicate of the entity's position, and its speed.
                en.x = src.x;
                en.y = src.y;
                en.z = src.z;
                en.h = src.h;
                en.lane = src.lane;
                en.on_road = src.on_road;
                en.yaw_offset = src.yaw_offset;
                en.parallel_lane = None;
                en.route = src.route.clone();
                en.speed = src.speed;
            } else {
                // A relative object position with no offsets: the entity's pose.
                en.set_world(self.net, src.x, src.y, None, src.h);
            }
            // Both branches mark the move (esmini's dirty bits): no default controller this step.
            en.teleported = true;
            en.moved_by_action = true;
        }
        if restart {
            if let Some(g) = self.ghost.as_mut() {
                g.mode = GhostMode::Restart;
                g.trail = Trail::default();
                // Without a head start no time rewinds: nothing to note.
                let (_, note) = g.restart_events[k].clone();
                if g.headstart > 0.0 && !self.warnings.contains(&note) {
                    self.warnings.push(note);
                }
            }
            self.warn_unreset_events(ev);
        }
        self.log_added_teleport("running", "end", "complete");
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

    /// esmini's `ScenarioEngine::ResetEvents` puts the completed events that hold a teleport of
    /// the ghost (an added one, or a TeleportAction handed over) back to standby on a restart,
    /// with execution counts it can drive below zero; not modelled: a warning (once per event)
    /// at the event's first action when such an event exists.
    fn warn_unreset_events(&mut self, ev: usize) {
        let Some(g) = self.ghost.as_ref() else { return };
        let ghost = g.entity;
        let mut found = Vec::new();
        for (id, n) in self.nodes.iter().enumerate() {
            if id == ev || n.kind != crate::storyboard::Kind::Event || n.state != crate::storyboard::State::Complete {
                continue;
            }
            let slots: Vec<usize> = n.children.iter().filter_map(|&c| self.nodes[c].action).collect();
            let teleports_ghost = slots.iter().any(|&a| {
                let slot = &self.actions[a];
                slot.actors.contains(&ghost) && matches!(&slot.model.kind, openscenario::ActionKind::Private(openscenario::PrivateAction::Teleport(_)))
            });
            if teleports_ghost || g.restart_events.iter().any(|(e, _)| *e == id) {
                if let Some(&first) = slots.first() {
                    found.push((n.name.clone(), self.actions[first].model.origin.clone()));
                }
            }
        }
        for (name, origin) in found {
            let msg = format!(
                "event `{name}` is complete when the ghost restarts; esmini's ScenarioEngine::ResetEvents would make it ready to start again (its execution count reset, or lowered by one per further action), osc2cr leaves it complete"
            );
            let w = crate::Warning::at(&origin, msg);
            if !self.warnings.contains(&w) {
                self.warnings.push(w);
            }
        }
    }
}
