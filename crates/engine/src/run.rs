//! The main loop, a frame at a time (`Simulation`). One frame, as esmini orders it (`frame`):
//! the storyboard is evaluated and its actions stepped at the current time t (triggers first,
//! then Init actions, then story actions in document order); if it is still running, time
//! advances to t + dt, the driver models that act before it step, the default controller
//! moves every entity no action moved, the entities driven from outside are put where their
//! inputs say, the driver models esmini steps after the default controller step, and the state
//! at t + dt is recorded. Frame 0 runs the Init actions and the first evaluation with dt = 0
//! and records the state at t = 0. The run ends when the storyboard's stop trigger fires (no
//! row is recorded for that frame) or after the row at the maximum time.
//!
//! Everything a frame changes is in `Sim` (`sim.rs`, data only); each call below is one
//! behaviour's step over it.

use crate::external::{External, ExternalEntity, Input, ScriptedMotion};
use crate::motion::Before;
use crate::run_memos::RunMemos;
use crate::sim::Sim;
use crate::storyboard::{State, Transition};
use crate::trace::{EntityTrace, Replay, RoadPos, Sample, StoryboardEvent, Trace};
use crate::{Diagnostic, Error, RunControl, Settings};
use opendrive::RoadNetwork;
use openscenario::Scenario;

/// What a run produced.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    pub trace: Trace,
    pub warnings: Vec<Diagnostic>,
    /// Light states LightStateActions asked for, in the order asked (not simulated).
    pub lights: Vec<crate::LightChange>,
    /// Environments EnvironmentActions set, in the order set (not simulated).
    pub environment: Vec<crate::EnvironmentChange>,
}

/// Run `scenario` on `roads` (None: no road network; road positions then fail with warnings),
/// with esmini's random generator seeded as the reference traces were made (`--seed 0`).
pub fn simulate(scenario: &Scenario, roads: Option<&RoadNetwork>, settings: &Settings) -> Result<Run, Error> {
    let control = RunControl { seed: crate::esmini_random::DEFAULT_SEED, deadline: None };
    simulate_with(scenario, roads, settings, &control)
}

/// Steps between two looks at the clock when a deadline is set.
const DEADLINE_CHECK_STEPS: usize = 256;
/// Rewound frames of ghost restarts a run may run, per step of the run, and at most (each
/// is a row of the trace kept in memory).
const MAX_REPLAY_FACTOR: usize = 10;
const MAX_REPLAYED: usize = 1_000_000;

/// [`simulate`] with a random seed (esmini's `--seed`) and an optional wall-clock deadline.
pub fn simulate_with(scenario: &Scenario, roads: Option<&RoadNetwork>, settings: &Settings, control: &RunControl) -> Result<Run, Error> {
    let mut run = Simulation::new(scenario, roads, settings, control, &External::none())?;
    // The run's memo entries stay in the thread's slots for all its frames: swapping them in
    // and out around every frame (what a lone `step` must do) costs more than the road
    // lookups of a light frame. Memos are pure caches, so the trace is the same either way.
    let mut memos = run.memos.take();
    let entered = memos.enter();
    while run.step()? {}
    drop(entered);
    Ok(run.finish())
}

/// A run one frame at a time: [`Simulation::new`] runs frame 0 (Init actions, the first
/// storyboard evaluation), each [`Simulation::step`] the next frame, until the storyboard's
/// stop trigger fires or the time cap is reached; [`Simulation::finish`] hands over the
/// [`Run`]. Stepping to the end gives exactly what [`simulate_with`] gives.
///
/// Closed loop: the entities `external` chooses are driven by the caller, who gives each of
/// them an [`Input`] for every frame ([`Simulation::step_with`]); the storyboard and the
/// driver models react to where they are (`external/`).
pub struct Simulation<'a> {
    sim: Sim<'a>,
    trace: Trace,
    before: Vec<Before>,
    memos: RunMemos,
    control: RunControl,
    t0: f64,
    dt: f64,
    /// Frames after frame 0 the time cap allows, and how many have run.
    steps: usize,
    k: usize,
    /// Rewound frames of ghost restarts run so far, and at most.
    replayed: usize,
    max_replayed: usize,
    over: bool,
}

