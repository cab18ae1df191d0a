//! Routes and trajectory paths that positions name, built once per run: a ReachPosition
//! condition on a RoutePosition would otherwise plan the route again every step. Only
//! shapes whose positions refer to no entity are cached (others change as entities move);
//! entries are keyed by the model's address, valid while the scenario is borrowed by the
//! run, and each run keeps its own entries (`run_memos.rs`).

use openscenario::{Position, Route, Shape, Trajectory};
use std::cell::RefCell;
use std::sync::Arc;

type RouteEntry = (usize, Arc<routing::Route>);
type PathEntry = (usize, Arc<trajectory::Path>);

thread_local! {
    static ROUTES: RefCell<Vec<RouteEntry>> = const { RefCell::new(Vec::new()) };
    static PATHS: RefCell<Vec<PathEntry>> = const { RefCell::new(Vec::new()) };
}

/// Most entries kept (hostile input: many distinct positions).
const MAX_ENTRIES: usize = 256;

/// One run's entries (`crate::run_memos`).
pub(crate) struct Store {
    routes: Vec<RouteEntry>,
    paths: Vec<PathEntry>,
}

impl Store {
    /// No entries.
    pub(crate) fn new() -> Store {
        Store { routes: Vec::new(), paths: Vec::new() }
    }

    /// Exchange these entries with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        ROUTES.with(|c| std::mem::swap(&mut *c.borrow_mut(), &mut self.routes));
        PATHS.with(|c| std::mem::swap(&mut *c.borrow_mut(), &mut self.paths));
    }
}

fn is_static(p: &Position) -> bool {
    match p {
        Position::Route { route, in_route, .. } => {
            !matches!(in_route, openscenario::InRoutePosition::FromCurrentEntity { .. }) && route.waypoints.iter().all(|w| is_static(&w.position))
        }
        Position::Trajectory { trajectory, .. } => trajectory_is_static(trajectory),
        other => other.reference_entity().is_none(),
    }
}

fn trajectory_is_static(t: &Trajectory) -> bool {
    match &t.shape {
        Shape::Polyline(v) => v.iter().all(|x| is_static(&x.position)),
        Shape::Clothoid { position, .. } => position.as_deref().is_some_and(is_static),
        Shape::ClothoidSpline { segments, .. } => segments.iter().all(|s| s.position_start.as_ref().is_some_and(is_static)),
        Shape::Nurbs { control_points, .. } => control_points.iter().all(|c| is_static(&c.position)),
    }
}

/// The planned route of `model`, from the cache when it can be.
pub(crate) fn route(model: &Route, plan: impl FnOnce() -> Result<routing::Route, String>) -> Result<Arc<routing::Route>, String> {
    let key = model as *const Route as usize;
    if let Some(r) = ROUTES.with(|c| c.borrow().iter().find(|e| e.0 == key).map(|e| e.1.clone())) {
        return Ok(r);
    }
    let r = Arc::new(plan()?);
    if model.waypoints.iter().all(|w| is_static(&w.position)) {
        ROUTES.with(|c| {
            let mut c = c.borrow_mut();
            if c.len() < MAX_ENTRIES {
                c.push((key, r.clone()));
            }
        });
    }
    Ok(r)
}

/// The path of `model` for a TrajectoryPosition, from the cache when it can be.
pub(crate) fn path(model: &Trajectory, build: impl FnOnce() -> Result<trajectory::Path, String>) -> Result<Arc<trajectory::Path>, String> {
    let key = model as *const Trajectory as usize;
    if let Some(p) = PATHS.with(|c| c.borrow().iter().find(|e| e.0 == key).map(|e| e.1.clone())) {
        return Ok(p);
    }
    let p = Arc::new(build()?);
    if trajectory_is_static(model) {
        PATHS.with(|c| {
            let mut c = c.borrow_mut();
            if c.len() < MAX_ENTRIES {
                c.push((key, p.clone()));
            }
        });
    }
    Ok(p)
}
