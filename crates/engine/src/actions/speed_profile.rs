//! SpeedProfileAction, planned as esmini 3.6 plans it when the action starts: the entries
//! become speed vertices in time (entry times are durations; a missing time is the time the
//! speed change takes at the maximum acceleration / deceleration). In `position` mode the
//! speed is linear between vertices; in `follow` mode acceleration changes at the jerk limits
//! (maximum acceleration / deceleration rates), so corners are rounded and vertices reached
//! late or early. The plan is a list of segments v(t) = v + k·(t − t0) + j·(t − t0)²/2.

pub(crate) mod state;

use state::{Segment, SpeedProfileRt};

use super::dynamic_constraints::{limits, Limits, Performance};
use super::state::ActionRt;
use crate::sim::Sim;
use openscenario::{DynamicConstraints, FollowingMode, SpeedProfileEntry};

/// esmini's SMALL_NUMBER, used for the planner's comparisons.
const EPS: f64 = 1e-6;

#[derive(Debug, Clone, Copy)]
struct Vertex {
    t: f64,
    v: f64,
    k: f64,
    /// Intercept of the line through the vertex with slope k: v − k·t.
    m: f64,
}

impl Vertex {
    fn new(t: f64, v: f64, k: f64) -> Vertex {
        Vertex { t, v, k, m: v - k * t }
    }
    fn set_k(&mut self, k: f64) {
        self.k = k;
        self.m = self.v - k * self.t;
    }
}

struct Planner {
    lim: Limits,
    follow: bool,
    segments: Vec<Segment>,
}

impl Planner {
    /// Add a segment; a value outside the constraints makes the rest of the plan linear.
    fn add(&mut self, t: f64, v: f64, k: f64, j: f64) {
        if self.follow {
            let l = self.lim;
            if v.abs() > l.speed + EPS || k > l.acc + EPS || k < -l.dec - EPS || j > l.acc_rate + EPS || j < -l.dec_rate - EPS {
                self.follow = false;
            }
        }
        self.segments.push(Segment { t, v, k, j });
    }
}

impl<'a> Sim<'a> {
    pub(super) fn start_speed_profile(
        &mut self,
        slot: usize,
        e: usize,
        entity: Option<&str>,
        mode: FollowingMode,
        constraints: Option<&DynamicConstraints>,
        entries: &[SpeedProfileEntry],
    ) -> ActionRt {
        let Some(en) = self.entities.get(e) else { return ActionRt::Done };
        if entries.is_empty() {
            return ActionRt::Done;
        }
        let offset = match entity {
            Some(name) => match self.action_ref_index(slot, name) {
                Some(i) => self.entities[i].speed,
                None => {
                    self.warn_action(slot, format!("SpeedProfileAction: unknown reference entity `{name}`"));
                    return ActionRt::Done;
                }
            },
            None => 0.0,
        };
        let lim = limits(constraints, Performance { speed: en.max_speed, acc: en.max_acc, dec: en.max_dec });
        // LongSpeedProfileAction::Start: init_acc_ is Position::GetAccLong, the world
        // acceleration's component along the heading, not the speed's rate of change
        let segments = plan(self.time, en.speed, en.acc_long(), offset, mode == FollowingMode::Follow, lim, entries);
        ActionRt::SpeedProfile(SpeedProfileRt { segments, current: 0, speed: en.speed, entries: entries.len() })
    }

    pub(super) fn step_speed_profile(&mut self, e: usize, p: &mut SpeedProfileRt) -> bool {
        let time = self.time + self.dt;
        let Some(last) = p.segments.last().copied() else { return true };
        if time < last.t + 10.0 && !(time > last.t && (p.speed - last.v).abs() < EPS) {
            while p.current + 1 < p.segments.len() && time > p.segments[p.current + 1].t - EPS {
                p.current += 1;
            }
            let s = p.segments[p.current];
            let d = time - s.t;
            p.speed = s.v + s.k * d + 0.5 * s.j * d * d;
        }
        // esmini compares the segment index with the entry count here.
        let done = p.current + 1 >= p.entries && (p.speed - last.v).abs() < EPS;
        if done {
            p.speed = last.v;
        }
        if let Some(en) = self.entities.get_mut(e) {
            en.speed = p.speed;
        }
        done
    }
}