impl<'a> Simulation<'a> {
    /// Builds the run state of `scenario` on `roads` and runs frame 0.
    pub fn new(
        scenario: &'a Scenario,
        roads: Option<&'a RoadNetwork>,
        settings: &Settings,
        control: &RunControl,
        external: &External,
    ) -> Result<Simulation<'a>, Error> {
        settings.check()?;
        let mut memos = RunMemos::new();
        let entered = memos.enter();
        let dt = settings.step;
        let mut sim = Sim::new(scenario, roads, dt, external).map_err(Error::Input)?;
        sim.random = crate::esmini_random::EsminiRandom::new(control.seed);
        // A ghost's head start runs before time 0 (ghost/); otherwise t0 = 0.
        let t0 = sim.time_origin();
        let steps = ((settings.max_time - t0) / dt + 1e-9).floor() as usize;
        let trace = Trace {
            start: t0,
            step: dt,
            len: 0,
            entities: sim.entities.iter().map(|e| EntityTrace { name: e.name.clone(), samples: Vec::with_capacity(steps + 1) }).collect(),
            events: Vec::new(),
            signal_states: Vec::new(),
            ghosts: sim.ghost.iter().filter_map(|g| sim.entities.get(g.entity)).map(|e| e.name.clone()).collect(),
            replays: Vec::new(),
        };
        let before = vec![Before::default(); sim.entities.len()];
        // Ghost restarts that keep re-arming each other would rewind time without end (esmini
        // too): the rewound frames of a run are capped.
        let max_replayed = steps.saturating_mul(MAX_REPLAY_FACTOR).min(MAX_REPLAYED);
        drop(entered);
        let mut run = Simulation { sim, trace, before, memos, control: *control, t0, dt, steps, k: 0, replayed: 0, max_replayed, over: false };
        run.first_frame();
        Ok(run)
    }

    /// Frame 0: Init actions and the first storyboard evaluation, no time passes.
    fn first_frame(&mut self) {
        let _entered = self.memos.enter();
        let (sim, before) = (&mut self.sim, &mut self.before);
        let root = 0;
        sim.time = self.t0;
        sim.clock = self.t0;
        sim.align_trailers();
        // sim.rs put the Init actions in esmini's order (init_order.rs)
        for slot in sim.init_actions.clone() {
            sim.start_action(slot);
        }
        sim.set_state(root, Transition::Start, State::Running);
        let stories = sim.nodes[root].children.clone();
        for s in stories {
            sim.start_element(s);
        }
        snapshot(sim, before);
        let restarting = sim.ghost_restarting();
        storyboard_step(sim, 0.0);
        if !restarting {
            // esmini's ScenarioEngine::step steps every active controller in frame 0 too (dt 0):
            // an ACC already stops for a lead closer than 1 m (ControllerACC::Step); a
            // FollowRoute that cannot plan its route (start and target on the same road and
            // lane) deactivates here, and in test mode stops the entity at once; an
            // OffroadFollower's vehicle model caps the speed at its limit at once
            // (ControllerOffroadFollower::Step: SetMaxSpeed, DrivingControlAnalog)
            sim.step_controllers_in_order(0.0, true);
        }
        sim.pull_trailers();
        sim.after_move(before, 0.0);
        sim.record_ghost_trail(0.0);
        record(sim, &mut self.trace);
        sim.update_ghost_mode();
        sim.start_named_external();
        self.over = self.steps == 0;
    }

    /// The entities driven from outside, or waiting for their controller to be activated.
    pub fn external(&self) -> Vec<ExternalEntity> {
        self.sim.external_entities()
    }

    /// Entity `index`'s state now (`None`: it does not exist now, or there is no such entity).
    pub fn state(&self, index: usize) -> Option<Sample> {
        self.sim.entities.get(index).and_then(sample_of)
    }

    /// Time of the newest row of the trace, s.
    pub fn time(&self) -> f64 {
        self.t0 + self.k as f64 * self.dt
    }

    /// The storyboard stopped or the time cap was reached: [`Simulation::step`] does nothing more.
    pub fn is_over(&self) -> bool {
        self.over
    }

    /// The rows so far (storyboard events and signal states are handed over by `finish`).
    pub fn trace(&self) -> &Trace {
        &self.trace
    }

    /// Storyboard state transitions so far.
    pub fn events(&self) -> &[StoryboardEvent] {
        &self.sim.events
    }

    /// Warnings so far.
    pub fn warnings(&self) -> &[Diagnostic] {
        &self.sim.warnings
    }

    /// Runs the next frame and records its row; `Ok(false)` when the run is over (the stop
    /// trigger fired in this frame — no row is recorded then — or the time cap was reached
    /// before it).
    pub fn step(&mut self) -> Result<bool, Error> {
        self.step_with(&[])
    }

    /// [`Simulation::step`] with the inputs of the entities driven from outside: one for each
    /// that is driven now (by index in the trace's entities). `Err(Error::Input)` names what is
    /// wrong (an input for an entity that is not external, a value that is not finite, …),
    /// and the frame is not run.
    pub fn step_with(&mut self, inputs: &[(usize, Input)]) -> Result<bool, Error> {
        if self.over {
            return Ok(false);
        }
        self.sim.give_inputs(inputs).map_err(Error::Input)?;
        let _entered = self.memos.enter();
        let (sim, before, trace) = (&mut self.sim, &mut self.before, &mut self.trace);
        let (t0, dt) = (self.t0, self.dt);
        let k = self.k + 1;
        if k % DEADLINE_CHECK_STEPS == 0 && self.control.deadline.is_some_and(|d| std::time::Instant::now() >= d) {
            return Err(Error::Deadline(t0 + (k - 1) as f64 * dt));
        }
        let t = t0 + k as f64 * dt;
        if !frame(sim, before, t - dt, dt) {
            self.over = true;
            return Ok(false);
        }
        self.k = k;
        record(sim, trace);
        if sim.update_ghost_mode() {
            // A ghost restart (ghost/restart.rs): the clock goes back by the head start and
            // runs up to `t` again, only the ghost moving (esmini's ScenarioPlayer::Frame runs
            // these frames before the next one).
            let headstart = sim.ghost.as_ref().map_or(0.0, |g| g.headstart);
            let after = trace.len - 1;
            let mut now = t - headstart;
            let mut replay = Replay { after, start: now + dt, rows: Vec::new() };
            let mut stopped = false;
            // esmini's step() begins with UpdateGhostMode too: with no head start to make up
            // the rewound run ends before it begins.
            while !sim.update_ghost_mode() && sim.ghost_restarting() {
                self.replayed += 1;
                if self.replayed % DEADLINE_CHECK_STEPS == 0 && self.control.deadline.is_some_and(|d| std::time::Instant::now() >= d) {
                    return Err(Error::Deadline(now));
                }
                if self.replayed > self.max_replayed {
                    sim.warn_endless_restarts(t);
                    stopped = true;
                    break;
                }
                if !frame(sim, before, now, dt) {
                    stopped = true;
                    break;
                }
                now += dt;
                replay.rows.push(sim.entities.iter().map(sample_of).collect());
                if sim.update_ghost_mode() {
                    // Restarted again while rewound: the clock goes back once more.
                    now -= headstart;
                    let next = Replay { after, start: now + dt, rows: Vec::new() };
                    trace.replays.push(std::mem::replace(&mut replay, next));
                }
            }
            if !replay.rows.is_empty() {
                trace.replays.push(replay);
            }
            if stopped {
                self.over = true;
                return Ok(false);
            }
            sim.time = t;
        }
        self.over = self.k >= self.steps;
        Ok(!self.over)
    }

    /// A copy of the run so far, as [`Simulation::finish`] would hand it over now.
    pub fn run_so_far(&self) -> Run {
        let sim = &self.sim;
        let mut trace = self.trace.clone();
        trace.events = sim.events.clone();
        trace.signal_states = sim.signals.log.clone();
        Run { trace, warnings: sim.warnings.clone(), lights: sim.lights.clone(), environment: sim.environment.clone() }
    }

    /// The run so far: its trace (storyboard events and signal states included), warnings,
    /// light states and environments.
    pub fn finish(self) -> Run {
        let Simulation { sim, mut trace, .. } = self;
        trace.events = sim.events;
        trace.signal_states = sim.signals.log;
        Run { trace, warnings: sim.warnings, lights: sim.lights, environment: sim.environment }
    }
}

