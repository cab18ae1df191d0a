//! The order in which Init private actions run. esmini (`ScenarioReader::parseInit` and
//! `moveInitObjectActions`) moves the actions of an entity whose TeleportAction is relative to
//! another entity (RelativeLane/World/Object positions) behind that entity's actions, so the
//! reference is placed first — repeating the pass until nothing moves, at most twice the number
//! of actions. Reproduced step by step, since the resulting order decides who is where.

use openscenario::{ActionKind, Position, PrivateAction};

/// One Init private action: the entity it belongs to and the entity its teleport is relative
/// to (if it is such a teleport).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct InitItem {
    pub entity: usize,
    pub relative_to: Option<usize>,
    /// Position of the action in file order.
    pub index: usize,
}

/// The entity a TeleportAction's position refers to, for the position types esmini reorders.
pub(crate) fn teleport_reference(kind: &ActionKind) -> Option<&str> {
    match kind {
        ActionKind::Private(PrivateAction::Teleport(
            Position::RelativeLane { entity, .. } | Position::RelativeWorld { entity, .. } | Position::RelativeObject { entity, .. },
        )) => Some(entity),
        _ => None,
    }
}

/// Reorders `items` (Init private actions in file order) as esmini does; returns whether it gave
/// up (a circular dependency), as esmini warns then.
pub(crate) fn reorder(items: &mut Vec<InitItem>) -> bool {
    let max_loops = 2 * items.len();
    let mut counter = 0;
    let mut done = false;
    while !done && counter < max_loops {
        done = true;
        let mut i = 0;
        while i < items.len() {
            let it = items[i];
            if let Some(r) = it.relative_to.filter(|&r| r != it.entity) {
                if move_object_actions(items, it.entity, r) {
                    done = false;
                }
            }
            i += 1;
        }
        counter += 1;
    }
    counter >= max_loops && !done
}

/// esmini's `moveInitObjectActions`: the actions of `object` that come before the first action
/// of `referred` move to just after the run of `referred`'s actions.
fn move_object_actions(items: &mut Vec<InitItem>, object: usize, referred: usize) -> bool {
    let mut moved = Vec::with_capacity(items.len());
    let mut tmp = Vec::new();
    let mut found = false;
    for &a in items.iter() {
        if a.entity == referred {
            found = true;
            if tmp.is_empty() {
                return false;
            }
        } else if a.entity == object && !found {
            tmp.push(a);
            continue;
        } else if found && !tmp.is_empty() {
            moved.append(&mut tmp);
        }
        moved.push(a);
    }
    moved.append(&mut tmp);
    *items = moved;
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(entity: usize, relative_to: Option<usize>) -> InitItem {
        InitItem { entity, relative_to, index: 0 }
    }

    #[test]
    fn a_chain_of_relative_teleports_is_placed_reference_first() {
        // init_actions_reorder.xosc: car0 relative to car1, car1 relative to car2, car2 on a lane;
        // two actions each (teleport, speed)
        let mut v = vec![item(0, Some(1)), item(0, None), item(1, Some(2)), item(1, None), item(2, None), item(2, None)];
        assert!(!reorder(&mut v));
        let order: Vec<usize> = v.iter().map(|i| i.entity).collect();
        assert_eq!(order, [2, 2, 1, 1, 0, 0]);
    }

    #[test]
    fn a_circle_gives_up() {
        let mut v = vec![item(0, Some(1)), item(1, Some(0))];
        assert!(reorder(&mut v));
    }

    #[test]
    fn an_order_already_right_stays() {
        let mut v = vec![item(1, None), item(0, Some(1)), item(0, None)];
        assert!(!reorder(&mut v));
        assert_eq!(v, [item(1, None), item(0, Some(1)), item(0, None)]);
    }
}
