//! The grammar: a seeded generator of OpenSCENARIO 1.3 scenarios that esmini 3.6.0 accepts,
//! reaching the language users write — every position type esmini reads, routes through
//! junctions, trajectories of every shape, the private and global actions, the conditions,
//! esmini's driver models, vehicles, bicycles, trailers, pedestrians and objects — on maps
//! it writes itself or reads from a folder. Every place is computed from the loaded map.
//!
//! Determinism: every random choice comes from a ChaCha8 generator seeded with the seed and
//! set to the scenario's index as its stream, so scenario `i` of a seed is always the same
//! bytes, whatever else is generated. Each file holds one idea: `maps`/`map_text`/`lanes` the
//! maps and what is known of them, `entity_kind`/`entities`, `positions`, `routes`, `trajectories`,
//! `actions`/`global_actions`, `conditions`, `controllers`, and `storyboard`, which puts a
//! scenario together. A scenario's features (`action:SpeedAction`, `init:RoutePosition`,
//! `controller:ACCController/override`, …) name what it exercises; the report tallies
//! agreement by feature.

mod actions;
mod conditions;
mod controllers;
mod entities;
mod entity_kind;
mod global_actions;
pub mod lanes;
pub mod map_text;
pub mod maps;
mod positions;
mod routes;
mod storyboard;
mod trajectories;
mod versions;

use std::collections::BTreeSet;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub use entity_kind::EntityKind;
use lanes::Place;
use maps::MapChoice;

/// One generated scenario: its text and the features it exercises.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    pub name: String,
    pub xosc: String,
    /// e.g. `action:SpeedAction`, `dynamics:SpeedAction/cubic/time`, `condition:SpeedCondition`.
    pub features: BTreeSet<String>,
}

/// What the generator decided about one entity.
#[derive(Debug, Clone)]
pub(crate) struct EntityPlan {
    pub name: String,
    pub kind: EntityKind,
    /// Where the Init puts it (as far as the generator can tell).
    pub place: Option<Place>,
    /// Its Init speed, m/s (negative: reversing).
    pub speed: f64,
    /// The esmini type of its controller, if it has one.
    pub controller: Option<String>,
}

impl EntityPlan {
    /// Moves by itself (vehicles and pedestrians; not objects or trailers).
    pub(crate) fn mobile(&self) -> bool {
        matches!(self.kind, EntityKind::Car | EntityKind::Truck | EntityKind::Bicycle | EntityKind::Pedestrian)
    }
    pub(crate) fn vehicle(&self) -> bool {
        matches!(self.kind, EntityKind::Car | EntityKind::Truck | EntityKind::Bicycle)
    }
}

/// The areas of the language. Each scenario focuses on one: the focus draws from its whole
/// grammar, every other area from a plain core (lane positions, speed and lane changes,
/// simulation-time triggers, cars) unless it is drawn in too (one chance in ten each), so
/// that a divergence can be told to the area it comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Area {
    Positions,
    Routes,
    Trajectories,
    Longitudinal,
    Lateral,
    Conditions,
    Controllers,
    RoadUsers,
    Globals,
}

impl Area {
    pub const ALL: [Area; 9] = [
        Area::Positions,
        Area::Routes,
        Area::Trajectories,
        Area::Longitudinal,
        Area::Lateral,
        Area::Conditions,
        Area::Controllers,
        Area::RoadUsers,
        Area::Globals,
    ];
    pub fn label(self) -> &'static str {
        match self {
            Area::Positions => "positions",
            Area::Routes => "routes",
            Area::Trajectories => "trajectories",
            Area::Longitudinal => "longitudinal",
            Area::Lateral => "lateral",
            Area::Conditions => "conditions",
            Area::Controllers => "controllers",
            Area::RoadUsers => "road-users",
            Area::Globals => "globals",
        }
    }
}

/// A declared parameter or variable: name, OpenSCENARIO type, initial value.
#[derive(Debug, Clone)]
pub(crate) struct Declared {
    pub name: String,
    pub kind: &'static str,
    pub value: String,
}

