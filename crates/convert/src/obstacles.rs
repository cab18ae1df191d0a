//! From tracks to CommonRoad obstacle elements: vehicles and pedestrians are dynamic
//! obstacles; a miscellaneous object that never moves is a static obstacle when its type is
//! one a `staticObstacle` may have, an environment obstacle when it is a building, pillar or
//! median strip; a moving one is a dynamic obstacle (`unknown` when its type is not a
//! dynamic type).

use commonroad::{AbsoluteShape, DynamicObstacle, DynamicObstacleType, EnvironmentObstacle, IdAllocator, PlacedRectangle, Point, Rectangle, StaticObstacle};

use crate::tracks::{Placement, Track};

/// The obstacles of a scenario, in track order within each element kind.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Obstacles {
    pub dynamic: Vec<DynamicObstacle>,
    pub statics: Vec<commonroad::StaticObstacle>,
    pub environment: Vec<EnvironmentObstacle>,
    /// The entity each obstacle was made of, by obstacle id.
    pub names: Vec<(u64, String)>,
    pub warnings: Vec<String>,
}

/// Builds the obstacles of `tracks`, leaving out the entities named in `skip` (the ego under
/// `--drop-ego`, the egos of carried planning problems). Ids come from `ids` in track order.
pub fn obstacles(tracks: &[Track], skip: &[&str], ids: &mut IdAllocator) -> Obstacles {
    let mut out = Obstacles::default();
    for t in tracks {
        if skip.contains(&t.entity.as_str()) {
            continue;
        }
        match &t.placement {
            Placement::Fixed { x, y, orientation, .. } => {
                if let Some(kind) = t.cr_type.static_type() {
                    let id = ids.obstacle();
                    out.names.push((id.get(), t.entity.clone()));
                    out.statics.push(StaticObstacle { id, obstacle_type: kind, shape: t.shape.clone(), x: *x, y: *y, orientation: *orientation });
                } else if let Some(kind) = t.cr_type.environment() {
                    let Ok(rectangle) = Rectangle::new(t.length, t.width) else {
                        out.warnings.push(format!("entity {:?}: no valid box: left out", t.entity));
                        continue;
                    };
                    let id = ids.obstacle();
                    out.names.push((id.get(), t.entity.clone()));
                    out.environment.push(EnvironmentObstacle {
                        id,
                        obstacle_type: kind,
                        shape: AbsoluteShape::Rectangle(PlacedRectangle { rectangle, center: Point::new(*x, *y), orientation: *orientation }),
                    });
                } else {
                    // only misc objects are fixed, and every misc type is static or environment
                    out.warnings.push(format!("entity {:?}: type {:?} fits neither a static nor an environment obstacle: left out", t.entity, t.cr_type));
                }
            }
            Placement::Moving(runs) => {
                let kind = match t.cr_type.dynamic() {
                    Some(k) => k,
                    None => {
                        out.warnings.push(format!(
                            "entity {:?} moves but its type {:?} is not allowed for a dynamic obstacle: written as unknown",
                            t.entity, t.cr_type
                        ));
                        DynamicObstacleType::Unknown
                    }
                };
                for run in runs {
                    let Some((first, rest)) = run.split_first() else {
                        continue;
                    };
                    let id = ids.obstacle();
                    out.names.push((id.get(), t.entity.clone()));
                    out.dynamic.push(DynamicObstacle { id, obstacle_type: kind, shape: t.shape.clone(), initial_state: *first, trajectory: rest.to_vec() });
                }
            }
        }
    }
    out
}
