//! esmini's trajectory filter, foreseen, and the pieces a trajectory is cut into so that the
//! filter changes no CommonRoad state.
//!
//! esmini 3.6.0 thins a polyline trajectory when an action starts following it
//! (`PolyLineShape::FinalizeVertices` in `RoadManager.cpp`, radius `--traj_filter`, 0.1 m by
//! default), and osc2cr's engine does as esmini does (`trajectory::filter_vertices`, which the
//! export runs too). With more than two vertices it walks them
//! keeping a last kept vertex A: a vertex within the radius of A (plus esmini's `SMALL_NUMBER`,
//! 1e-6) whose heading is not more than 0.1 rad *below* A's (the heading test is signed) is not
//! unique. A run of such vertices after A is dropped up to the first unique vertex C, except that
//! when C comes 1 s or more after A the last dropped vertex B stays, moved onto A (a standstill
//! from A's time to B's). The first and the last vertex always stay. Between the vertices that
//! stay, the entity moves linearly in time (position mode: the time gives the distance along the
//! polyline linearly, the distance the point on it).
//!
//! So a fast road user's trajectory comes through whole, but a slow, stopping or starting one
//! can be off by up to the radius at a CommonRoad time step. The export foresees the filter:
//! it cuts the states into consecutive pieces (each a `FollowTrajectoryAction` of its own, the
//! next started when the previous one ends) such that, for each piece, the filtered piece still
//! puts the entity within [`TOLERANCE`] of every state. A piece of two vertices is never
//! filtered, so a cut always exists; the cuts are chosen greedily, each piece as long as the
//! search finds (every piece taken has been checked).

use trajectory::{filter_vertices, PolylineVertex, Pose};

/// How far the filtered piece may put the entity from a state, m: a tenth of the 0.01 m the
/// forward conversion is held to (the rest is for simulator arithmetic).
pub(crate) const TOLERANCE: f64 = 1e-3;

/// A trajectory vertex as the simulator reads it: time (s), position (m), heading (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Vertex {
    pub t: f64,
    pub x: f64,
    pub y: f64,
    pub h: f64,
}

/// The vertices esmini keeps of `v`: the walk of osc2cr's engine (`trajectory::filter_vertices`,
/// esmini's `FinalizeVertices` at the default radius), so that export and engine agree.
pub(crate) fn filtered(v: &[Vertex]) -> Vec<Vertex> {
    let resolved: Vec<PolylineVertex> =
        v.iter().map(|p| PolylineVertex { pose: Pose::new(p.x, p.y, 0.0, p.h), time: Some(p.t), explicit_heading: true, relative: false }).collect();
    filter_vertices(&resolved).into_iter().map(|p| Vertex { t: p.time.unwrap_or(0.0), x: p.pose.x, y: p.pose.y, h: p.pose.heading }).collect()
}

/// The greatest distance between each vertex of `v` and where the filtered polyline puts the
/// entity at the vertex's time.
pub(crate) fn worst_error(v: &[Vertex]) -> f64 {
    let f = filtered(v);
    let mut j = 0;
    let mut worst = 0.0f64;
    for p in v {
        while j + 2 < f.len() && f[j + 1].t <= p.t {
            j += 1;
        }
        let (x, y) = match (f.get(j), f.get(j + 1)) {
            (Some(a), Some(b)) if b.t > a.t => {
                let k = ((p.t - a.t) / (b.t - a.t)).clamp(0.0, 1.0);
                (a.x + k * (b.x - a.x), a.y + k * (b.y - a.y))
            }
            (Some(a), _) => (a.x, a.y),
            (None, _) => (p.x, p.y),
        };
        worst = worst.max((x - p.x).hypot(y - p.y));
    }
    worst
}

fn replays(v: &[Vertex]) -> bool {
    worst_error(v) <= TOLERANCE
}

