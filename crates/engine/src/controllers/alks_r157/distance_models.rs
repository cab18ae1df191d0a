//! The two ALKS R157 safety models whose criticality is a safe-distance formula: RSS
//! (Responsibility-Sensitive Safety) and FSM (the Fuzzy Safety Model), as esmini 3.6.0's
//! ControllerALKS_R157SM::RSS and ::FSM. Both share the generic detection (Model::Detect /
//! Process) and cruise control with the other models; what differs is which object counts as a
//! threat (CheckSafety), when the situation is critical (CheckCritical), how hard the model brakes
//! after its reaction time (ReactCritical) and the gap the cruise control keeps (MinDist).

use super::state::{AlksR157Rt, Info, Mode, Scen};
use super::Frame;

// CommonMini's SMALL_NUMBER, which these models compare against.
use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
/// Both models' jerk when building up braking (min_jerk_), m/s³.
const MIN_JERK: f64 = 12.65;
/// Model::max_acc_ and max_acc_lat_ (m/s²): the accelerations RSS assumes of the others.
const MAX_ACC: f64 = 3.0;
const MAX_ACC_LAT: f64 = 1.0;
/// RSS's lateral fluctuation margin mu_ (m).
const RSS_MU: f64 = 0.3;
/// FSM's braking parameters (m/s²): the rear's comfortable (br_min_) and maximum (br_max_)
/// deceleration and the lead's assumed braking (bl_); its margins (m).
const FSM_BR_MIN: f64 = 4.0;
const FSM_BR_MAX: f64 = 6.0;
const FSM_BL: f64 = 7.0;
const FSM_MARGIN_DIST: f64 = 2.0;
const FSM_MARGIN_SAFE_DIST: f64 = 2.0;

/// esmini's SIGN macro: 1 for zero.
pub(super) fn esmini_sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// ControllerALKS_R157SM::RSS::CheckSafety: an object that overlaps laterally or shares the lane
/// is a deceleration threat; one in a neighbour lane closer than the RSS safe lateral distance
/// (given its lateral speed) cuts in. `fo` is the object's road frame.
pub(super) fn rss_check_safety(info: &mut Info, fo: &Frame, a: &AlksR157Rt) -> bool {
    if info.dist_lat < SMALL_NUMBER || info.dlane == 0 {
        info.action = Scen::Deceleration;
        return false;
    }
    let cut_in_lat = fo.v_t.abs();
    let rt = a.rt;
    let d_safe_lat = RSS_MU + ((2.0 * cut_in_lat + MAX_ACC_LAT * rt) * rt / 2.0).abs() + (cut_in_lat + MAX_ACC_LAT * rt).powi(2) / (2.0 * MAX_ACC_LAT);
    if info.dist_lat.abs() < d_safe_lat {
        info.action = Scen::CutIn;
        return false;
    }
    true
}

/// ControllerALKS_R157SM::FSM::CheckSafety: same lane is a deceleration threat; a neighbour
/// moving towards the ego lane cuts in unless it needs clearly longer (0.1 s) to close the lateral
/// gap than the ego needs to close the longitudinal one.
pub(super) fn fsm_check_safety(info: &mut Info, fo: &Frame, ego_speed: f64, obj_speed: f64) -> bool {
    if info.dlane == 0 {
        info.action = Scen::Deceleration;
        return false;
    }
    if info.dist_lat > -SMALL_NUMBER {
        let cutin_speed = -esmini_sign(info.dlane as f64) * fo.v_t;
        if cutin_speed <= 0.0 {
            return true;
        }
        let headway_lat = info.dist_lat.abs() / cutin_speed;
        let headway_long_gross = info.dist_long.abs() / (ego_speed - obj_speed).max(SMALL_NUMBER);
        if headway_lat > headway_long_gross + 0.1 {
            return true;
        }
    }
    info.action = Scen::CutIn;
    false
}

/// Entering the critical mode starts the reaction timer (Model::ResetReactionTime).
fn enter_critical(a: &mut AlksR157Rt) {
    if a.mode != Mode::Critical {
        a.rt_counter = a.rt;
    }
    a.mode = Mode::Critical;
}

/// ControllerALKS_R157SM::RSS::CheckCritical: critical while closing in on the object in focus
/// within the RSS safe longitudinal distance.
pub(super) fn rss_check_critical(a: &mut AlksR157Rt, v: f64, lead_speed: f64) -> bool {
    if a.focus.obj.is_none() {
        a.mode = Mode::NoTarget;
        return false;
    }
    if a.focus.dv_s > 0.0 && a.focus.dist_long > 0.0 {
        let rt = a.rt;
        let d_safe_long = v * rt + MAX_ACC * rt.powi(2) / 2.0 + (v + rt * MAX_ACC).powi(2) / (2.0 * a.max_dec) - lead_speed.powi(2) / (2.0 * a.max_dec);
        if a.focus.dist_long < d_safe_long {
            enter_critical(a);
            return true;
        }
    }
    a.mode = Mode::TargetInSight;
    false
}

/// The reaction time of RSS's and FSM's ReactCritical: while it runs down the gas is released
/// (no acceleration, a deceleration already under way kept) and the new speed is returned.
fn reacting(a: &mut AlksR157Rt, v: f64, dt: f64) -> Option<f64> {
    if a.rt_counter > 0.0 {
        a.acc = a.acc.min(0.0);
        a.rt_counter -= dt;
        return Some(v + a.acc * dt);
    }
    None
}

