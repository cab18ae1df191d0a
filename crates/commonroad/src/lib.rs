//! `commonroad` — a model of a CommonRoad 2020a scenario (header, location, tags, lanelet
//! network, traffic signs and lights, intersections, static/dynamic/environment obstacles,
//! planning problems), its XML writer, and the writer of the CommonRoad 2024 format
//! ([`protobuf`]: map, scenario and dynamic files, the map named by its content).
//!
//! It owns the output format and its traps (see `../shared/COMMONROAD.md`): the types make
//! invalid files hard to build (equal bound point counts, per-element obstacle types, one
//! state struct for every trajectory state, typed ids from one allocator), [`Scenario::validate`]
//! checks what types cannot (references, unique ids, referenced signs, consecutive
//! trajectories), and [`xml`] writes bytes that both 2020a XSDs and both commonroad-io readers
//! accept.
//!
//! It must not know OpenSCENARIO or OpenDRIVE: converters build this model.
//!
//! ```
//! use commonroad::*;
//!
//! let header = Header {
//!     benchmark_id: BenchmarkId::for_converted("ZAM", "cut-in 01")?, // ZAM_cutin01-1_1_T-1
//!     date: Date::new(2026, 1, 15)?,
//!     author: "osc2cr".into(),
//!     affiliation: "".into(),
//!     source: "OpenSCENARIO conversion".into(),
//!     time_step_size: 0.1,
//! };
//! let mut scenario = Scenario::new(header);
//! scenario.tags.insert(Tag::Simulated);
//! let mut ids = IdAllocator::new(); // or scenario.id_allocator(None) after adding a map
//!
//! let bounds = LaneletBounds::new(
//!     vec![Point::new(0.0, 3.5), Point::new(100.0, 3.5)], // left
//!     vec![Point::new(0.0, 0.0), Point::new(100.0, 0.0)], // right, same count
//! )?;
//! let lane = ids.lanelet();
//! scenario.network.lanelets.push(Lanelet::new(lane, bounds, LaneletType::Urban));
//!
//! let state = |t: u64| State {
//!     time_step: t, x: 10.0 + t as f64, y: 1.75, orientation: 0.0,
//!     velocity: 10.0, acceleration: 0.0, yaw_rate: 0.0,
//! };
//! scenario.dynamic_obstacles.push(DynamicObstacle {
//!     id: ids.obstacle(),
//!     obstacle_type: DynamicObstacleType::Car,
//!     shape: Shape::rectangle(4.5, 1.8)?,
//!     initial_state: state(0),
//!     trajectory: (1..=20).map(state).collect(), // t0+1, t0+2, …
//! });
//!
//! let problems = PlanningProblemSet {
//!     problems: vec![PlanningProblem {
//!         id: ids.planning_problem(),
//!         initial_state: PlanningInitialState {
//!             x: 5.0, y: 1.75, orientation: 0.0, velocity: 10.0,
//!             yaw_rate: 0.0, slip_angle: 0.0, acceleration: None,
//!         },
//!         goal_states: vec![GoalState {
//!             time: TimeInterval::new(10, 20)?,
//!             position: Some(GoalPosition::Lanelets(vec![lane])),
//!             orientation: None,
//!             velocity: Some(Interval::new(5.0, 15.0)?),
//!         }],
//!     }],
//! };
//!
//! assert!(scenario.validate(Some(&problems)).is_empty());
//! let bytes = xml::write_scenario(&scenario, &problems)?;
//! # let dir = std::env::temp_dir().join(format!("commonroad-doc-{}", std::process::id()));
//! # std::fs::create_dir_all(&dir)?;
//! xml::write_atomic(&dir.join("cut_in.xml"), &bytes)?; // whole file or none
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod error;
mod geometry;
mod header;
mod ids;
mod intersection;
mod lanelet;
mod obstacle;
mod planning;
pub mod protobuf;
mod scenario;
mod sign_ids;
mod str_enum;
mod tags;
mod traffic;
mod validate;
pub mod xml;

pub use error::Error;
pub use geometry::{AbsoluteShape, Circle, PlacedCircle, PlacedRectangle, Point, Polygon, Rectangle, Shape};
pub use header::{BenchmarkId, BenchmarkIdParts, Date, GeoLocation, GeoTransformation, Header};
pub use ids::{IdAllocator, IncomingId, IntersectionId, LaneletId, ObstacleId, PlanningProblemId, TrafficLightId, TrafficSignId};
pub use intersection::{Incoming, Intersection};
pub use lanelet::{Adjacent, DrivingDir, Lanelet, LaneletBounds, LaneletType, LineMarking, RoadUser, StopLine};
pub use obstacle::{DynamicObstacle, DynamicObstacleType, EnvironmentObstacle, EnvironmentObstacleType, State, StaticObstacle, StaticObstacleType};
pub use planning::{GoalPosition, GoalState, Interval, PlanningInitialState, PlanningProblem, PlanningProblemSet, TimeInterval};
pub use scenario::{LaneletNetwork, Scenario};
pub use sign_ids::{is_xsd_traffic_sign_id, XSD_TRAFFIC_SIGN_IDS};
pub use tags::Tag;
pub use traffic::{CycleElement, TrafficLight, TrafficLightColor, TrafficLightDirection, TrafficSign, TrafficSignElement};
pub use validate::{ElementKind, Problem, ProblemKind};

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
