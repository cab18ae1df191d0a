//! The scenario: header, location, tags, the lanelet network and the obstacles.
//! Planning problems are kept apart ([`crate::PlanningProblemSet`]) because a map file has none.

use std::collections::BTreeSet;

use crate::header::{GeoLocation, Header};
use crate::ids::IdAllocator;
use crate::intersection::Intersection;
use crate::lanelet::Lanelet;
use crate::obstacle::{DynamicObstacle, EnvironmentObstacle, StaticObstacle};
use crate::planning::PlanningProblemSet;
use crate::tags::Tag;
use crate::traffic::{TrafficLight, TrafficSign};

/// Lanelets with their traffic signs, lights and intersections (what a map converter makes).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LaneletNetwork {
    pub lanelets: Vec<Lanelet>,
    pub traffic_signs: Vec<TrafficSign>,
    pub traffic_lights: Vec<TrafficLight>,
    pub intersections: Vec<Intersection>,
}

impl LaneletNetwork {
    /// The largest id used by any element of the network (0 if none).
    pub fn max_id(&self) -> u64 {
        let lanelets = self.lanelets.iter().map(|l| l.id.get());
        let signs = self.traffic_signs.iter().map(|s| s.id.get());
        let lights = self.traffic_lights.iter().map(|l| l.id.get());
        let inters = self.intersections.iter().flat_map(|i| std::iter::once(i.id.get()).chain(i.incomings.iter().map(|inc| inc.id.get())));
        lanelets.chain(signs).chain(lights).chain(inters).max().unwrap_or(0)
    }
}

/// A CommonRoad 2020a scenario without its planning problems. Elements are written in the
/// order of these vectors, so the output is as deterministic as the caller's order.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    pub header: Header,
    pub location: GeoLocation,
    pub tags: BTreeSet<Tag>,
    pub network: LaneletNetwork,
    pub static_obstacles: Vec<StaticObstacle>,
    pub dynamic_obstacles: Vec<DynamicObstacle>,
    pub environment_obstacles: Vec<EnvironmentObstacle>,
}

impl Scenario {
    /// An empty scenario with the default (unknown) location and no tags.
    pub fn new(header: Header) -> Self {
        Self {
            header,
            location: GeoLocation::default(),
            tags: BTreeSet::new(),
            network: LaneletNetwork::default(),
            static_obstacles: Vec::new(),
            dynamic_obstacles: Vec::new(),
            environment_obstacles: Vec::new(),
        }
    }

    /// The largest id used by any element of the scenario (0 if none).
    pub fn max_id(&self) -> u64 {
        let obstacles = self
            .static_obstacles
            .iter()
            .map(|o| o.id.get())
            .chain(self.dynamic_obstacles.iter().map(|o| o.id.get()))
            .chain(self.environment_obstacles.iter().map(|o| o.id.get()));
        obstacles.chain(std::iter::once(self.network.max_id())).max().unwrap_or(0)
    }

    /// An allocator whose ids come after every id already in the scenario and in `problems`
    /// (the same argument as [`Scenario::validate`]), e.g. to add obstacles and planning
    /// problems to a converted map. Use it for every further element of the file.
    pub fn id_allocator(&self, problems: Option<&PlanningProblemSet>) -> IdAllocator {
        let max = self.max_id().max(problems.map_or(0, PlanningProblemSet::max_id));
        IdAllocator::starting_at(max.saturating_add(1))
    }
}

impl PlanningProblemSet {
    /// The largest planning-problem id (0 if none).
    pub fn max_id(&self) -> u64 {
        self.problems.iter().map(|p| p.id.get()).max().unwrap_or(0)
    }
}