/// ControllerALKS_R157SM::RSS::ReactCritical: the gas released during the reaction time, then a
/// jerk-limited build-up of braking. esmini bounds it with `MIN(acc - jerk dt, max_dec)`, which
/// never binds, so the deceleration keeps growing until the situation is no longer critical.
pub(super) fn rss_react(a: &mut AlksR157Rt, v: f64, dt: f64) -> f64 {
    if let Some(speed) = reacting(a, v, dt) {
        return speed;
    }
    a.acc = (a.acc - MIN_JERK * dt).min(a.max_dec);
    (v + a.acc * dt).max(0.0)
}

/// ControllerALKS_R157SM::RSS::MinDist.
pub(super) fn rss_min_dist(a: &AlksR157Rt, v: f64) -> f64 {
    let (rt, dec) = (a.rt, a.max_dec);
    v * rt * rt + MAX_ACC * rt.powi(2) / 2.0 + (v + rt * MAX_ACC).powi(2) / (2.0 * dec) - (v - rt * MAX_ACC * dec).max(0.0).powi(2) / (2.0 * dec)
        + 0.5 * dec * rt.powi(2)
}

/// ControllerALKS_R157SM::FSM::MinDist.
pub(super) fn fsm_min_dist(a: &AlksR157Rt, v: f64, lead_speed: f64) -> f64 {
    FSM_MARGIN_DIST + v * a.rt + v.powi(2) / (2.0 * FSM_BR_MIN) - lead_speed.powi(2) / (2.0 * FSM_BL) + FSM_MARGIN_SAFE_DIST
}

/// FSM::PFS, the proactive fuzzy safety surrogate: 0 beyond the safe distance, 1 inside the
/// unsafe one (braking at br_max), linear between.
fn fsm_pfs(dist: f64, speed_rear: f64, speed_lead: f64, rt: f64) -> f64 {
    let dist = dist - FSM_MARGIN_DIST;
    let dsafe = speed_rear * rt + speed_rear.powi(2) / (2.0 * FSM_BR_MIN) - speed_lead.powi(2) / (2.0 * FSM_BL) + FSM_MARGIN_SAFE_DIST;
    if dist > dsafe {
        return 0.0;
    }
    let dunsafe = speed_rear * rt + speed_rear.powi(2) / (2.0 * FSM_BR_MAX) - speed_lead.powi(2) / (2.0 * FSM_BL);
    if dist < dunsafe {
        1.0
    } else {
        (dist - dsafe) / (dunsafe - dsafe)
    }
}

/// FSM::CFS, the critical fuzzy safety surrogate, from the rear's current acceleration `acc`.
fn fsm_cfs(dist: f64, speed_rear: f64, speed_lead: f64, rt: f64, acc: f64) -> f64 {
    let ar = acc.max(-FSM_BR_MIN);
    let u_new = speed_rear + rt * ar;
    if speed_rear <= speed_lead {
        return 0.0;
    }
    if u_new < speed_lead {
        let dsafe = (speed_rear - speed_lead).powi(2) / (acc * 2.0).abs();
        return if dist < dsafe { 1.0 } else { 0.0 };
    }
    let dsafe = (speed_rear + ar * rt / 2.0 - speed_lead) * rt + (speed_rear + ar * rt - speed_lead).powi(2) / (FSM_BR_MIN * 2.0);
    if dist > dsafe {
        return 0.0;
    }
    let dunsafe = (speed_rear + ar * rt / 2.0 - speed_lead) * rt + (speed_rear + ar * rt - speed_lead).powi(2) / (FSM_BR_MAX * 2.0);
    if dist < dunsafe {
        1.0
    } else {
        (dist - dsafe) / (dunsafe - dsafe)
    }
}

/// ControllerALKS_R157SM::FSM::CheckCritical: critical while closing in with either surrogate
/// non-zero. `acc_s` is the ego's acceleration along the road (Position::GetAccS).
pub(super) fn fsm_check_critical(a: &mut AlksR157Rt, v: f64, lead_speed: f64, acc_s: f64) -> bool {
    if a.focus.obj.is_none() {
        a.mode = Mode::NoTarget;
        return false;
    }
    if a.focus.dv_s > 0.0 && a.focus.dist_long > 0.0 {
        a.cfs = fsm_cfs(a.focus.dist_long, v, lead_speed, a.rt, acc_s);
        a.pfs = fsm_pfs(a.focus.dist_long, v, lead_speed, a.rt);
        if a.cfs + a.pfs < SMALL_NUMBER {
            a.mode = Mode::TargetInSight;
            return false;
        }
        enter_critical(a);
        return true;
    }
    a.mode = Mode::TargetInSight;
    false
}

/// ControllerALKS_R157SM::FSM::ReactCritical: after the reaction time, brake towards a
/// deceleration graded by the surrogates (br_min..br_max by CFS, else up to br_min by PFS),
/// built up with the jerk limit and capped at the model's maximum deceleration.
pub(super) fn fsm_react(a: &mut AlksR157Rt, v: f64, dt: f64) -> f64 {
    if let Some(speed) = reacting(a, v, dt) {
        return speed;
    }
    let target = if a.cfs > SMALL_NUMBER { a.cfs * (FSM_BR_MAX - FSM_BR_MIN) + FSM_BR_MIN } else { a.pfs * FSM_BR_MIN };
    a.acc = (a.acc - MIN_JERK * dt).max(-a.max_dec).max(-target);
    (v + a.acc * dt).max(0.0)
}
