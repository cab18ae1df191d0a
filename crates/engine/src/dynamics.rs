//! Transition dynamics: a value moving from a start to a target along a shape (step, linear,
//! cubic, sinusoidal) over a parameter (time or distance) whose span is given directly or
//! follows from a peak rate. Shapes as the standard defines them:
//! linear `a + b·x/c`, cubic `a + b·(x/c)²·(3 − 2x/c)`, sinusoidal `a + b·(1 − cos(πx/c))/2`.

use openscenario::{DynamicsDimension, DynamicsShape};
use std::f64::consts::PI;

pub(crate) const SMALL: f64 = 1e-10;

/// esmini's SMALL_NUMBER (CommonMini.hpp): the tolerance of its actions' end tests.
pub(crate) const ESMINI_SMALL_NUMBER: f64 = 1e-6;

pub(crate) fn sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// esmini's ABS_LIMIT: limit the magnitude, keep the sign.
pub(crate) fn abs_limit(v: f64, limit: f64) -> f64 {
    if v.abs() > limit.abs() {
        sign(v) * limit.abs()
    } else {
        v
    }
}

/// esmini's CLAMP macro, `MIN(hi, MAX(lo, x))`, which unlike `f64::clamp` takes `hi` when it is
/// below `lo`: a model whose set speed is negative (activated while reversing) cruises at that
/// set speed (Model::Cruise).
pub(crate) fn esmini_clamp(x: f64, lo: f64, hi: f64) -> f64 {
    let m = if x > lo { x } else { lo };
    if m < hi {
        m
    } else {
        hi
    }
}

pub(crate) fn avoid_zero(x: f64) -> f64 {
    if x.abs() < SMALL {
        sign(x) * SMALL
    } else {
        x
    }
}

