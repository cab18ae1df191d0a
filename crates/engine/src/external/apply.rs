//! Where the outside takes effect in a frame. esmini steps its controllers after the default
//! controller (ScenarioEngine::step), so an external entity is put where its input says right
//! after the default controller has moved the others and before the driver models that follow
//! (ACC, ghosts' followers, NaturalDriver, …) look at it; the storyboard's triggers see it in
//! the next frame. The default controller never moves it (esmini: a controller overrides both
//! domains), and its actions follow `overridden`. With `ScriptedMotion::Replaced` the
//! storyboard, the default controller and the entity's own driver models move it as in an
//! open-loop run, and the outside's state replaces the result at the end of the step's moves.

use super::choice::{Chosen, External, ExternalEntity, ScriptedMotion, Source, OUTSIDE_DRIVERS};
use super::driven::{Driven, LastState, Pose};
use super::input::Input;
use crate::dynamics::SMALL;
use crate::entities::Entity;
use crate::roads::move_along_s;
use crate::roads::road_follow::at_dead_end;
use crate::sim::Sim;
use crate::Diagnostic;
use opendrive::RoadNetwork;

impl<'a> Sim<'a> {
    /// Whether the storyboard's motion yields to the outside for entity `e` now (driven from
    /// outside, under esmini's override rule).
    pub(crate) fn outside(&self, e: usize) -> bool {
        self.entities.get(e).is_some_and(|en| en.outside)
    }

    /// Whether controller type `kind` makes its entity external in this run.
    pub(crate) fn waits_for_outside_driver(&self, kind: &str) -> bool {
        self.external_choice.entities == Chosen::Controllers && OUTSIDE_DRIVERS.contains(&kind)
    }

    /// Entity `e` gets `c`, a controller that needs an outside driver: external from the
    /// step `c` is activated.
    pub(crate) fn await_outside_driver(&mut self, e: usize, c: &openscenario::Controller) {
        if let Some(slot) = self.external.get_mut(e) {
            let active = slot.as_ref().is_some_and(|d| d.active);
            *slot = Some(Driven::new(Source::Controller(c.clone()), active));
        }
    }

    /// The named entities of `choice`: `Err` naming an entity the scenario does not have.
    pub(crate) fn name_external(&mut self, choice: &External) -> Result<(), String> {
        let Chosen::Named(names) = &choice.entities else { return Ok(()) };
        for name in names {
            let Some(e) = self.entity_index(name) else {
                let known: Vec<&str> = self.entities.iter().map(|en| en.name.as_str()).collect();
                return Err(format!("no entity named `{name}` to drive from outside; the scenario has {}", known.join(", ")));
            };
            self.external[e] = Some(Driven::new(Source::Named, false));
        }
        Ok(())
    }

    /// Whether the caller named entity `e` and its motion yields to the outside (its own
    /// controllers are then not assigned: a driver model would move it again after the
    /// outside did; with `ScriptedMotion::Replaced` they drive it, and are replaced).
    pub(crate) fn named_external(&self, e: usize) -> bool {
        let Chosen::Named(names) = &self.external_choice.entities else { return false };
        self.external_choice.motion == ScriptedMotion::Overridden && self.entities.get(e).is_some_and(|en| names.contains(&en.name))
    }

    /// Frame 0 is over: the named entities, where Init put them, are the caller's from now on.
    pub(crate) fn start_named_external(&mut self) {
        for e in 0..self.external.len() {
            if matches!(self.external[e], Some(Driven { source: Source::Named, .. })) {
                self.set_outside(e, true);
            }
        }
    }

    /// ActivateControllerAction (or an AssignControllerAction that activates) on `e` with these
    /// domains: an entity waiting for an outside driver becomes external, or stops being so
    /// when both domains are switched off.
    pub(crate) fn activate_outside_driver(&mut self, slot: usize, e: usize, lateral: bool, longitudinal: bool) {
        if !matches!(self.external.get(e), Some(Some(Driven { source: Source::Controller(_), .. }))) {
            return;
        }
        if lateral != longitudinal {
            let (on, off) = if lateral { ("lateral", "longitudinal") } else { ("longitudinal", "lateral") };
            self.warn_action(slot, format!("the outside driver's controller is activated on the {on} domain only; osc2cr lets the outside set the whole pose, as esmini's UDP driver does, so the {off} motion is the outside's too"));
        }
        self.set_outside(e, lateral || longitudinal);
    }

