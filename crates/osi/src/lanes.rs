//! The lanes and lane boundaries of a road network, as esmini's `OSIReporter::UpdateOSIRoadLane`
//! and `UpdateOSILaneBoundary` report them once, in the first frame: every lane but the centre
//! lanes (and the lanes of junctions esmini treats as intersections) with its type and subtype
//! (esmini's table), its centre line on esmini's OSI points, whether the centre line runs in the
//! driving direction, its left and right neighbours (skipping the centre lane) and the ids of
//! the boundaries on either side; and a boundary for each road-mark line (on the lane's outer
//! border, a double line's two lines ±its width apart) or, for a lane without road marks, its
//! outer border (`TYPE_ROAD_EDGE` for the outermost lane, else `TYPE_NO_LINE`). Not reported:
//! the lanes esmini builds for intersections, lane pairings (successors and predecessors),
//! broken lines as dashes (their line is given whole), and a line's own offset from an explicit
//! `<type>` definition (the line lies on the border).

use opendrive::{Lane, LaneSection, LaneType, Road, RoadMark, RoadMarkType, RoadNetwork, TrafficRule};

use crate::global_ids::{is_osi_intersection, mark_lines, GlobalIds, LaneKey};
use crate::moving::{id, vec3};
use crate::osi3::lane::classification::{Subtype, Type};
use crate::osi3::lane_boundary::classification::{Color, Type as BoundaryType};
use crate::osi3::lane_boundary::BoundaryPoint;
use crate::osi3::{lane, lane_boundary, ExternalReference, Identifier, Lane as OsiLane, LaneBoundary, Vector3d};

/// esmini's `SOURCE_REF_TYPE_ODR`.
const SOURCE_ODR: &str = "net.asam.opendrive";
/// esmini's ROADMARK_WIDTH_STANDARD, the offset of a double line's stand-in lines.
const ROADMARK_WIDTH: f64 = 0.15;

fn lane_type(t: LaneType) -> (Type, Subtype) {
    match t {
        LaneType::Driving | LaneType::Bidirectional => (Type::Driving, Subtype::Normal),
        LaneType::Parking => (Type::Nondriving, Subtype::Parking),
        LaneType::Stop => (Type::Nondriving, Subtype::Stop),
        LaneType::Biking => (Type::Nondriving, Subtype::Biking),
        LaneType::Sidewalk => (Type::Nondriving, Subtype::Sidewalk),
        LaneType::Border | LaneType::Curb => (Type::Nondriving, Subtype::Border),
        LaneType::Restricted => (Type::Nondriving, Subtype::Restricted),
        LaneType::RoadWorks | LaneType::Tram | LaneType::Rail | LaneType::Median => (Type::Nondriving, Subtype::Other),
        LaneType::Entry => (Type::Driving, Subtype::Entry),
        LaneType::Exit => (Type::Driving, Subtype::Exit),
        LaneType::OffRamp => (Type::Driving, Subtype::Offramp),
        LaneType::OnRamp => (Type::Driving, Subtype::Onramp),
        LaneType::Shoulder => (Type::Nondriving, Subtype::Shoulder),
        LaneType::ConnectingRamp => (Type::Driving, Subtype::Connectingramp),
        LaneType::Special1 | LaneType::Special2 | LaneType::Special3 => (Type::Other, Subtype::Other),
        _ => (Type::Unknown, Subtype::Unknown),
    }
}

fn ids(v: impl IntoIterator<Item = u64>) -> Vec<Identifier> {
    v.into_iter().map(|x| Identifier { value: Some(x) }).collect()
}

/// The points of the curve at `t(s)` from `s0` to `s1` on `road`, on esmini's OSI points.
fn points(road: &Road, (s0, s1): (f64, f64), t: impl Fn(f64) -> Option<f64>) -> Vec<Option<Vector3d>> {
    let xy = |s: f64| {
        let p = road.st_to_world(s, t(s)?);
        Some((p.x, p.y))
    };
    opendrive::road_osi_points(road, s0, s1, xy)
        .into_iter()
        .filter_map(|s| {
            let p = road.st_to_world(s, t(s)?);
            Some(vec3(p.x, p.y, p.z))
        })
        .collect()
}

/// t of lane `lane_id`'s outer border (the centre lane: the lane offset).
fn outer(road: &Road, j: usize, lane_id: i32, s: f64) -> Option<f64> {
    road.lane_borders(j, lane_id, s).map(|b| b.outer)
}

/// esmini's road lanes (`LANE_TYPE_ANY_ROAD`): driving, entry, exit, ramps, bidirectional,
/// restricted, stop, shoulder, parking.
fn is_road_lane(t: LaneType) -> bool {
    use LaneType::*;
    matches!(t, Driving | Entry | Exit | OffRamp | OnRamp | ConnectingRamp | Bidirectional | Restricted | Stop | Shoulder | Parking)
}

/// esmini's road edge (OpenDrive::ParseOpenDRIVE): the outermost road lane of each side, and
/// the centre lane when a side has none.
fn is_road_edge(sec: &LaneSection, lane_id: i32) -> bool {
    let right = sec.right.iter().filter(|l| is_road_lane(l.kind)).map(|l| l.id).min().unwrap_or(0);
    let left = sec.left.iter().filter(|l| is_road_lane(l.kind)).map(|l| l.id).max().unwrap_or(0);
    match lane_id {
        0 => right == 0 || left == 0,
        id => id == right || id == left,
    }
}

fn is_osi_lane(sec: &LaneSection, lane_id: i32) -> bool {
    lane_id != 0 && sec.lane(lane_id).is_some()
}

