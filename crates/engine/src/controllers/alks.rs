//! ALKSController, esmini's "Automated Lane Keeping System" driver model. In esmini 3.6.0
//! (ControllerALKS) it is the ACC controller under another type name: the class derives from
//! ControllerACC and overrides nothing but its type. So the entity keeps its lane (the default
//! lateral behaviour: lane and lateral offset are held), cruises at a set speed and follows the
//! nearest vehicle ahead in its lane at 3 m + `timeGap` × speed, with the same properties and
//! defaults (`timeGap` 1.5 s, `setSpeed`, `lateralDist` 5 m, `mode` additive unless given) and
//! the same interplay with storyboard speed actions — all of it in `acc`.

use super::acc::state::AccRt;
use openscenario::Controller;

/// The run-time state of an ALKSController: an ACC controller's.
pub(crate) fn new(c: &Controller) -> AccRt {
    AccRt::new(c)
}
