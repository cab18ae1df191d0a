//! One input held over several engine steps (`ClosedLoop::step_held`: a CommonRoad time step
//! of 0.1 s is ten engine steps of 0.01 s). Driver input, hold and dead reckoning are given
//! at every engine step as they are. A state is where the entity is to be at the end of the
//! last engine step; the engine steps before it get the poses of a cubic Hermite curve from
//! where the entity was (its position and velocity vector at both ends, so a car at constant
//! speed on an arc stays on it), the heading turning the short way and the speed changing
//! linearly — a planner stepping at 10 Hz drives the entity through the 100 Hz engine steps
//! without jumps, and every condition and driver model sees it in between as it would be.

use engine::{ExternalState, Input, Sample};

use crate::angle::wrap_angle;

/// The input of engine step `j` (1..=`n`) of `n` for an entity that was at `from` (its
/// reference point; `None`: it did not exist) when the held input began; `span` = the `n`
/// steps' duration, s. Step `n` gets `input` itself.
pub(crate) fn substep(input: &Input, from: Option<&Sample>, j: usize, n: usize, span: f64) -> Input {
    let (Input::State(to), Some(from)) = (input, from) else { return *input };
    // the last step, and a wrong state (the engine's check names the wrong number, which
    // the poses in between would spread to the others)
    if j >= n || input.check().is_err() {
        return *input;
    }
    let t = j as f64 / n as f64;
    let (t2, t3) = (t * t, t * t * t);
    // Hermite basis: start point, start tangent, end point, end tangent
    let (h00, h10, h01, h11) = (2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t, 3.0 * t2 - 2.0 * t3, t3 - t2);
    let (v0x, v0y) = (from.speed * from.h.cos() * span, from.speed * from.h.sin() * span);
    let (v1x, v1y) = (to.speed * to.h.cos() * span, to.speed * to.h.sin() * span);
    let x = h00 * from.x + h10 * v0x + h01 * to.x + h11 * v1x;
    let y = h00 * from.y + h10 * v0y + h01 * to.y + h11 * v1y;
    Input::State(ExternalState {
        x,
        y,
        h: from.h + t * wrap_angle(to.h - from.h),
        speed: from.speed + t * (to.speed - from.speed),
        z: to.z.map(|z| from.z + t * (z - from.z)),
        pitch: to.pitch,
        roll: to.roll,
        // derived from the heading change in between; the one given at the end
        yaw_rate: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(x: f64, y: f64, h: f64, speed: f64) -> Sample {
        Sample { x, y, z: 0.0, h, speed, acceleration: 0.0, yaw_rate: 0.0, road: None, visible: true }
    }

    fn state(i: Input) -> ExternalState {
        match i {
            Input::State(s) => s,
            other => panic!("not a state: {other:?}"),
        }
    }

    #[test]
    fn the_last_step_gets_the_input_and_other_inputs_are_held() {
        let to = Input::State(ExternalState { yaw_rate: Some(0.2), ..ExternalState::new(3.0, 0.0, 0.0, 30.0) });
        let from = sample(0.0, 0.0, 0.0, 30.0);
        assert_eq!(substep(&to, Some(&from), 10, 10, 0.1), to);
        assert_eq!(substep(&to, None, 3, 10, 0.1), to, "nowhere to start from: the state itself");
        let wrong = Input::State(ExternalState::new(3.0, 0.0, f64::NAN, 30.0));
        // (NaN is not equal to itself: compare the printed values)
        assert_eq!(format!("{:?}", substep(&wrong, Some(&from), 3, 10, 0.1)), format!("{wrong:?}"), "as given, for the engine to refuse");
        for held in [Input::Hold, Input::DeadReckon, Input::Driver(engine::DriverInput { throttle: 0.5, brake: 0.0, steering: 0.1 })] {
            assert_eq!(substep(&held, Some(&from), 4, 10, 0.1), held);
        }
    }

    #[test]
    fn constant_speed_on_a_straight_line_is_reproduced_exactly_enough() {
        // 30 m/s east for 0.1 s: 3 m; step j of 10 is at 0.3·j m
        let from = sample(100.0, 5.0, 0.0, 30.0);
        let to = Input::State(ExternalState::new(103.0, 5.0, 0.0, 30.0));
        for j in 1..10 {
            let s = state(substep(&to, Some(&from), j, 10, 0.1));
            assert!((s.x - (100.0 + 0.3 * j as f64)).abs() < 1e-12, "step {j}: {}", s.x);
            assert!((s.y - 5.0).abs() < 1e-12 && s.h == 0.0 && (s.speed - 30.0).abs() < 1e-12);
            assert_eq!(s.yaw_rate, None);
        }
    }

    #[test]
    fn an_arc_at_constant_speed_stays_near_the_arc_and_turns_the_short_way() {
        // a circle of radius 50 m at 20 m/s: 2 m in 0.1 s, heading from 179° to about −178.7°
        let (r, v, span) = (50.0, 20.0, 0.1);
        let h0 = 179f64.to_radians();
        let turn = v * span / r;
        let centre = (-r * h0.sin(), r * h0.cos()); // the circle's centre, left of the heading
        let on_circle = |a: f64| (centre.0 + r * (a - std::f64::consts::FRAC_PI_2).cos(), centre.1 + r * (a - std::f64::consts::FRAC_PI_2).sin());
        let (x0, y0) = on_circle(h0);
        let (x1, y1) = on_circle(h0 + turn);
        let from = sample(x0, y0, h0, v);
        let to = Input::State(ExternalState::new(x1, y1, wrap_angle(h0 + turn), v));
        for j in 1..10 {
            let s = state(substep(&to, Some(&from), j, 10, span));
            let off = ((s.x - centre.0).hypot(s.y - centre.1) - r).abs();
            assert!(off < 1e-5, "step {j}: {off} m off the arc");
            let expected = h0 + turn * j as f64 / 10.0;
            assert!((s.h - expected).abs() < 1e-12, "step {j}: heading {} vs {expected}", s.h);
        }
    }

    #[test]
    fn speed_and_given_height_change_linearly() {
        let from = Sample { z: 1.0, ..sample(0.0, 0.0, 0.0, 10.0) };
        let to = Input::State(ExternalState { z: Some(2.0), pitch: Some(0.05), ..ExternalState::new(1.5, 0.0, 0.0, 20.0) });
        let s = state(substep(&to, Some(&from), 5, 10, 0.1));
        assert!((s.speed - 15.0).abs() < 1e-12 && (s.z.unwrap_or(f64::NAN) - 1.5).abs() < 1e-12);
        assert_eq!(s.pitch, Some(0.05));
        let flat = Input::State(ExternalState::new(1.5, 0.0, 0.0, 20.0));
        assert_eq!(state(substep(&flat, Some(&from), 5, 10, 0.1)).z, None, "no height given: the road's");
    }
}