/// The generator's state while it writes one scenario.
pub(crate) struct Gen<'a> {
    pub rng: ChaCha8Rng,
    pub features: BTreeSet<String>,
    pub map: &'a MapChoice,
    pub entities: Vec<EntityPlan>,
    pub parameters: Vec<Declared>,
    pub variables: Vec<Declared>,
    /// Storyboard elements written so far, (type, name), for StoryboardElementStateConditions.
    pub elements: Vec<(&'static str, String)>,
    /// The scenario uses the map's signals (its RoadNetwork then declares a signal controller).
    pub uses_signals: bool,
    /// The names every entity will have (known before any is written).
    pub all_names: Vec<String>,
    /// The event being written (its name is `E{n}`).
    pub current_event: usize,
    /// Entities a DeleteEntityAction removes, with the event that removes them.
    pub deleted: Vec<(String, String)>,
    /// A start condition the event being written must have (set by its action: an absolute
    /// trajectory starts when its times begin, an entity is added back after its deletion).
    pub forced_condition: Option<String>,
    /// A counter for unique names of routes and trajectories.
    serial: u32,
    /// The areas drawn from their whole grammar (bit per `Area::ALL` index).
    rich: u16,
    /// The FileHeader's `revMinor` (OpenSCENARIO 1.0 to 1.3): esmini reads some elements
    /// differently before 1.3 (an Orientation without a type, a controller's name).
    pub rev_minor: u32,
    /// Entities whose ObjectController wrapper has a name (`{entity}Ctrl`).
    pub named_wrappers: Vec<String>,
    /// Events whose action esmini 3.6.0 drops when reading (a ParameterModifyAction, a
    /// TrafficSignalControllerAction): a StoryboardElementStateCondition on such an action is
    /// fatal to esmini ("StoryboardElement … not found"), so it is turned onto the event.
    pub dropped_actions: Vec<usize>,
    /// The (action name, state) of every StoryboardElementStateCondition on an action; their
    /// features are named once the dropped actions are known.
    pub action_state_refs: Vec<(String, String)>,
}

impl<'a> Gen<'a> {
    fn new(rng: ChaCha8Rng, map: &'a MapChoice) -> Self {
        Gen {
            rng,
            features: BTreeSet::new(),
            map,
            entities: Vec::new(),
            parameters: Vec::new(),
            variables: Vec::new(),
            elements: Vec::new(),
            uses_signals: false,
            all_names: Vec::new(),
            current_event: 0,
            deleted: Vec::new(),
            forced_condition: None,
            serial: 0,
            rich: 0,
            rev_minor: 3,
            named_wrappers: Vec::new(),
            dropped_actions: Vec::new(),
            action_state_refs: Vec::new(),
        }
    }

    /// Chooses the scenario's focus and the areas drawn in with it (named as features), and its
    /// OpenSCENARIO version (`rev_minor` when given).
    fn choose_areas(&mut self, rev_minor: Option<u32>) {
        let focus = self.rng.gen_range(0..Area::ALL.len());
        self.feature(format!("focus:{}", Area::ALL[focus].label()));
        for (i, a) in Area::ALL.iter().enumerate() {
            if i == focus || self.rng.gen_bool(0.1) {
                self.rich |= 1 << i;
                self.feature(format!("area:{}", a.label()));
            }
        }
        // mostly 1.3; older files as users still write them
        if self.rng.gen_bool(0.25) {
            self.rev_minor = self.rng.gen_range(0..3);
        }
        if let Some(v) = rev_minor {
            self.rev_minor = v;
        }
        self.feature(format!("header:OpenSCENARIO 1.{}", self.rev_minor));
    }

    /// Whether `area` draws from its whole grammar in this scenario.
    pub(crate) fn rich(&self, area: Area) -> bool {
        Area::ALL.iter().position(|a| *a == area).is_some_and(|i| self.rich & (1 << i) != 0)
    }

