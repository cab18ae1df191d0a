//! How fast the simulation runs against the wall clock. A client in asynchronous mode sends
//! when it likes and expects the simulation to move on in real time (esmini's player without
//! `--fixed_timestep`), so a run with an asynchronous port runs in real time by default, each
//! step computed no earlier than its simulated time (scaled by a factor). In synchronous mode
//! the client and the simulation go in lockstep — each step waits for its datagram — so the run
//! goes as fast as the datagrams come (esmini with `--fixed_timestep`).

use std::time::{Duration, Instant};

/// The pace of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pace {
    /// Simulated seconds per wall-clock second (1: real time).
    RealTime(f64),
    /// No waiting but for the datagrams of synchronous ports.
    AsFastAsPossible,
}

/// The wall clock of a run started now.
#[derive(Debug, Clone, Copy)]
pub struct Clock {
    start: Instant,
    pace: Pace,
}

impl Clock {
    pub fn start(pace: Pace) -> Clock {
        Clock { start: Instant::now(), pace }
    }

    /// Waits until simulated time `t` (from the start of the run) is due.
    pub fn wait_until(&self, t: f64) {
        let Pace::RealTime(factor) = self.pace else { return };
        if !(factor > 0.0 && factor.is_finite() && t.is_finite() && t > 0.0) {
            return;
        }
        let Ok(due) = Duration::try_from_secs_f64(t / factor) else { return };
        let elapsed = self.start.elapsed();
        if due > elapsed {
            std::thread::sleep(due - elapsed);
        }
    }
}