/// The speed plan from `now` for an entity at `speed` with acceleration `acc0`.
fn plan(now: f64, speed: f64, acc0: f64, offset: f64, follow: bool, lim: Limits, entries: &[SpeedProfileEntry]) -> Vec<Segment> {
    let mut vx: Vec<Vertex> = Vec::with_capacity(entries.len() + 1);
    let mut index = 0;
    let first_time = entries[0].time;
    match first_time {
        Some(t) if t > EPS => vx.push(Vertex::new(now, speed, 0.0)),
        Some(_) if follow => {
            vx.push(Vertex::new(now, speed, 0.0));
            index = 1;
        }
        Some(_) => vx.push(Vertex::new(now, entries[0].speed, 0.0)),
        None => vx.push(Vertex::new(now, speed, 0.0)),
    }
    let mut time = now;
    let n = entries.len();
    while index < n {
        let entry = &entries[index];
        let target = entry.speed + offset;
        let Some(back) = vx.last().copied() else { break };
        // A missing time reads as −1, as esmini stores it (LongSpeedProfileAction::Start).
        let dt = entry.time.unwrap_or(-1.0);
        let mut k = (target - back.v) / dt;
        if dt < -EPS || k < -lim.dec || k > lim.acc {
            // No time, or a slope beyond the limits: the change takes the time it needs at
            // the limit, counted from the previous vertex moved to the current time.
            let dv = target - back.v;
            if dv.abs() < EPS {
                index += 1;
                continue;
            }
            k = if dt < -EPS {
                if dv < 0.0 {
                    (-lim.dec).min(-EPS)
                } else {
                    lim.acc.max(EPS)
                }
            } else if k < 0.0 {
                k.max(-lim.dec)
            } else {
                k.min(lim.acc)
            };
            if let Some(b) = vx.last_mut() {
                b.t = time;
            }
            time += dv / k;
        } else {
            time += dt;
        }
        // esmini tests the entry's own time here (also −1 for a missing one): a vertex with
        // no duration, the last excepted, replaces the previous one.
        if index + 1 < n && dt < EPS {
            if let Some(b) = vx.last_mut() {
                *b = Vertex::new(time, target, 0.0);
            }
            index += 1;
            continue;
        }
        if let Some(b) = vx.last_mut() {
            b.set_k(k);
        }
        let len = vx.len();
        let delta_k = if index > 1 && len >= 2 { vx[len - 1].k - vx[len - 2].k } else { vx[len - 1].k - acc0 };
        if delta_k.abs() < EPS && index > 1 && len >= 2 {
            let prev = vx[len - 2];
            let new_k = (target - prev.v) / (time - prev.t);
            vx[len - 1] = Vertex::new(time, target, new_k);
            index += 1;
            continue;
        }
        vx.push(Vertex::new(time, target, 0.0));
        index += 1;
    }

    let mut p = Planner { lim, follow, segments: Vec::new() };
    let first = vx[0];
    if vx.len() == 1 {
        p.add(first.t, first.v, 0.0, 0.0);
    } else if follow && vx.len() == 2 {
        single_target(&mut p, acc0, vx[0], vx[1]);
    } else {
        several_targets(&mut p, now, acc0, &vx);
    }
    p.segments
}

