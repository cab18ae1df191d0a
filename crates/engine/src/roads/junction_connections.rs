//! A junction's connections as esmini holds them: the file's, in file order, then the counter
//! connections esmini adds at load for the roads the file only leaves the junction by
//! (OpenDrive::CheckConnections → CheckLink → CheckJunctionConnection): for each road in file
//! order, for each of its junction links, for each connection that road enters by, the road at
//! the connecting road's other end gets a connection into the same connecting road from the
//! other side, with the lane links of that end — unless it has one already. esmini picks a
//! junction arm among these in this order (the first one, or the one a route names), and a
//! lane with none of them cannot enter the junction. Direct junctions keep the file's.
//! Built once per network per run (`crate::run_memos`).

use opendrive::{ContactPoint, ElementType, JunctionType, RoadLink, RoadNetwork};
use std::cell::RefCell;
use std::sync::Arc;

/// One connection: entering `connecting` from `incoming` at `contact` of the connecting road;
/// lane links (incoming lane, connecting lane).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Connection {
    pub incoming: usize,
    pub connecting: usize,
    pub contact: ContactPoint,
    pub lane_links: Vec<(i32, i32)>,
}

type Built = (usize, usize, Arc<Vec<Vec<Connection>>>);

thread_local! {
    static MEMO: RefCell<Option<Built>> = const { RefCell::new(None) };
}

/// esmini's connections of every junction (indexed as `net.junctions`).
fn all(net: &RoadNetwork) -> Arc<Vec<Vec<Connection>>> {
    let key = (net as *const RoadNetwork as usize, net.roads.len());
    if let Some(all) = MEMO.with(|m| m.borrow().as_ref().filter(|b| (b.0, b.1) == key).map(|b| b.2.clone())) {
        return all;
    }
    let all = Arc::new(build(net));
    MEMO.with(|m| *m.borrow_mut() = Some((key.0, key.1, all.clone())));
    all
}

/// The connections of the junction `junction` that `road` enters by, in esmini's order.
pub(crate) fn entering(net: &RoadNetwork, junction: usize, road: usize) -> Vec<Connection> {
    all(net).get(junction).map(|c| c.iter().filter(|c| c.incoming == road).cloned().collect()).unwrap_or_default()
}

fn build(net: &RoadNetwork) -> Vec<Vec<Connection>> {
    let mut all: Vec<Vec<Connection>> = net
        .junctions
        .iter()
        .map(|j| {
            j.connections
                .iter()
                .filter_map(|c| {
                    Some(Connection {
                        incoming: net.road_index(c.incoming_road.as_deref()?)?,
                        connecting: net.road_index(c.target_road()?)?,
                        contact: c.contact_point.unwrap_or(ContactPoint::Start),
                        lane_links: c.lane_links.iter().map(|l| (l.from, l.to)).collect(),
                    })
                })
                .collect()
        })
        .collect();
    for (ri, road) in net.roads.iter().enumerate() {
        for link in [road.predecessor.as_ref(), road.successor.as_ref()].into_iter().flatten() {
            if link.element_type != ElementType::Junction {
                continue;
            }
            let Some(ji) = net.junction_index(&link.element_id) else { continue };
            if net.junctions.get(ji).is_none_or(|j| j.kind == JunctionType::Direct) {
                continue;
            }
            let Some(conns) = all.get_mut(ji) else { continue };
            let n = conns.len();
            for i in 0..n {
                if conns[i].incoming == ri {
                    add_counter_connection(net, &link.element_id, conns, i);
                }
            }
        }
    }
    all
}

/// esmini's CheckJunctionConnection for a default junction: the counter connection of
/// connection `i` for the road at the other end of its connecting road.
fn add_counter_connection(net: &RoadNetwork, junction_id: &str, conns: &mut Vec<Connection>, i: usize) {
    let Some(c) = conns.get(i).cloned() else { return };
    let Some(cr) = net.roads.get(c.connecting) else { return };
    for (side, link) in [(ContactPoint::Start, cr.predecessor.as_ref()), (ContactPoint::End, cr.successor.as_ref())] {
        let Some(link) = link.filter(|l| l.element_type == ElementType::Road) else { continue };
        let Some(other) = net.road_index(&link.element_id) else { continue };
        if other == c.incoming {
            continue;
        }
        let Some(other_road) = net.roads.get(other) else { continue };
        let links_here = |l: Option<&RoadLink>| l.is_some_and(|l| l.element_type == ElementType::Junction && l.element_id == junction_id);
        for back in [other_road.predecessor.as_ref(), other_road.successor.as_ref()] {
            if !links_here(back) {
                continue;
            }
            if conns.iter().any(|x| x.incoming == other && x.connecting == c.connecting) {
                // esmini returns from the whole check here
                return;
            }
            let section = if side == ContactPoint::Start { 0 } else { cr.lane_sections.len().saturating_sub(1) };
            let lane_links: Vec<(i32, i32)> = cr
                .lane_sections
                .get(section)
                .map(|sec| {
                    sec.lanes_left_to_right()
                        .filter_map(|l| {
                            let to = if side == ContactPoint::Start { l.predecessors.first() } else { l.successors.first() };
                            to.map(|&t| (t, l.id))
                        })
                        .collect()
                })
                .unwrap_or_default();
            if !lane_links.is_empty() {
                let contact = if c.contact == ContactPoint::End { ContactPoint::Start } else { ContactPoint::End };
                conns.push(Connection { incoming: other, connecting: c.connecting, contact, lane_links });
            }
        }
    }
}

/// One run's entry (`crate::run_memos`).
pub(crate) struct Store(Option<Built>);

impl Store {
    /// No entry.
    pub(crate) fn new() -> Store {
        Store(None)
    }

    /// Exchange this entry with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        MEMO.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.0));
    }
}