/// One frame from time `t` to `t + dt`; false when the storyboard stopped (nothing moved).
fn frame(sim: &mut Sim, before: &mut [Before], t: f64, dt: f64) -> bool {
    sim.time = t;
    snapshot(sim, before);
    // ScenarioEngine::SwapAndClearDirtyBits clears the "moved" marks of the active entities
    // only: a deleted entity keeps the mark an action set while it was away, and is not moved
    // in the step it is added back.
    for e in &mut sim.entities {
        if e.active {
            e.moved_by_action = false;
            e.speed_set = false;
        }
    }
    storyboard_step(sim, dt);
    if sim.nodes[0].state != State::Running {
        return false;
    }
    // esmini asks for the ghost mode where it acts, so a restart in this storyboard step
    // (RESTARTING turned RESTART) lets everything move again from here on.
    let restarting = sim.ghost_restarting();
    sim.time = t + dt;
    sim.clock += dt;
    if restarting {
        sim.hold_during_restart();
        // ScenarioEngine::step steps injected actions (a NaturalDriver's lane change) whatever
        // the ghost mode; LatLaneChangeAction::Step only returns early for a non-ghost while
        // the (rewound) time before the step is below 0.
        sim.step_injected_during_restart(t, dt);
    } else {
        sim.step_controllers(dt);
    }
    sim.hold_trailers();
    sim.default_controller(dt);
    if !restarting {
        sim.apply_external(dt, ScriptedMotion::Overridden);
        sim.step_controllers_in_order(dt, false);
        sim.apply_external(dt, ScriptedMotion::Replaced);
    }
    sim.pull_trailers();
    sim.after_move(before, dt);
    sim.external_rates();
    sim.record_ghost_trail(dt);
    true
}

