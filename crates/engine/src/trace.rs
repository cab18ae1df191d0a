//! The result of a run: every entity's state at every engine step, the storyboard's
//! state transitions, and every change of a traffic signal's state. This is the engine's only
//! output format; the CommonRoad converter and the conformance CSV both read it.

use std::fmt::Write as _;

/// Where an entity is on the road network.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadPos {
    /// Index of the road in `opendrive::RoadNetwork::roads`.
    pub road: u32,
    /// OpenDRIVE lane id.
    pub lane_id: i32,
    /// Lateral offset from the lane centre, m (positive to the left of the reference line direction).
    pub lane_offset: f64,
    /// Distance along the road's reference line, m.
    pub s: f64,
}

/// One entity's state at one step. Position is the entity's reference point (OpenSCENARIO
/// position; a vehicle's rear axle centre) in the road network's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Heading, rad.
    pub h: f64,
    /// Signed speed along the heading, m/s.
    pub speed: f64,
    /// Longitudinal acceleration, m/s².
    pub acceleration: f64,
    /// Rate of change of the heading, rad/s.
    pub yaw_rate: f64,
    pub road: Option<RoadPos>,
    pub visible: bool,
}

/// The samples of one entity. `samples[k]` is its state at `k * Trace::step` seconds, `None`
/// while the entity does not exist (not yet added, or deleted).
#[derive(Debug, Clone, PartialEq)]
pub struct EntityTrace {
    pub name: String,
    pub samples: Vec<Option<Sample>>,
}

/// A storyboard element changed state (for comparison with esmini's event log).
#[derive(Debug, Clone, PartialEq)]
pub struct StoryboardEvent {
    pub time: f64,
    pub element: String,
    pub from: String,
    pub transition: String,
    pub to: String,
}

/// A traffic signal took a state (OpenSCENARIO state text, e.g. "off;off;on") at `time`, set by
/// a TrafficSignalStateAction or by a phase of a traffic-signal controller.
#[derive(Debug, Clone, PartialEq)]
pub struct SignalState {
    pub time: f64,
    /// The signal's name in the scenario (its OpenDRIVE signal id).
    pub signal: String,
    pub state: String,
}

/// Everything a run produced.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Trace {
    /// Time of the first step, s: 0, or −head start when a ghost runs ahead (`ghost/`).
    pub start: f64,
    /// Engine step, s.
    pub step: f64,
    /// Number of steps recorded; every `EntityTrace::samples` has this length.
    pub len: usize,
    pub entities: Vec<EntityTrace>,
    pub events: Vec<StoryboardEvent>,
    /// Every change of a traffic signal's state, in the order it happened (time 0 holds the
    /// initial states). Only signals that a controller or an action sets appear.
    pub signal_states: Vec<SignalState>,
    /// Entities that are ghosts (FollowGhost/FollowReference run them ahead of their entity):
    /// part of the run, not road users.
    pub ghosts: Vec<String>,
    /// Steps run again after a ghost restart (`ghost/restart.rs`): time went back by the head
    /// start and only the ghost moved. Not part of `entities` (whose samples keep each time
    /// once, the first pass); the CSV lists them where esmini's log has them.
    pub replays: Vec<Replay>,
}

/// Steps a ghost restart ran again, logged after row `after`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Replay {
    /// Index of the row these steps follow.
    pub after: usize,
    /// Time of the first replayed step, s; the others follow at `Trace::step`.
    pub start: f64,
    /// One row per replayed step: each entity's sample, in `Trace::entities` order.
    pub rows: Vec<Vec<Option<Sample>>>,
}

impl Trace {
    /// Time of step `k`, s.
    pub fn time(&self, k: usize) -> f64 {
        self.start + k as f64 * self.step
    }

    /// Simulated duration, s (from the first to the last recorded step).
    pub fn duration(&self) -> f64 {
        self.len.saturating_sub(1) as f64 * self.step
    }

    /// Time of the last recorded step, s (the scenario's end; `duration()` when `start` is 0).
    pub fn end_time(&self) -> f64 {
        self.time(self.len.saturating_sub(1))
    }

    /// Index of the row at time 0: 0, or the number of head-start rows a ghost ran before the
    /// scenario's own time began (those rows are not part of the scenario).
    pub fn zero_index(&self) -> usize {
        if self.start < 0.0 && self.step > 0.0 {
            ((-self.start / self.step).round() as usize).min(self.len)
        } else {
            0
        }
    }

    /// The trace as CSV in the format `conformance.py` reads
    /// (`time,entity,x,y,z,h,speed,bb_cx,...,lane_id,lane_offset,s`). `boxes` gives each
    /// entity's bounding box `(cx, cy, cz, length, width, height)` by index.
    pub fn to_csv(&self, boxes: &[[f64; 6]]) -> String {
        let mut out = String::from("time,entity,x,y,z,h,speed,bb_cx,bb_cy,bb_cz,length,width,height,lane_id,lane_offset,s\n");
        for k in 0..self.len {
            let t = self.time(k);
            let row = self.entities.iter().map(|e| e.samples.get(k).copied().flatten());
            self.csv_row(&mut out, t, row, boxes);
            for r in self.replays.iter().filter(|r| r.after == k) {
                for (j, row) in r.rows.iter().enumerate() {
                    self.csv_row(&mut out, r.start + j as f64 * self.step, row.iter().copied(), boxes);
                }
            }
        }
        out
    }

    fn csv_row(&self, out: &mut String, t: f64, row: impl Iterator<Item = Option<Sample>>, boxes: &[[f64; 6]]) {
        for (i, (e, s)) in self.entities.iter().zip(row).enumerate() {
            let Some(s) = s else { continue };
            let b = boxes.get(i).copied().unwrap_or([0.0; 6]);
            let _ = write!(
                out,
                "{:.3},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},",
                t,
                csv_field(&e.name),
                s.x,
                s.y,
                s.z,
                s.h,
                s.speed,
                b[0],
                b[1],
                b[2],
                b[3],
                b[4],
                b[5]
            );
            match s.road {
                Some(r) => {
                    let _ = writeln!(out, "{},{:.4},{:.4}", r.lane_id, r.lane_offset, r.s);
                }
                None => out.push_str(",,\n"),
            }
        }
    }
}

/// Quote a CSV field when it needs it.
fn csv_field(s: &str) -> std::borrow::Cow<'_, str> {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\"")).into()
    } else {
        s.into()
    }
}
