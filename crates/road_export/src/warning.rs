//! Warnings and errors of an export: each names the CommonRoad element it is about.

use std::fmt;

/// The CommonRoad element a warning is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Subject {
    Lanelet(u64),
    TrafficSign(u64),
    TrafficLight(u64),
    Intersection(u64),
    /// The network as a whole.
    Network,
}

impl fmt::Display for Subject {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Subject::Lanelet(id) => write!(f, "lanelet {id}"),
            Subject::TrafficSign(id) => write!(f, "traffic sign {id}"),
            Subject::TrafficLight(id) => write!(f, "traffic light {id}"),
            Subject::Intersection(id) => write!(f, "intersection {id}"),
            Subject::Network => write!(f, "lanelet network"),
        }
    }
}

/// Something OpenDRIVE cannot say, or that was approximated or left out.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    pub subject: Subject,
    pub message: String,
}

impl Warning {
    pub fn new(subject: Subject, message: impl Into<String>) -> Warning {
        Warning { subject, message: message.into() }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.subject, self.message)
    }
}

/// Why a network cannot be exported at all.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// No lanelet could be made into a road (OpenDRIVE needs at least one).
    #[error("no lanelet of the network can be exported (OpenDRIVE needs at least one road){}", detail(.0))]
    NoRoads(Vec<Warning>),
    /// A hard cap against hostile input.
    #[error("the lanelet network is too large: {what} is {got}, at most {max} are accepted")]
    TooLarge { what: &'static str, got: usize, max: usize },
}

fn detail(w: &[Warning]) -> String {
    match w.first() {
        Some(first) => format!(": {first}{}", if w.len() > 1 { format!(" (and {} more)", w.len() - 1) } else { String::new() }),
        None => String::new(),
    }
}