/// esmini's AVOID_ZERO itself (CommonMini.hpp): a magnitude below SMALL_NUMBER becomes
/// SMALL_NUMBER, 0 counting as positive ([`avoid_zero`] keeps the engine's 1e-10 instead).
pub(crate) fn esmini_avoid_zero(x: f64) -> f64 {
    sign(x) * x.abs().max(ESMINI_SMALL_NUMBER)
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct Transition {
    pub shape: DynamicsShape,
    pub dimension: DynamicsDimension,
    pub start: f64,
    pub target: f64,
    /// Current parameter value (time or distance since the start).
    pub param: f64,
    /// Parameter value at which the target is reached.
    pub param_target: f64,
    /// Peak rate for `rate` dimension (signed towards the target).
    pub rate: f64,
    /// Stretch of the parameter when the peak rate exceeds a limit.
    pub scale: f64,
}

impl Transition {
    pub(crate) fn new(shape: DynamicsShape, dimension: DynamicsDimension, value: f64) -> Self {
        let mut t = Transition { shape, dimension, start: 0.0, target: 0.0, param: 0.0, param_target: 1.0, rate: 0.0, scale: 1.0 };
        t.set_param_target(value);
        t
    }

    pub(crate) fn set_param_target(&mut self, value: f64) {
        if self.dimension == DynamicsDimension::Rate {
            self.rate = value;
            self.update_rate();
        } else {
            self.param_target = avoid_zero(value);
        }
    }

    pub(crate) fn set_start(&mut self, v: f64) {
        self.start = v;
        self.update_rate();
    }

    pub(crate) fn set_target(&mut self, v: f64) {
        self.target = v;
        self.update_rate();
    }

    fn update_rate(&mut self) {
        self.rate = sign(self.target - self.start) * self.rate.abs();
        if self.dimension == DynamicsDimension::Rate {
            self.param_target = avoid_zero(self.param_by_peak(self.rate));
        }
    }

    /// Parameter span for a given peak rate.
    pub(crate) fn param_by_peak(&self, peak: f64) -> f64 {
        let d = self.target - self.start;
        match self.shape {
            DynamicsShape::Step => 0.0,
            DynamicsShape::Linear => d / peak,
            DynamicsShape::Sinusoidal => PI * d / (2.0 * peak),
            DynamicsShape::Cubic => 1.5 * d / peak,
        }
    }

    /// Parameter span for a given peak second derivative (LaneOffsetAction's maxLateralAcc).
    pub(crate) fn param_by_peak_acc(&self, acc: f64) -> f64 {
        let d = (self.target - self.start).abs();
        match self.shape {
            DynamicsShape::Step => 0.0,
            DynamicsShape::Linear | DynamicsShape::Cubic => (6.0 * d / acc).sqrt(),
            DynamicsShape::Sinusoidal => PI * (d / (2.0 * acc)).sqrt(),
        }
    }

    /// Peak first derivative over the whole transition.
    pub(crate) fn peak_rate(&self) -> f64 {
        if self.dimension == DynamicsDimension::Rate {
            return self.rate;
        }
        let d = self.target - self.start;
        let c = avoid_zero(self.param_target);
        match self.shape {
            DynamicsShape::Step => 1e10 * sign(d),
            DynamicsShape::Linear => d / c,
            DynamicsShape::Sinusoidal => PI * d / (2.0 * c),
            DynamicsShape::Cubic => 1.5 * d / c,
        }
    }

    /// Limit the peak rate to `max_rate` by stretching the parameter.
    pub(crate) fn set_max_rate(&mut self, max_rate: f64) {
        let peak = self.peak_rate().abs();
        self.scale = if peak > max_rate.abs() { peak / avoid_zero(max_rate.abs()) } else { 1.0 };
    }

    /// Advance the parameter, kept within [0, span] so the last step lands on the target
    /// (esmini's TransitionDynamics::Step).
    pub(crate) fn step(&mut self, d: f64) {
        self.param += d / self.scale;
        if self.param > self.param_target {
            self.param = self.param_target;
        } else if self.param < 0.0 {
            self.param = 0.0;
        }
    }

    pub(crate) fn value(&self) -> f64 {
        let (a, b) = (self.start, self.target - self.start);
        let c = avoid_zero(self.param_target);
        let x = self.param;
        match self.shape {
            DynamicsShape::Step => self.target,
            DynamicsShape::Linear => a + x * b / c,
            DynamicsShape::Sinusoidal => a - b * ((PI * x / c).cos() - 1.0) / 2.0,
            DynamicsShape::Cubic => a + b * (x / c).powi(2) * (3.0 - 2.0 * x / c),
        }
    }

    /// First derivative with respect to the (unscaled) parameter.
    pub(crate) fn derivative(&self) -> f64 {
        let b = self.target - self.start;
        let c = avoid_zero(self.param_target);
        let x = self.param;
        match self.shape {
            DynamicsShape::Step => 1e10 * sign(b),
            DynamicsShape::Linear => b / c,
            DynamicsShape::Sinusoidal => PI * b * (PI * x / c).sin() / (2.0 * c),
            DynamicsShape::Cubic => 6.0 * b * (c - x) * x / c.powi(3),
        }
    }

    /// Derivative with the stretch applied.
    pub(crate) fn scaled_derivative(&self) -> f64 {
        self.derivative() / avoid_zero(self.scale)
    }

    /// Whether the target is reached at `value` (end of span, close enough, or passed), with
    /// the tolerance of esmini's lane change / lane offset end test (SMALL_NUMBER).
    pub(crate) fn done(&self, value: f64) -> bool {
        self.param > self.param_target - ESMINI_SMALL_NUMBER
            || (value - self.target).abs() < ESMINI_SMALL_NUMBER
            || (self.param > 0.0 && sign(value - self.target) != sign(self.start - self.target))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_reach_the_midpoint_halfway() {
        for shape in [DynamicsShape::Linear, DynamicsShape::Cubic, DynamicsShape::Sinusoidal] {
            let mut t = Transition::new(shape, DynamicsDimension::Time, 4.0);
            t.set_start(10.0);
            t.set_target(20.0);
            t.step(2.0);
            assert!((t.value() - 15.0).abs() < 1e-12, "{shape:?}");
            t.step(2.0);
            assert!((t.value() - 20.0).abs() < 1e-12, "{shape:?}");
        }
    }

    #[test]
    fn rate_dimension_gives_span() {
        let mut t = Transition::new(DynamicsShape::Linear, DynamicsDimension::Rate, 2.0);
        t.set_start(10.0);
        t.set_target(0.0);
        assert!((t.param_target - 5.0).abs() < 1e-12);
        t.step(1.0);
        assert!((t.value() - 8.0).abs() < 1e-12);
    }
}