/// Consecutive pieces of `v` (index ranges, inclusive; each next one starts where the previous
/// ends) that the filter leaves replaying every vertex within [`TOLERANCE`]: one piece when
/// the whole trajectory does. Each piece is grown by doubling while it replays, then the last
/// doubling is halved back to the longest length found that replays (the filter's effect is
/// not monotonic in the length, so only checked lengths are taken).
pub(crate) fn pieces(v: &[Vertex]) -> Vec<(usize, usize)> {
    let n = v.len();
    if n <= 2 || replays(v) {
        return vec![(0, n.saturating_sub(1))];
    }
    let mut out = Vec::new();
    let mut start = 0;
    while start + 1 < n {
        // `good` replays (two vertices always do); `bad`, once found, does not
        let mut good = start + 1;
        let mut bad = None;
        let mut step = 1;
        while good + 1 < n {
            let next = (good + step).min(n - 1);
            if replays(&v[start..=next]) {
                good = next;
                step *= 2;
            } else {
                bad = Some(next);
                break;
            }
        }
        if let Some(mut bad) = bad {
            while bad - good > 1 {
                let mid = good + (bad - good) / 2;
                if replays(&v[start..=mid]) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
        }
        out.push((start, good));
        start = good;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(t: f64, x: f64) -> Vertex {
        Vertex { t, x, y: 0.0, h: 0.0 }
    }

    #[test]
    fn fast_vertices_all_stay() {
        let fast: Vec<Vertex> = (0..20).map(|k| v(0.1 * k as f64, 1.2 * k as f64)).collect();
        assert_eq!(filtered(&fast), fast);
        assert_eq!(pieces(&fast), vec![(0, 19)]);
    }

    #[test]
    fn close_vertices_go_and_a_long_standstill_stays() {
        // stands at 0 from 0 s to 2 s, then 1 m a step
        let mut s: Vec<Vertex> = (0..=20).map(|k| v(0.1 * k as f64, 0.0)).collect();
        s.extend((1..=5).map(|k| v(2.0 + 0.1 * k as f64, k as f64)));
        let f = filtered(&s);
        // the first, the standstill's last (2 s), then every moving vertex
        let times: Vec<f64> = f.iter().map(|p| p.t).collect();
        let expected = [0.0, 2.0, 2.1, 2.2, 2.3, 2.4, 2.5];
        assert!(times.len() == expected.len() && times.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-9), "{times:?}");
        assert!(worst_error(&s) < 1e-12);
        // a standstill shorter than a second is lost: the entity creeps from 0 instead
        let mut short: Vec<Vertex> = (0..=5).map(|k| v(0.1 * k as f64, 0.0)).collect();
        short.extend((1..=5).map(|k| v(0.5 + 0.1 * k as f64, k as f64)));
        assert_eq!(filtered(&short).len(), 6);
        assert!(worst_error(&short) > 0.4);
        // cut where the standstill ends: each piece replays
        let p = pieces(&short);
        assert_eq!(p, vec![(0, 5), (5, 10)]);
        assert!(p.iter().all(|&(a, b)| worst_error(&short[a..=b]) <= TOLERANCE));
    }

    #[test]
    fn the_heading_test_is_signed() {
        let at = |t: f64, x: f64, h: f64| Vertex { t, x, y: 0.0, h };
        // a close vertex whose heading is 0.5 rad above the kept one's is merged; 0.5 rad below, it stays
        let above = [at(0.0, 0.0, 1.0), at(0.1, 0.05, 1.5), at(0.2, 5.0, 1.5)];
        assert_eq!(filtered(&above).len(), 2);
        let below = [at(0.0, 0.0, 1.0), at(0.1, 0.05, 0.5), at(0.2, 5.0, 0.5)];
        assert_eq!(filtered(&below).len(), 3);
    }

    #[test]
    fn a_slow_stop_is_cut_into_pieces_that_replay() {
        // braking at 2 m/s² from 1.5 m/s to a stop, then standing 0.4 s
        let mut s = Vec::new();
        let mut x = 0.0;
        let mut speed: f64 = 1.5;
        for k in 0..16 {
            s.push(v(0.1 * k as f64, x));
            x += speed * 0.1 - 0.01;
            speed = (speed - 0.2).max(0.0);
            x = x.max(s[s.len() - 1].x);
        }
        assert!(worst_error(&s) > TOLERANCE);
        let p = pieces(&s);
        assert!(p.len() > 1);
        assert_eq!(p[0].0, 0);
        assert_eq!(p[p.len() - 1].1, s.len() - 1);
        assert!(p.windows(2).all(|w| w[0].1 == w[1].0));
        assert!(p.iter().all(|&(a, b)| b > a && worst_error(&s[a..=b]) <= TOLERANCE));
    }
}
