//! What the storyboard's actions do to an entity driven from outside. esmini's private actions
//! look, in their Start and Step, whether a controller in override mode holds their domain
//! (OSCPrivateAction.cpp, `IsControllerModeOnDomains(MODE_OVERRIDE, …)`), and an entity driven
//! from outside is held on both: a SpeedAction ends at once (LongSpeedAction), a lane change,
//! lane offset, trajectory, distance or synchronize action runs without moving it and never
//! ends (their Step returns early), a TeleportAction does nothing; every other action runs
//! as usual (a SpeedProfileAction's speed is then replaced by the outside one).

use openscenario::PrivateAction;

/// An action's fate on an entity driven from outside.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Overridden {
    /// Runs as usual.
    Runs,
    /// Ends at once without effect (the action's own code handles it: `longitudinal_overridden`).
    Ends,
    /// Runs without effect and never ends.
    Idles,
    /// Completes without effect.
    Ignored,
}

/// The fate of private action `p`.
pub(crate) fn overridden(p: &PrivateAction) -> Overridden {
    match p {
        PrivateAction::Speed { .. } => Overridden::Ends,
        PrivateAction::LaneChange { .. }
        | PrivateAction::LaneOffset { .. }
        | PrivateAction::FollowTrajectory { .. }
        | PrivateAction::LongitudinalDistance { .. }
        | PrivateAction::LateralDistance { .. }
        | PrivateAction::Synchronize { .. } => Overridden::Idles,
        PrivateAction::Teleport(_) => Overridden::Ignored,
        _ => Overridden::Runs,
    }
}

/// The warning for action `element` on entity `entity`, or none when it runs as usual.
pub(crate) fn note(fate: Overridden, element: &str, entity: &str) -> Option<String> {
    let what = match fate {
        Overridden::Runs => return None,
        Overridden::Ends => "ends at once without effect",
        Overridden::Idles => "runs without effect and does not end",
        Overridden::Ignored => "has no effect",
    };
    Some(format!(
        "{element} on `{entity}`: the entity is driven from outside, so the action {what} (esmini's rule for an entity whose controller overrides it)"
    ))
}
