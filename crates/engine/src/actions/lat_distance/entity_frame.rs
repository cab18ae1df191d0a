//! LateralDistanceAction in the entity coordinate system, as esmini 3.6.0 runs it
//! (LatDistanceAction::Step, its `CS_ENTITY` branch): the actor aims at the line parallel to
//! the reference's x axis at the wanted distance (+ left of the reference), at the foot of the
//! perpendicular from where it is. Without a maximum acceleration it jumps onto that line and
//! goes on along it by what is left of speed·dt, facing the reference's heading; with one it
//! drives speed·dt along its own heading, turning at most 1.5·v·dt/r per step, r = 1.5·v²/a
//! (a clamped to 1000, r at least 0.5 m): straight at the line while farther than r, within r
//! blending the heading towards the line and the reference's heading (a cubic-smoothed weight
//! from the arc left). The road plays no part; the action never ends by itself (esmini calls no
//! `End` there), and it moves the entity itself (the default controller leaves it alone).

use crate::angles::angle_difference;
use crate::angles::wrap_2pi;
use crate::dynamics::{abs_limit, ESMINI_SMALL_NUMBER as SMALL_NUMBER};
use std::f64::consts::PI;

/// esmini clamps the acceleration the turn radius is derived from, m/s².
const MAX_TURN_ACC: f64 = 1000.0;
/// Smallest turn radius, m.
const MIN_TURN_RADIUS: f64 = 0.5;

/// A pose in the plane: x, y, heading.
#[derive(Debug, Clone, Copy)]
pub(super) struct Pose {
    pub x: f64,
    pub y: f64,
    pub h: f64,
}

/// Where the actor goes this step: the pose esmini gives it by `SetInertiaPos`.
///
/// `distance` is signed (+ left of the reference), `speed` the actor's, `max_acc` ≥ esmini's
/// LARGE_NUMBER for an instant move.
pub(super) fn entity_frame_step(actor: Pose, reference: Pose, distance: f64, speed: f64, max_acc: f64, large: f64, dt: f64) -> Pose {
    let axis = (reference.h.cos(), reference.h.sin());
    // A point on the target line and the foot of the perpendicular from the actor.
    let p0 = (reference.x - distance * axis.1, reference.y + distance * axis.0);
    let foot = project_on_line(actor.x, actor.y, p0, axis);
    let delta = (foot.0 - actor.x, foot.1 - actor.y);
    let dist = delta.0.hypot(delta.1);
    if max_acc >= large {
        let step = speed.abs() * dt;
        // Given the speed, what the sideways jump leaves of the step goes along the line.
        let along = if dist < step { step - dist } else { 0.0 };
        return Pose { x: foot.0 + axis.0 * along, y: foot.1 + axis.1 * along, h: reference.h };
    }
    let step_len = speed * dt;
    if dist < SMALL_NUMBER {
        // On the line already: go on along it.
        return Pose { x: actor.x + axis.0 * step_len, y: actor.y + axis.1 * step_len, h: reference.h };
    }
    // The acceleration peaks mid-curve, about 1.5 times a circular arc's.
    let turn_radius = (1.5 * speed * speed / max_acc.abs().min(MAX_TURN_ACC)).max(MIN_TURN_RADIUS);
    let dh_max = ((speed / turn_radius * dt).abs() * 1.5).min(PI - SMALL_NUMBER);
    if dist < step_len / 2.0 - SMALL_NUMBER && step_len / 2.0 > turn_radius - SMALL_NUMBER {
        // The line is well within this step: land on it where the step's circle cuts it,
        // at the cut whose direction is nearer the reference's heading.
        if let Some((i0, i1)) = line_circle(p0, axis, (actor.x, actor.y), step_len) {
            let h0 = angle_of_vector(i0.0 - actor.x, i0.1 - actor.y);
            let h1 = angle_of_vector(i1.0 - actor.x, i1.1 - actor.y);
            let (p, h) = if angle_difference(h0, reference.h).abs() < angle_difference(h1, reference.h).abs() { (i0, h0) } else { (i1, h1) };
            return Pose { x: p.0, y: p.1, h };
        }
    }
    let dh = if dist > turn_radius - SMALL_NUMBER {
        // Far from the line: head straight at the foot point, turning no faster than allowed.
        abs_limit(angle_difference(delta.1.atan2(delta.0), actor.h), dh_max)
    } else {
        // Within the turn radius: blend the heading towards the line and the reference's, by
        // the mean tangent angle of the arc left (linear weight, then cubic smoothing).
        let h_diff_delta = angle_difference(angle_of_vector(delta.0, delta.1), actor.h);
        // esmini's GetAngleDifference: exactly opposite is +π, which turns left.
        let h_diff_heading = angle_difference(angle_of_vector(axis.0, axis.1), actor.h);
        let d_angle = step_len / turn_radius;
        let angle = (1.0 - dist / turn_radius).acos().max(d_angle / 2.0);
        let w = (2.0 * angle - d_angle / 2.0) / PI;
        let w = 3.0 * w * w - 2.0 * w * w * w;
        abs_limit(w * h_diff_delta + (1.0 - w) * h_diff_heading, dh_max)
    };
    let h = wrap_2pi(actor.h + dh);
    Pose { x: actor.x + h.cos() * step_len, y: actor.y + h.sin() * step_len, h }
}

/// The foot of the perpendicular from (x, y) on the line through `p0` along the unit `dir`
/// (esmini's ProjectPointOnLine2D).
fn project_on_line(x: f64, y: f64, p0: (f64, f64), dir: (f64, f64)) -> (f64, f64) {
    let k = (dir.1 * (x - p0.0) - dir.0 * (y - p0.1)) / (dir.0 * dir.0 + dir.1 * dir.1);
    (x - k * dir.1, y + k * dir.0)
}

/// The two points where the line through `p0` along `dir` cuts the circle round `c` of radius
/// `r` (esmini's GetIntersectionsOfLineAndCircle, first the one farther along `dir`); a
/// tangent gives the same point twice, a miss `None`.
fn line_circle(p0: (f64, f64), dir: (f64, f64), c: (f64, f64), r: f64) -> Option<((f64, f64), (f64, f64))> {
    let a = dir.0 * dir.0 + dir.1 * dir.1;
    let b = 2.0 * (dir.0 * (p0.0 - c.0) + dir.1 * (p0.1 - c.1));
    let cc = (p0.0 - c.0).powi(2) + (p0.1 - c.1).powi(2) - r * r;
    let disc = b * b - 4.0 * a * cc;
    if disc < -SMALL_NUMBER {
        return None;
    }
    let root = if disc.abs() < SMALL_NUMBER { 0.0 } else { disc.sqrt() };
    let at = |t: f64| (p0.0 + t * dir.0, p0.1 + t * dir.1);
    Some((at((-b + root) / (2.0 * a)), at((-b - root) / (2.0 * a))))
}

/// esmini's GetAngleOfVector: the direction in [0, 2π), an x below SMALL_NUMBER nudged to it.
pub(crate) fn angle_of_vector(x: f64, y: f64) -> f64 {
    if x.abs() < SMALL_NUMBER && y.abs() < SMALL_NUMBER {
        return 0.0;
    }
    let x = if x.abs() < SMALL_NUMBER {
        if x < 0.0 {
            -SMALL_NUMBER
        } else {
            SMALL_NUMBER
        }
    } else {
        x
    };
    wrap_2pi(y.atan2(x))
}