/// Follow mode towards one speed: jerk, optional constant acceleration, jerk back to zero.
fn single_target(p: &mut Planner, k0: f64, a: Vertex, b: Vertex) {
    let l = p.lim;
    let j0 = if a.k - k0 < 0.0 { -l.dec_rate } else { l.acc_rate };
    p.add(a.t, a.v, k0, j0);
    let j1 = if a.k < 0.0 { l.acc_rate } else { -l.dec_rate };
    let (t0, v0, mut t3, v3) = (a.t, a.v, b.t, b.v);
    let (mut t1, mut v1, mut k1, mut t2, mut v2): (f64, f64, f64, f64, f64);
    k1 = 0.0;
    t2 = 0.0;
    v2 = 0.0;
    if (j1 - j0).abs() < EPS {
        if (t0 - t3).abs() > EPS && (j1 * (t0 - t3) - k0).abs() > EPS {
            t1 = (2.0 * j1 * (v0 + t0 * j1 * (t0 - t3) - v3) + k0 * k0 + 2.0 * k0 * j1 * (t3 - 2.0 * t0)) / (2.0 * j1 * (j1 * (t0 - t3) - k0));
            if t1 >= 0.0 {
                v1 = v0 + k0 * (t1 - t0) + j0 * 0.5 * (t1 - t0).powi(2);
                k1 = k0 + j0 * (t1 - t0);
                t2 = k1 / j1 + t3;
                if t2 >= 0.0 {
                    v2 = v1 + k1 * (t2 - t1);
                    if k1 < l.acc && k1 > -l.dec {
                        p.add(t1, v1, k1, 0.0);
                    }
                }
            }
        }
    } else {
        let factor = j0 * j1 * (2.0 * v0 * (j1 - j0) + k0 * k0 + 2.0 * k0 * j1 * (t3 - t0) + j0 * j1 * (t0 - t3).powi(2) + 2.0 * v3 * (j0 - j1));
        if factor < 0.0 {
            // No time for a stretch of constant acceleration.
            t2 = ((j1 * (-(j0 - j1)) * (j0 * (2.0 * v3 - 2.0 * v0) + k0 * k0)).sqrt() + (j0 - j1) * (t0 * j0 - k0)) / (j0 * (j0 - j1));
            v2 = v0 + k0 * (t2 - t0) + j0 * 0.5 * (t2 - t0).powi(2);
            k1 = k0 + j0 * (t2 - t0);
            t3 = t2 - k1 / j1;
        } else {
            t1 = (-factor.sqrt() - j0 * (k0 + t3 * j1) + t0 * j0 * j0) / (j0 * (j0 - j1));
            v1 = v0 + k0 * (t1 - t0) + j0 * 0.5 * (t1 - t0).powi(2);
            k1 = k0 + j0 * (t1 - t0);
            t2 = k1 / j1 + t3;
            v2 = v1 + k1 * (t2 - t1);
            if k1 >= -l.dec && k1 <= l.acc {
                p.add(t1, v1, k1, 0.0);
            }
        }
    }
    if k1 >= -l.dec && k1 <= l.acc {
        p.add(t2, v2, k1, j1);
        p.add(t3, v3, 0.0, 0.0);
    } else {
        k1 = k1.clamp(-l.dec, l.acc);
        t1 = t0 + (k1 - k0) / j0;
        v1 = v0 + k0 * (t1 - t0) + 0.5 * j0 * (t1 - t0).powi(2);
        t2 = (v3 - v1) / k1 + t1 + k1 / (2.0 * j1);
        v2 = v3 + k1 * k1 / (2.0 * j1);
        t3 = -v1 / k1 + v3 / k1 + t1 - k1 / (2.0 * j1);
        p.add(t1, v1, k1, 0.0);
        p.add(t2, v2, k1, j1);
        p.add(t3, v3, 0.0, 0.0);
    }
}

/// Several speeds: linear between vertices (position mode), or the lines through the
/// vertices joined by jerk segments (follow mode, falling back to linear when impossible).
fn several_targets(p: &mut Planner, now: f64, acc0: f64, vx: &[Vertex]) {
    let l = p.lim;
    let first = vx[0];
    let (mut t3, mut v3, mut k1, mut m1, mut j) = (first.t, 0.0, 0.0, 0.0, 0.0);
    let mut k0 = acc0;
    if p.follow {
        if first.k.abs() > EPS {
            j = if first.k - k0 < 0.0 { -l.dec_rate } else { l.acc_rate };
            p.add(first.t, first.v, k0, j);
            t3 = first.t + if j.abs() > EPS { (first.k - k0) / j } else { 0.0 };
        }
        v3 = first.v + k0 * (t3 - now) + 0.5 * j * (t3 - now).powi(2);
        k1 = first.k;
        m1 = v3 - k1 * t3;
        p.add(t3, v3, k1, 0.0);
    }
    for index in 0..vx.len() {
        if !p.follow {
            let v = vx[index];
            p.add(v.t, v.v, v.k, 0.0);
        } else if index + 1 < vx.len() {
            k0 = k1;
            let v = vx[index + 1];
            let (t0, v0, m0) = (t3, v3, m1);
            k1 = v.k;
            m1 = v.m;
            j = if v.k - k0 < 0.0 { -l.dec_rate } else { l.acc_rate };
            if (k0 - k1).abs() < EPS {
                t3 = t0;
                v3 = v0;
            } else {
                // Where the jerk must start so that it ends on the next line.
                let t1 = (k0 * k0 - 2.0 * k0 * k1 + k1 * k1 - 2.0 * j * (m0 - m1)) / (2.0 * j * (k0 - k1));
                if t1 < t0 {
                    p.follow = false;
                    continue;
                }
                let v1 = v0 + k0 * (t1 - t0);
                t3 = t1 + (v.k - k0) / j;
                v3 = v1 + k0 * (t3 - t1) + 0.5 * j * (t3 - t1).powi(2);
                p.add(t1, v1, k0, j);
            }
            p.add(t3, v3, v.k, 0.0);
        }
    }
}
