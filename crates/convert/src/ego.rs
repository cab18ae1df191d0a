//! Which entity is the ego: the one named by the user, else (in closed loop) the moving entity
//! driven from outside, else the first (by name) whose name contains the pattern
//! (case-insensitive; default "ego"), else the first moving entity of the trace. The ego must be a dynamic track: its first and last states make the planning problem.

use crate::tracks::{Placement, Track};

/// Why a scenario without entities cannot be converted (`preflight` says it before a run).
pub const NO_EGO: &str = "the scenario has no entity that could be the ego of the planning problem";

/// How the ego is chosen.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EgoChoice {
    /// The first entity (sorted by name) whose name contains this text, ignoring ASCII case;
    /// else the first dynamic entity.
    Pattern(String),
    /// Exactly this entity (`--ego NAME`); an error when it does not exist or is not dynamic.
    Name(String),
    /// This entity when it moves (the one a closed-loop run drove from outside), else as
    /// `Pattern` with this text.
    Preferred { name: String, pattern: String },
}

impl Default for EgoChoice {
    fn default() -> Self {
        EgoChoice::Pattern("ego".to_string())
    }
}

/// The index of the ego's track in `tracks`.
pub fn choose_ego(tracks: &[Track], choice: &EgoChoice) -> Result<usize, String> {
    let dynamic = |t: &Track| matches!(t.placement, Placement::Moving(_));
    match choice {
        EgoChoice::Name(name) => match tracks.iter().position(|t| &t.entity == name) {
            Some(i) if dynamic(&tracks[i]) => Ok(i),
            Some(_) => Err(format!("the ego {name:?} is a fixed object, not a moving entity: choose another with --ego")),
            None => Err(format!("no entity named {name:?} (--ego); the scenario has: {}", names(tracks))),
        },
        EgoChoice::Preferred { name, pattern } => match tracks.iter().position(|t| &t.entity == name) {
            Some(i) if dynamic(&tracks[i]) => Ok(i),
            _ => choose_ego(tracks, &EgoChoice::Pattern(pattern.clone())),
        },
        EgoChoice::Pattern(pattern) => {
            let pattern = pattern.to_ascii_lowercase();
            let by_pattern = tracks
                .iter()
                .enumerate()
                .filter(|(_, t)| dynamic(t) && t.entity.to_ascii_lowercase().contains(&pattern))
                .min_by(|(_, a), (_, b)| a.entity.cmp(&b.entity))
                .map(|(i, _)| i);
            // A scenario of fixed objects only still has a map and obstacles worth converting:
            // the planning problem then starts at a fixed object (the caller warns).
            let fixed_by_pattern = || {
                tracks
                    .iter()
                    .enumerate()
                    .filter(|(_, t)| t.entity.to_ascii_lowercase().contains(&pattern))
                    .min_by(|(_, a), (_, b)| a.entity.cmp(&b.entity))
                    .map(|(i, _)| i)
            };
            by_pattern
                .or_else(|| tracks.iter().position(dynamic))
                .or_else(fixed_by_pattern)
                .or_else(|| (!tracks.is_empty()).then_some(0))
                .ok_or_else(|| NO_EGO.to_string())
        }
    }
}

fn names(tracks: &[Track]) -> String {
    let list: Vec<String> = tracks.iter().map(|t| format!("{:?}", t.entity)).collect();
    if list.is_empty() {
        "no entities".to_string()
    } else {
        list.join(", ")
    }
}