    fn set_outside(&mut self, e: usize, on: bool) {
        let Some(en) = self.entities.get_mut(e) else { return };
        let Some(Some(d)) = self.external.get_mut(e) else { return };
        if on && !d.active {
            // ControllerUDPDriver::Activate: the vehicle model starts at the entity's pose
            // and speed, as long as its bounding box.
            d.vehicle = super::driver_vehicle::udp_driver_vehicle(en.x, en.y, en.h, en.speed, en.bbox[3]);
        }
        d.active = on;
        en.outside = on && self.external_choice.motion == ScriptedMotion::Overridden;
    }

    /// The entities driven from outside, or waiting to be.
    pub(crate) fn external_entities(&self) -> Vec<ExternalEntity> {
        (self.external.iter().enumerate())
            .filter_map(|(index, d)| {
                let d = d.as_ref()?;
                let name = self.entities.get(index)?.name.clone();
                Some(ExternalEntity { index, name, source: d.source.clone(), active: d.active })
            })
            .collect()
    }

    /// The inputs of the next frame: one for each entity driven from outside now, none for an
    /// entity that is not external (an entity waiting for its controller may have one: it is
    /// used if the controller is activated in this frame).
    pub(crate) fn give_inputs(&mut self, inputs: &[(usize, Input)]) -> Result<(), String> {
        for (en, d) in self.entities.iter().zip(self.external.iter_mut()) {
            if let Some(d) = d {
                d.input = None;
                d.start = Some(Pose::of(en));
            }
        }
        for (e, input) in inputs {
            let name = self.entities.get(*e).map(|en| en.name.clone()).ok_or_else(|| format!("no entity with index {e}"))?;
            input.check().map_err(|m| format!("input for `{name}`: {m}"))?;
            let Some(Some(d)) = self.external.get_mut(*e) else {
                let external: Vec<String> = self.external_entities().into_iter().map(|x| x.name).collect();
                let list = if external.is_empty() {
                    "none is".to_string()
                } else {
                    format!("{} {}", external.join(", "), if external.len() == 1 { "is" } else { "are" })
                };
                return Err(format!("`{name}` is not driven from outside ({list})"));
            };
            if d.input.replace(*input).is_some() {
                return Err(format!("two inputs for `{name}` in one step"));
            }
        }
        match self.external.iter().position(|d| d.as_ref().is_some_and(|d| d.active && d.input.is_none())) {
            Some(e) => {
                let name = self.entities.get(e).map_or("?", |en| en.name.as_str());
                Err(format!("no input for `{name}`, which is driven from outside (give a state, driver input, or hold)"))
            }
            None => Ok(()),
        }
    }

    /// Put every entity driven from outside where its input says: under esmini's override rule
    /// right after the default controller (`at` = Overridden), when the outside replaces the
    /// scripted motion at the end of the step's moves (`at` = Replaced), so that the entity's
    /// own driver models move it from where it was, as they would have.
    pub(crate) fn apply_external(&mut self, dt: f64, at: ScriptedMotion) {
        if self.external_choice.motion != at {
            return;
        }
        let net = self.net;
        let replaced = at == ScriptedMotion::Replaced;
        let mut ends = Vec::new();
        for (e, (en, d)) in self.entities.iter_mut().zip(self.external.iter_mut()).enumerate() {
            let Some(d) = d.as_mut().filter(|d| d.active) else { continue };
            let input = d.input.take().unwrap_or(Input::Hold);
            d.yaw_rate = None;
            if !en.active {
                continue;
            }
            // Without a road network a height stays as it is.
            let road_z = |given: Option<f64>, z: f64| given.or(if net.is_none() { Some(z) } else { None });
            let target = match input {
                Input::State(s) => {
                    d.last_state = Some(LastState { speed: s.speed, h: s.h, z_given: s.z.is_some() });
                    (d.yaw_rate, d.pitch, d.roll) = (s.yaw_rate, s.pitch, s.roll);
                    Some((s.x, s.y, road_z(s.z, en.z), s.h, s.speed))
                }
                Input::Driver(i) => {
                    if dt > SMALL {
                        d.vehicle.drive(dt, i.throttle - i.brake, i.steering);
                    }
                    (d.pitch, d.roll) = (None, None);
                    let car = d.vehicle.car;
                    Some((car.x, car.y, road_z(None, en.z), car.h, car.speed))
                }
                // ControllerUDPDriver::Step: on at the last message's speed and heading, the
                // heading that of the vehicle model. Nothing gives the entity a speed there, so
                // esmini derives it from the displacement (prepareGroundTruth): never negative.
                Input::DeadReckon => match (d.last_state.filter(|_| dt > SMALL), d.start) {
                    (Some(l), Some(from)) => {
                        from.put(en);
                        let (x, y) = (en.x + l.speed * dt * l.h.cos(), en.y + l.speed * dt * l.h.sin());
                        let z = if l.z_given { Some(en.z) } else { road_z(None, en.z) };
                        Some((x, y, z, d.vehicle.car.h, l.speed.abs()))
                    }
                    // no state given yet: as held
                    _ => hold(en, d.start),
                },
                Input::Hold => hold(en, d.start),
            };
            if let Some((x, y, z, h, speed)) = target {
                place(en, net, (x, y, z, h), &mut d.end_of_road, replaced);
                if d.end_of_road && !replaced && !d.told_end_of_road {
                    d.told_end_of_road = true;
                    ends.push(e);
                }
                en.speed = speed;
                if let Input::State(_) = input {
                    // esmini's Vehicle::SetPos: the model's pose follows, its speed stays
                    (d.vehicle.car.x, d.vehicle.car.y, d.vehicle.car.h) = (en.x, en.y, en.h);
                }
            }
            en.moved_by_action = true;
        }
        for e in ends {
            if let (Some(en), Some(model)) = (self.entities.get(e), self.scenario.entities.get(e)) {
                let note = format!("`{}`, driven from outside, reached the end of its road at {:.2} s: its EndOfRoad status is seen one step later than for an entity the engine moves (esmini reads it before the outside places the entity)", en.name, self.time);
                self.warnings.push(Diagnostic::at(&model.origin, note));
            }
        }
    }

