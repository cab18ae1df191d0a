//! What Python gives an external entity for one step → `engine::Input`. The Python layer
//! (`osc2cr/_simulation.py`) reduces every accepted form (a commonroad-io state, a dict, a
//! tuple, `DriverInput`, `"hold"`) to `(kind, numbers)`; the fast path gives rows of a flat
//! float array. Positions come in as CommonRoad positions — the centre of the entity's
//! bounding box — and go to the engine as the OpenSCENARIO reference point.

use engine::{DriverInput, ExternalState, Input};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// Numbers of a state row: x, y, heading, speed, then optionally z, pitch, roll, yaw rate.
pub(crate) const STATE_WIDTHS: [usize; 2] = [4, 8];
/// Numbers of a driver-input row: throttle, brake, steering.
pub(crate) const DRIVER_WIDTH: usize = 3;

/// A CommonRoad state (box centre at `x`, `y`) of an entity whose box centre lies at
/// `offset` from its reference point. A heading that is not a number leaves the position as
/// given, so that the engine's check names the heading.
fn state(x: f64, y: f64, h: f64, speed: f64, optional: [Option<f64>; 4], offset: (f64, f64)) -> Input {
    let (x, y) = if h.is_finite() { convert::reference_point(x, y, h, offset.0, offset.1) } else { (x, y) };
    let [z, pitch, roll, yaw_rate] = optional;
    Input::State(ExternalState { x, y, h, speed, z, pitch, roll, yaw_rate })
}

/// `(kind, numbers)` from the Python layer → the input of the entity `name`.
pub(crate) fn from_parts(name: &str, kind: &str, v: &[Option<f64>], offset: (f64, f64)) -> PyResult<Input> {
    let wrong = |what: &str| PyValueError::new_err(format!("input for `{name}`: {what}"));
    match kind {
        "state" => match v {
            [Some(x), Some(y), Some(h), Some(speed), rest @ ..] if rest.len() <= 4 => {
                let mut optional = [None; 4];
                optional[..rest.len()].copy_from_slice(rest);
                Ok(state(*x, *y, *h, *speed, optional, offset))
            }
            _ => Err(wrong("a state is x, y, heading, speed and optionally z, pitch, roll, yaw_rate")),
        },
        "driver" => match v {
            [Some(throttle), Some(brake), Some(steering)] => Ok(Input::Driver(DriverInput { throttle: *throttle, brake: *brake, steering: *steering })),
            _ => Err(wrong("driver input is throttle, brake and steering")),
        },
        "hold" => Ok(Input::Hold),
        "dead_reckon" => Ok(Input::DeadReckon),
        other => Err(wrong(&format!("unknown kind of input {other:?} (state, driver, hold, dead_reckon)"))),
    }
}

/// One row of the fast path's array: a state (x, y, heading, speed, and in a row of 8 z,
/// pitch, roll, yaw rate, NaN where not given) or driver input (throttle, brake, steering).
/// A row whose first number is NaN holds the entity; a NaN elsewhere among the numbers a
/// state or driver input needs reaches the engine's check, which names it.
pub(crate) fn from_row(row: &[f64], driver: bool, offset: (f64, f64)) -> Input {
    let at = |i: usize| row.get(i).copied().unwrap_or(f64::NAN);
    if at(0).is_nan() {
        return Input::Hold;
    }
    if driver {
        return Input::Driver(DriverInput { throttle: at(0), brake: at(1), steering: at(2) });
    }
    let given = |i: usize| row.get(i).copied().filter(|v| !v.is_nan());
    state(at(0), at(1), at(2), at(3), [given(4), given(5), given(6), given(7)], offset)
}