    pub(crate) fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.rng.gen_range(0..items.len())]
    }
    pub(crate) fn pick_index(&mut self, n: usize) -> usize {
        self.rng.gen_range(0..n.max(1))
    }
    pub(crate) fn chance(&mut self, p: f64) -> bool {
        self.rng.gen_bool(p.clamp(0.0, 1.0))
    }
    /// A number in [lo, hi) with two decimals: the file says exactly what both simulators read.
    /// An empty range gives `lo`.
    pub(crate) fn num(&mut self, lo: f64, hi: f64) -> f64 {
        if hi <= lo {
            return (lo * 100.0).round() / 100.0;
        }
        (self.rng.gen_range(lo..hi) * 100.0).round() / 100.0
    }
    pub(crate) fn feature(&mut self, f: impl Into<String>) {
        self.features.insert(f.into());
    }
    /// A fresh name with `prefix`.
    pub(crate) fn unique(&mut self, prefix: &str) -> String {
        self.serial += 1;
        format!("{prefix}{}", self.serial)
    }
    pub(crate) fn entity(&self, name: &str) -> Option<&EntityPlan> {
        self.entities.iter().find(|e| e.name == name)
    }
    /// Names of the entities that move by themselves.
    pub(crate) fn mobile_names(&self) -> Vec<String> {
        self.entities.iter().filter(|e| e.mobile()).map(|e| e.name.clone()).collect()
    }
    pub(crate) fn names(&self) -> Vec<String> {
        self.entities.iter().map(|e| e.name.clone()).collect()
    }
    /// A random driving spot of the map and a place on it.
    pub(crate) fn random_place(&mut self) -> Place {
        let spots: Vec<&lanes::Spot> = self.map.driving_spots().collect();
        let spot = spots[self.rng.gen_range(0..spots.len())].clone();
        let s = self.num(spot.s_min, spot.s_max.max(spot.s_min + 0.01));
        Place { road: spot.road, lane: spot.lane, s, forward: spot.along_s }
    }
    /// The place of entity `name` at the start, or a random one if unknown.
    pub(crate) fn place_of(&mut self, name: &str) -> Place {
        match self.entity(name).and_then(|e| e.place) {
            Some(p) => p,
            None => self.random_place(),
        }
    }
    /// OpenDRIVE id of road index `road`.
    pub(crate) fn road_id(&self, road: usize) -> String {
        self.map.net.roads.get(road).map_or_else(String::new, |r| r.id.clone())
    }
}

/// Three decimals, for computed coordinates.
pub(crate) fn f3(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r == 0.0 {
        "0".into()
    } else {
        format!("{r}")
    }
}

/// Scenario `index` of `seed` on one of `maps` (referred to by `map.name` from the folder the
/// scenario is written to). A quarter of them are written as OpenSCENARIO 1.0, 1.1 or 1.2, the
/// versions users' older files have, in their words (`versions`); one that uses what its
/// version's schema does not have is written again as 1.3 (the same draws otherwise), so every
/// file is valid for its own version.
pub fn generate(seed: u64, index: u64, maps: &[MapChoice]) -> Generated {
    let older = generate_as(seed, index, maps, None);
    if older.rev_minor >= 3 || valid_for_its_version(&older) {
        return older.generated;
    }
    generate_as(seed, index, maps, Some(3)).generated
}

struct Draft {
    generated: Generated,
    rev_minor: u32,
}

fn generate_as(seed: u64, index: u64, maps: &[MapChoice], rev_minor: Option<u32>) -> Draft {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    let map = &maps[rng.gen_range(0..maps.len())];
    let mut g = Gen::new(rng, map);
    g.choose_areas(rev_minor);
    let xosc = g.scenario(seed, index);
    Draft { generated: Generated { name: format!("s{seed}_{index:05}"), xosc, features: g.features }, rev_minor: g.rev_minor }
}

/// No error, and nothing that came with a later version than the file declares (the
/// validator warns of it, naming the version, as esmini reads it anyway): a file of 1.0 is
/// written as users' 1.0 files are.
fn valid_for_its_version(d: &Draft) -> bool {
    let path = std::path::Path::new(&d.generated.name);
    openscenario::validate::validate_str(path, &d.generated.xosc, &[]).iter().all(|f| !strictly_invalid(f))
}

/// An error, or a construct of a later version than the file declares.
pub fn strictly_invalid(f: &openscenario::validate::Finding) -> bool {
    f.severity == openscenario::validate::Severity::Error || f.message.contains("(the file declares 1.")
}
