//! What an ALKS R157 safety-model controller remembers: its model and mode, the target in focus,
//! the reference driver's phase and timers, the cut-in trigger.

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Model {
    Regulation,
    ReferenceDriver,
    /// Responsibility-Sensitive Safety: critical inside the RSS safe longitudinal distance.
    Rss,
    /// Fuzzy Safety Model: critical while its proactive or critical fuzzy surrogate is non-zero.
    Fsm,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Mode {
    Critical,
    TargetInSight,
    NoTarget,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Scen {
    None,
    CutIn,
    CutOut,
    Deceleration,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Phase {
    Inactive,
    Perceive,
    React,
    BrakeRef,
}

#[derive(Debug, Clone, Copy)]
pub(super) struct Info {
    pub(super) obj: Option<usize>,
    pub(super) dist_long: f64,
    pub(super) dist_lat: f64,
    pub(super) dv_s: f64,
    pub(super) dv_t: f64,
    pub(super) ttc: f64,
    pub(super) thw: f64,
    pub(super) dlane: i32,
    pub(super) action: Scen,
}

#[derive(Debug, Clone)]
pub(super) struct Trigger {
    /// Wandering trigger (threshold adapted to the target's lane offset) or fixed lateral distance.
    pub(super) wandering: bool,
    pub(super) base: f64,
    pub(super) threshold: f64,
    pub(super) active: bool,
    pub(super) obj: Option<usize>,
    pub(super) t0: f64,
}

#[derive(Debug, Clone)]
pub(crate) struct AlksR157Rt {
    pub active: bool,
    /// Active on the longitudinal domain (else the default controller moves the entity as well).
    pub(in crate::controllers) longitudinal: bool,
    /// Active on the lateral domain.
    pub(in crate::controllers) lateral: bool,
    pub(in crate::controllers) override_mode: bool,
    pub model: Model,
    pub(super) rt: f64,
    pub(super) max_dec: f64,
    pub(super) max_range: f64,
    pub(super) set_speed: f64,
    pub(super) acc: f64,
    pub(super) cruise: bool,
    pub(super) full_stop: bool,
    pub(super) always_trig: bool,
    pub(super) mode: Mode,
    pub(super) scen: Scen,
    pub(super) focus: Info,
    // ReferenceDriver
    pub(super) phase: Phase,
    pub(super) timer: f64,
    pub(super) time_mode: bool,
    pub(super) perception_t: f64,
    pub(super) perception_dist: f64,
    pub(super) perception_time: f64,
    pub(super) ped_eval_time: f64,
    pub(super) aeb_ttc: f64,
    pub(super) aeb_active: bool,
    /// The AEB's deceleration (`aebDeceleration`, 0.85 g) and whether it exists (`aebAvailable`).
    pub(super) aeb_dec: f64,
    pub(super) aeb_available: bool,
    pub(super) overlap_tol: f64,
    pub(super) trigger: Trigger,
    /// Ego speed at the start of the current step.
    pub(super) speed_now: f64,
    /// The current step's length (Model::dt_): 0 in frame 0, where esmini steps it too.
    pub(super) dt: f64,
    /// Where the model's own last move left the entity: at a road's end, no road beyond
    /// (Position::MoveAlongS's POS_STATUS_END_OF_ROAD), seen by the next step.
    pub(super) at_end: bool,
    // RSS and FSM
    /// Reaction timer counting down from `rt` once a situation turns critical (Model::rt_counter_).
    pub(super) rt_counter: f64,
    /// FSM's critical and proactive fuzzy surrogates of the last check.
    pub(super) cfs: f64,
    pub(super) pfs: f64,
}