fn storyboard_step(sim: &mut Sim, dt: f64) {
    sim.dt = dt;
    sim.eval_triggers(0);
    for k in 0..sim.init_actions.len() {
        let slot = sim.init_actions[k];
        sim.step_action(slot);
    }
    sim.step_tree(0);
}

fn snapshot(sim: &Sim, before: &mut [Before]) {
    // A ghost restarted in the last step keeps its state from before it (`Sim::after_move`).
    let unmeasured = sim.ghost.as_ref().and_then(|g| g.unmeasured.then_some(g.entity));
    for (i, (b, e)) in before.iter_mut().zip(&sim.entities).enumerate() {
        // esmini stores the old state of active entities only (ScenarioEngine::prepareGroundTruth):
        // a deleted entity is measured, once added back, from where it last was.
        if unmeasured == Some(i) || !e.active {
            continue;
        }
        *b = Before { x: e.x, y: e.y, z: e.z, h: e.h, speed: e.speed };
    }
}

fn record(sim: &Sim, trace: &mut Trace) {
    for (et, e) in trace.entities.iter_mut().zip(&sim.entities) {
        et.samples.push(sample_of(e));
    }
    trace.len += 1;
}

fn sample_of(e: &crate::entities::Entity) -> Option<Sample> {
    e.active.then(|| Sample {
        x: e.x,
        y: e.y,
        z: e.z,
        h: e.h,
        speed: e.speed,
        acceleration: e.accel,
        yaw_rate: e.yaw_rate,
        road: e.lane.map(|l| RoadPos { road: l.road as u32, lane_id: l.lane_id, lane_offset: l.offset, s: l.s }),
        visible: e.visible,
    })
}
