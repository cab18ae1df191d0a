//! esmini's OSI ids. esmini 3.6.0 numbers every OSI item from one counter (`GetNewGlobalId`) as
//! it creates it: while reading the OpenDRIVE file each road's lanes in document order (each
//! lane's road-mark lines right after it), then the road's signals and objects; then the
//! junctions; then, once the file is read, a lane boundary for every lane without road marks
//! (`SetLaneBoundaryPoints`, lanes from left to right); then the scenario's objects
//! (`Entities::addObject`), in esmini's object order. So an entity's OSI id is the number of
//! road items plus its object index, and a lane's id says where it stands in the file.
//! Road-mark lines come from a mark's `<type>`/`<explicit>` lines, else from esmini's stand-in
//! lines for its type (one, or two for the double types). A traffic light's lamps take their ids
//! just before the light (`opendrive::traffic_light_lamps` counts them). Not checked against
//! esmini: maps with tunnels (esmini builds OSI items for a tunnel's walls).

use std::collections::HashMap;

use opendrive::{JunctionType, RoadKind, RoadMark, RoadMarkType, RoadNetwork};

/// esmini's `ID_UNDEFINED` as an OSI id: what `assigned_lane_id` holds off any road.
pub const UNDEFINED: u64 = 0xFFFF_FFFF;

/// A lane: (road index, lane section index, OpenDRIVE lane id).
pub type LaneKey = (usize, usize, i32);

/// The ids esmini gives a road network's items and the first id left for the entities.
#[derive(Debug, Clone, Default)]
pub struct GlobalIds {
    pub lanes: HashMap<LaneKey, u64>,
    /// Each lane's road-mark lines, in mark order.
    pub lines: HashMap<LaneKey, Vec<u64>>,
    /// The boundary of each lane without road marks.
    pub boundaries: HashMap<LaneKey, u64>,
    pub first_entity: u64,
}

/// The stand-in lines esmini creates for a mark without `<type>`/`<explicit>` lines
/// (RoadManager.cpp, OpenDrive::ParseOpenDRIVE): their count.
pub fn stand_in_lines(kind: RoadMarkType) -> usize {
    match kind {
        RoadMarkType::None | RoadMarkType::Edge | RoadMarkType::Solid | RoadMarkType::Curb | RoadMarkType::Broken => 1,
        RoadMarkType::SolidSolid | RoadMarkType::BrokenBroken | RoadMarkType::BrokenSolid | RoadMarkType::SolidBroken => 2,
        _ => 0,
    }
}

/// Lines of road mark `m` (esmini: its explicit lines, else the stand-ins).
pub fn mark_lines(m: &RoadMark) -> usize {
    if m.lines > 0 {
        m.lines
    } else {
        stand_in_lines(m.kind)
    }
}

/// Whether esmini treats junction `j` as an OSI intersection (`Junction::IsOsiIntersection`):
/// not direct, and its first incoming road not a motorway.
pub fn is_osi_intersection(net: &RoadNetwork, j: &opendrive::Junction) -> bool {
    if j.kind == JunctionType::Direct {
        return false;
    }
    let incoming = j.connections.first().and_then(|c| c.incoming_road.as_deref()).and_then(|id| net.road(id));
    match incoming.and_then(|r| r.type_at(0.0)) {
        Some(t) => t.kind != RoadKind::Motorway,
        None => true,
    }
}

impl GlobalIds {
    /// The ids of `net`'s items (none without a road network).
    pub fn new(net: Option<&RoadNetwork>) -> GlobalIds {
        let mut ids = GlobalIds::default();
        let Some(net) = net else { return ids };
        let mut next = 0u64;
        let mut take = || {
            let id = next;
            next += 1;
            id
        };
        for (r, road) in net.roads.iter().enumerate() {
            for (j, sec) in road.lane_sections.iter().enumerate() {
                // document order: esmini adds the lanes as it reads them
                let mut lanes: Vec<&opendrive::Lane> = sec.left.iter().chain(&sec.center).chain(&sec.right).collect();
                lanes.sort_by_key(|l| (l.pos.line, l.pos.col));
                for lane in lanes {
                    ids.lanes.insert((r, j, lane.id), take());
                    let lines: Vec<u64> = lane.road_marks.iter().flat_map(|m| (0..mark_lines(m)).collect::<Vec<_>>()).map(|_| take()).collect();
                    if !lines.is_empty() {
                        ids.lines.insert((r, j, lane.id), lines);
                    }
                }
            }
            for signal in &road.signals {
                // a traffic light's lamps are numbered as it is built, before the light itself
                // (TrafficLight::SetTrafficLightInfo, then Signal::SetGlobalId)
                for _ in 0..opendrive::traffic_light_lamps(signal).unwrap_or(0) {
                    take();
                }
                take();
            }
            for _ in &road.objects {
                take();
            }
        }
        for _ in &net.junctions {
            take();
        }
        for (r, road) in net.roads.iter().enumerate() {
            for (j, sec) in road.lane_sections.iter().enumerate() {
                // esmini keeps a section's lanes sorted from left to right
                let mut lanes: Vec<&opendrive::Lane> = sec.left.iter().chain(&sec.center).chain(&sec.right).collect();
                lanes.sort_by_key(|l| std::cmp::Reverse(l.id));
                for lane in lanes {
                    if lane.road_marks.is_empty() {
                        ids.boundaries.insert((r, j, lane.id), take());
                    }
                }
            }
        }
        ids.first_entity = next;
        ids
    }

    /// The id of lane `key` (esmini's `ID_UNDEFINED` when it has none).
    pub fn lane(&self, key: LaneKey) -> u64 {
        self.lanes.get(&key).copied().unwrap_or(UNDEFINED)
    }

    /// The boundary ids of lane `key`'s outer border: its road-mark lines, else its boundary.
    pub fn outer_boundary(&self, key: LaneKey) -> Vec<u64> {
        match self.lines.get(&key) {
            Some(lines) => lines.clone(),
            None => self.boundaries.get(&key).copied().into_iter().collect(),
        }
    }
}