    /// After the rates are derived from the move: a yaw rate the outside gave replaces it.
    pub(crate) fn external_rates(&mut self) {
        for (en, d) in self.entities.iter_mut().zip(&self.external) {
            if let Some(r) = d.as_ref().filter(|d| d.active).and_then(|d| d.yaw_rate) {
                en.yaw_rate = r;
            }
        }
    }

    /// Pitch and roll the outside fixed for entity `e`, each where given.
    pub(crate) fn external_attitude(&self, e: usize) -> (Option<f64>, Option<f64>) {
        match self.external.get(e) {
            Some(Some(d)) if d.active => (d.pitch, d.roll),
            _ => (None, None),
        }
    }
}

/// A held entity stays where the step began (the scripted motion may have moved it meanwhile),
/// standing: esmini derives the speed of an entity nobody set it for from its displacement.
/// Nothing to place afterwards.
fn hold(en: &mut Entity, start: Option<Pose>) -> Option<(f64, f64, Option<f64>, f64, f64)> {
    if let Some(from) = start {
        from.put(en);
    }
    en.speed = 0.0;
    None
}

/// Put `en` at a world pose the outside gave. It is first moved along its lane by the distance
/// travelled, so that where junction roads overlap it stays on the road its lane leads to (as
/// the looming controller does), then located there. Under esmini's override rule the
/// end-of-road status this finds is the one the next step sees: esmini reads an entity's
/// position status before it steps the controllers (ScenarioEngine::step). When the outside
/// replaces a scripted move made in the same step (`ScriptedMotion::Replaced`), the status is
/// that move's, as the storyboard's course is.
fn place(en: &mut Entity, net: Option<&RoadNetwork>, (x, y, z, h): (f64, f64, Option<f64>, f64), end_of_road: &mut bool, replaced: bool) {
    if let (Some(net), Some(mut lp)) = (net, en.lane) {
        let travelled = (x - en.x).hypot(y - en.y);
        // forwards or backwards along the way it faces
        let along = (x - en.x) * en.h.cos() + (y - en.y) * en.h.sin();
        move_along_s(net, &mut lp, if along < 0.0 { -travelled } else { travelled });
        en.lane = Some(lp);
    }
    en.set_world(net, x, y, z, h);
    // The outside's heading is kept as given: a scenario's WorldPosition on a sloped or banked
    // road is turned by the road's rotation (EvaluateHPR), but in closed loop the entity is
    // where and as the driver outside says (a replayed run gives its own states back).
    en.h = crate::angles::wrap_2pi(h);
    let found = match (net, en.lane) {
        (Some(net), Some(lp)) => at_dead_end(net, &lp),
        _ => false,
    };
    if !replaced {
        en.at_road_end = *end_of_road;
    }
    *end_of_road = found;
}