fn boundary_type(kind: RoadMarkType) -> BoundaryType {
    match kind {
        RoadMarkType::None => BoundaryType::NoLine,
        RoadMarkType::Broken | RoadMarkType::BrokenBroken => BoundaryType::DashedLine,
        RoadMarkType::BottsDots => BoundaryType::BottsDots,
        RoadMarkType::Edge => BoundaryType::RoadEdge,
        _ => BoundaryType::SolidLine,
    }
}

fn color(m: &RoadMark) -> Color {
    match m.color.as_deref().map(str::to_ascii_lowercase).as_deref() {
        Some("blue") => Color::Blue,
        Some("green") => Color::Green,
        Some("red") => Color::Red,
        Some("yellow") => Color::Yellow,
        _ => Color::White,
    }
}

/// The boundaries of lane `key`'s outer border.
fn boundaries_of(road: &Road, key: LaneKey, lane: &Lane, gids: &GlobalIds, out: &mut Vec<LaneBoundary>) {
    let (_, j, lane_id) = key;
    let Some(range) = road.section_range(j) else { return };
    let side = if lane_id < 1 { -1.0 } else { 1.0 };
    let Some(line_ids) = gids.lines.get(&key) else {
        let Some(&bid) = gids.boundaries.get(&key) else { return };
        let edge = road.lane_sections.get(j).is_some_and(|sec| is_road_edge(sec, lane_id));
        out.push(LaneBoundary {
            id: id(bid),
            boundary_line: points(road, range, |s| outer(road, j, lane_id, s))
                .into_iter()
                .map(|position| BoundaryPoint { position, ..Default::default() })
                .collect(),
            classification: Some(lane_boundary::Classification {
                r#type: Some(if edge { BoundaryType::RoadEdge } else { BoundaryType::NoLine } as i32),
                color: Some(Color::Unknown as i32),
            }),
        });
        return;
    };
    let mut next = line_ids.iter();
    for (i, m) in lane.road_marks.iter().enumerate() {
        // a mark runs from its start to the next mark's
        let from = (range.0 + m.s_offset).min(range.1);
        let to = lane.road_marks.get(i + 1).map_or(range.1, |n| (range.0 + n.s_offset).clamp(from, range.1));
        let n = mark_lines(m);
        let width = m.width.unwrap_or(ROADMARK_WIDTH);
        for k in 0..n {
            let Some(&line_id) = next.next() else { return };
            // a double stand-in: the first line inside, the second outside
            let dt = if n == 2 && m.lines == 0 {
                if k == 0 {
                    -width * side
                } else {
                    width * side
                }
            } else {
                0.0
            };
            let line: Vec<BoundaryPoint> = points(road, (from, to), |s| outer(road, j, lane_id, s).map(|t| t + dt))
                .into_iter()
                .map(|position| BoundaryPoint { position, width: Some(width), height: Some(m.height.unwrap_or(0.0)) })
                .collect();
            out.push(LaneBoundary {
                id: id(line_id),
                boundary_line: line,
                classification: Some(lane_boundary::Classification { r#type: Some(boundary_type(m.kind) as i32), color: Some(color(m) as i32) }),
            });
        }
    }
}

/// The lanes and lane boundaries of `net`, numbered as esmini numbers them.
pub fn lanes_and_boundaries(net: &RoadNetwork, gids: &GlobalIds) -> (Vec<OsiLane>, Vec<LaneBoundary>) {
    let mut lanes = Vec::new();
    let mut boundaries = Vec::new();
    for (r, road) in net.roads.iter().enumerate() {
        let intersection = road.junction.as_deref().and_then(|j| net.junction(j)).is_some_and(|j| is_osi_intersection(net, j));
        for (j, sec) in road.lane_sections.iter().enumerate() {
            let mut all: Vec<&Lane> = sec.left.iter().chain(&sec.center).chain(&sec.right).collect();
            all.sort_by_key(|l| std::cmp::Reverse(l.id));
            for lane in &all {
                boundaries_of(road, (r, j, lane.id), lane, gids, &mut boundaries);
            }
            if intersection {
                continue;
            }
            for lane in all.iter().filter(|l| l.id != 0) {
                let lid = lane.id;
                let (kind, subtype) = lane_type(lane.kind);
                let along = !((lid >= 0 && road.rule == TrafficRule::RightHand) || (lid < 0 && road.rule == TrafficRule::LeftHand));
                let neighbour = |d: i32| [lid + d, lid + 2 * d].into_iter().find(|&n| is_osi_lane(sec, n)).map(|n| gids.lane((r, j, n)));
                let (own, inner) = (gids.outer_boundary((r, j, lid)), gids.outer_boundary((r, j, lid - lid.signum())));
                let (left_b, right_b) = if lid < 0 { (inner, own) } else { (own, inner) };
                lanes.push(OsiLane {
                    id: id(gids.lane((r, j, lid))),
                    classification: Some(lane::Classification {
                        r#type: Some(kind as i32),
                        subtype: Some(subtype as i32),
                        centerline: points(road, road.section_range(j).unwrap_or_default(), |s| road.lane_center_t(j, lid, s)).into_iter().flatten().collect(),
                        centerline_is_driving_direction: Some(along),
                        left_adjacent_lane_id: ids(neighbour(1)),
                        right_adjacent_lane_id: ids(neighbour(-1)),
                        left_lane_boundary_id: ids(left_b),
                        right_lane_boundary_id: ids(right_b),
                    }),
                    source_reference: vec![ExternalReference {
                        r#type: Some(SOURCE_ODR.into()),
                        identifier: vec![format!("road_id:{}", road.id), format!("road_s:{}", sec.s), format!("lane_id:{lid}")],
                    }],
                });
            }
        }
    }
    (lanes, boundaries)
}
