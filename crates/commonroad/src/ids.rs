//! Typed ids. Each kind of element has its own id type so a lanelet reference cannot be filled
//! with a traffic-light id by mistake; all of them share one number space because the 2020a XSD
//! requires ids to be unique over the whole file (`xs:key`), which [`IdAllocator`] guarantees.

use std::fmt;
use std::num::NonZeroU64;

macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(NonZeroU64);

        impl $name {
            /// An id with the given value; `None` for 0 (ids are `xs:positiveInteger`).
            /// Prefer [`IdAllocator`], which also guarantees uniqueness.
            pub fn new(raw: u64) -> Option<Self> {
                NonZeroU64::new(raw).map(Self)
            }

            /// The number written to the file.
            pub fn get(self) -> u64 {
                self.0.get()
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                self.0.fmt(f)
            }
        }
    };
}

id_type!(
    /// Id of a `lanelet`.
    LaneletId
);
id_type!(
    /// Id of a `trafficSign`.
    TrafficSignId
);
id_type!(
    /// Id of a `trafficLight`.
    TrafficLightId
);
id_type!(
    /// Id of an `intersection`.
    IntersectionId
);
id_type!(
    /// Id of an `intersection/incoming`.
    IncomingId
);
id_type!(
    /// Id of a static, dynamic or environment obstacle.
    ObstacleId
);
id_type!(
    /// Id of a `planningProblem`.
    PlanningProblemId
);

/// One `IdAllocator` method per id type: the next number of the shared space, as that type.
macro_rules! fresh_ids {
    ($($(#[$doc:meta])* $method:ident -> $id:ident,)*) => {
        $(
            $(#[$doc])*
            pub fn $method(&mut self) -> $id {
                $id(self.take())
            }
        )*
    };
}

/// Hands out ids that are unique across one file, whatever their kind.
///
/// Use one allocator per output file. [`crate::Scenario::id_allocator`] returns one that
/// continues after the largest id already in a scenario (e.g. after the map's lanelets).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IdAllocator {
    next: NonZeroU64,
}

impl Default for IdAllocator {
    fn default() -> Self {
        Self::new()
    }
}

impl IdAllocator {
    /// Starts at 1.
    pub fn new() -> Self {
        Self { next: NonZeroU64::MIN }
    }

    /// Starts at `first` (0 is treated as 1).
    pub fn starting_at(first: u64) -> Self {
        Self { next: NonZeroU64::new(first).unwrap_or(NonZeroU64::MIN) }
    }

    /// The value the next call will return.
    pub fn peek(&self) -> u64 {
        self.next.get()
    }

    fn take(&mut self) -> NonZeroU64 {
        let id = self.next;
        // u64 cannot realistically be exhausted; saturating keeps this panic-free and a
        // (theoretical) repeat would still be caught by `validate()`.
        self.next = self.next.saturating_add(1);
        id
    }

    fresh_ids! {
        /// A fresh lanelet id.
        lanelet -> LaneletId,
        /// A fresh traffic-sign id.
        traffic_sign -> TrafficSignId,
        /// A fresh traffic-light id.
        traffic_light -> TrafficLightId,
        /// A fresh intersection id.
        intersection -> IntersectionId,
        /// A fresh incoming id.
        incoming -> IncomingId,
        /// A fresh obstacle id.
        obstacle -> ObstacleId,
        /// A fresh planning-problem id.
        planning_problem -> PlanningProblemId,
    }
}
