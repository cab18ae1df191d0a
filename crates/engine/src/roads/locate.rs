//! World → lane for the engine's per-step questions, cheaper than a full network search:
//! an entity that moved a little is looked for first on the road it was on (starting the
//! projection at its last s); only when the point is not on that road does the spatial-index
//! search run. A point on the hinted road is what the full search returns too (it prefers the
//! hinted road among the roads containing the point), except at the road's end, where a
//! junction arm starting there takes it (`junction_arm_at_end`); past the end, a junction arm
//! containing the point wins over the other roads containing it (`entry_connector`). Exact repeats of full searches (fixed
//! target points of distance conditions) come from a small memo. On a banked road t is
//! measured along the tilted surface, as esmini's `Position::XYZ2TrackPos` measures it.

use super::banking::surface_t;
use opendrive::{LanePosition, RoadNetwork};
use std::cell::RefCell;

const MEMO_SIZE: usize = 32;

/// (network address, x bits, y bits, hint).
type Key = (usize, u64, u64, Option<usize>);

thread_local! {
    static MEMO: RefCell<Vec<(Key, Option<LanePosition>)>> = const { RefCell::new(Vec::new()) };
}

/// Nearest lane of (x, y); `hint`: the road, s and lane the caller was at (lane 0: unknown).
/// Without a hint the point is a fresh position's, asked at z = 0 (see [`world_to_lane_at`]).
pub(crate) fn world_to_lane(net: &RoadNetwork, x: f64, y: f64, hint: Option<(usize, f64, i32)>) -> Option<LanePosition> {
    world_to_lane_at(net, x, y, hint.is_none().then_some(0.0), hint.map(|(road, s, _)| (road, s)), hint)
}

/// [`world_to_lane`] for a point asked at height `z` (`None`: heights not weighed): esmini's
/// XYZ2TrackPos adds to a road's distance the height difference from its reference line
/// where it exceeds 2 m, so a point under a bridge takes the road below. A fresh Position
/// (nobody was at it: an Init's WorldPosition without z) asks at z = 0. The road preferred
/// (`hint`: road and s) may differ from the one the position was on (`current`: road, s and
/// lane; XYZ2TrackPos's current road), e.g. the road a move along the lane has led to.
pub(crate) fn world_to_lane_at(
    net: &RoadNetwork,
    x: f64,
    y: f64,
    z: Option<f64>,
    hint: Option<(usize, f64)>,
    current: Option<(usize, f64, i32)>,
) -> Option<LanePosition> {
    if hint.is_none() {
        if let Some(p) = fresh_point(net, x, y, z.unwrap_or(0.0)) {
            return Some(p);
        }
    }
    let mut hinted = None;
    if let Some((road, s)) = hint {
        if let Some(p) = net.locate_on_road_by(road, x, y, s, &surface_t) {
            if p.is_on_road() {
                if let Some(arm) = junction_arm_at_end(net, &p, current, x, y) {
                    return Some(arm);
                }
                return Some(offset_road_s(net, unshifted(net, p, x, y), x, y));
            }
            hinted = Some(p);
        }
    }
    if let Some((road, s, lane_id)) = current {
        let p = match hinted.filter(|p| p.road == road) {
            Some(p) => Some(p),
            None => net.locate_on_road_by(road, x, y, s, &surface_t),
        };
        if let Some(p) = p {
            if p.is_on_road() {
                return Some(offset_road_s(net, unshifted(net, p, x, y), x, y));
            }
            if let Some(held) = held_on_current(net, p, lane_id, x, y) {
                return Some(unshifted(net, held, x, y));
            }
        }
        // Off the current road: a road directly connected to it from its lane that contains
        // the point wins over any other containing it (XYZ2TrackPos replaces the best by a
        // directly connected road as close, by another road only when strictly closer), the
        // straightest at its contact point among them — so a point where a junction's
        // connecting roads overlap goes on the one going most straight on.
        if let Some(arm) = super::junction_entry::entry_connector(net, road, lane_id, x, y) {
            return Some(unshifted(net, arm, x, y));
        }
    }
    // Off the current road, roads containing the point alike: one directly connected to the
    // current road (from its lane) first, then the network's order (XYZ2TrackPos).
    // (The connected roads are listed only when a tie asks.)
    let connected = std::cell::OnceCell::new();
    let rank = |r: usize| {
        let connected = current.map(|(road, _, lane_id)| connected.get_or_init(|| super::junction_entry::directly_connected(net, road, lane_id)));
        u8::from(!connected.is_some_and(|c| c.contains(&r)))
    };
    let found = net.world_to_lane_ranked(x, y, z, hint.map(|h| h.0), &surface_t, current.is_some().then_some(&rank as &dyn Fn(usize) -> u8));
    match (hint, found) {
        (None, Some(lp)) => Some(on_chosen_segment(net, lp, x, y, z.unwrap_or(0.0)).unwrap_or(lp)),
        _ => found.map(|p| past_end_at_last_osi_point(net, offset_road_s(net, unshifted(net, p, x, y), x, y))),
    }
}

/// A point beyond the end of the road it is attached to: XYZ2TrackPos gives it the s of the
/// road's last OSI point (its "same point" case), which OpenDrive::SetLaneOSIPoints puts
/// `SMALL_NUMBER / 2` short of the end; the projection stops at the end itself. So of two
/// cars at a road's end, one driven past it (a ghost's follower, a trajectory) is that much
/// nearer than one stopped there by a move along s, and an ACC takes it as its lead. (Before
/// the start the first OSI point is the start: s 0 either way.)
fn past_end_at_last_osi_point(net: &RoadNetwork, lp: LanePosition) -> LanePosition {
    use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
    match net.roads.get(lp.road) {
        Some(road) if !lp.is_on_road() && lp.s >= road.length => LanePosition { s: road.length - SMALL_NUMBER / 2.0, ..lp },
        _ => lp,
    }
}

/// On a road with a lane offset, the s XYZ2TrackPos interpolates on lane 0's OSI segments
/// (lane 0 runs at the offset, tilted against the reference line, so a point beside it gets an
/// s shifted by about its distance from lane 0 times the offset's slope); elsewhere `lp`.
fn offset_road_s(net: &RoadNetwork, lp: LanePosition, x: f64, y: f64) -> LanePosition {
    let Some(road) = net.roads.get(lp.road) else { return lp };
    if !lane_offset_varies(road) {
        return lp;
    }
    on_chosen_segment(net, lp, x, y, road.elevation_at(lp.s)).unwrap_or(lp)
}

/// Whether the road's laneOffset changes along it (a linear or higher term): lane 0 then runs
/// tilted against the reference line.
fn lane_offset_varies(road: &opendrive::Road) -> bool {
    road.lane_offsets.iter().any(|o| o.b != 0.0 || o.c != 0.0 || o.d != 0.0)
}

/// How far from the end of its road a point is looked for on the junction arms starting
/// there: the arms begin at the end, so a point farther back lies before every arm's start.
const ARM_REACH: f64 = 1.0;

/// A point on the current road `p` (lane `current`'s) at its end, where junction arms start:
/// XYZ2TrackPos lets a road directly connected to the current one replace it when it contains
/// the point as closely (`weightedDist < closestPointDist + SMALL_NUMBER`; directly connected
/// roads carry no extra weight), and among such arms takes the one bending least at its
/// contact point, the later in the file at a tie (`junction_entry::entry_connector`). So an
/// entity placed exactly where the arms start (a trajectory ending at the road's end) is on
/// an arm already, which may not be the one the default controller would enter.
fn junction_arm_at_end(net: &RoadNetwork, p: &LanePosition, current: Option<(usize, f64, i32)>, x: f64, y: f64) -> Option<LanePosition> {
    let (road, _, lane_id) = current.filter(|c| c.0 == p.road)?;
    let length = net.roads.get(road)?.length;
    if p.s > ARM_REACH && p.s < length - ARM_REACH {
        return None;
    }
    super::junction_entry::entry_connector(net, road, lane_id, x, y)
}

/// Whether a point inside a real lane of `road` at `s` certainly stays on it in
/// [`world_to_lane_at`] with that road current: it is on the road, and no junction arm can take
/// it (they start at the ends, `junction_arm_at_end`; a centimetre spares rounding).
pub(crate) fn stays_on_its_road(net: &RoadNetwork, road: usize, s: f64) -> bool {
    net.roads.get(road).is_some_and(|r| s > ARM_REACH + 0.01 && s < r.length - ARM_REACH - 0.01)
}

/// XYZ2TrackPos: a point within the current road's s range and less than this beyond its
/// lanes is inside it (`insideCurrentRoad`, "2 meter lateral slack").
const CURRENT_ROAD_SLACK: f64 = 2.0;

/// Position::XYZ2TrackPos's hold on the current road: a point beside the current road `p`
/// (within its s range, less than 2 m beyond its outer lane border on that side) stays on it
/// unless a road directly connected to it from lane `lane_id` (Road::IsDirectlyConnected)
/// contains the point or lies nearer; any other road, even one containing the point, weighs 3 m
/// more (the penalty of roads not directly connected) and so loses, and so does a connected
/// road whose s range the point is beyond (3 m too). So an entity drifting a little off a
/// connecting road stays on it instead of moving onto a crossing one. `None` when the point is
/// not inside the current road (the plain search answers).
fn held_on_current(net: &RoadNetwork, p: LanePosition, lane_id: i32, x: f64, y: f64) -> Option<LanePosition> {
    // Inside the road's s range: the distance beyond the road's width on the point's side
    // (XYZ2TrackPos: the distance from lane 0's OSI segment less Road::GetWidth).
    let beyond = |q: &LanePosition| {
        let road = net.roads.get(q.road)?;
        if q.s <= 0.0 || q.s >= road.length {
            return None;
        }
        let t = q.t - road.lane_offset_at(q.s);
        Some((t.abs() - super::track_pos::width(road, q.s, t > 0.0)).max(0.0))
    };
    let d = beyond(&p).filter(|d| *d < CURRENT_ROAD_SLACK)?;
    let mut best = (p, d);
    for r in super::junction_entry::directly_connected(net, p.road, lane_id) {
        let Some(other) = net.roads.get(r) else { continue };
        let Some(q) = net.locate_on_road_by(r, x, y, 0.5 * other.length, &surface_t) else { continue };
        if let Some(dq) = beyond(&q).filter(|dq| *dq < best.1) {
            best = (q, dq);
        }
    }
    Some(best.0)
}

/// On a straight piece of a road both rolled and sloped: the s XYZ2TrackPos gives (x, y), that
/// of the point moved back along the heading by the shift Track2XYZ gives a point that far
/// across (`banking::along_shift`), so a lane position and its world point map onto each
/// other. Elsewhere `p` as it is.
fn unshifted(net: &RoadNetwork, p: LanePosition, x: f64, y: f64) -> LanePosition {
    let Some(road) = net.roads.get(p.road) else { return p };
    if road.superelevation.is_empty() {
        return p;
    }
    let pose = road.reference_pose(p.s);
    if pose.curvature != 0.0 {
        return p;
    }
    let (sin, cos) = pose.hdg.sin_cos();
    let along = super::banking::along_shift(road, p.s, -(x - pose.x) * sin + (y - pose.y) * cos);
    if along == 0.0 {
        return p;
    }
    net.locate_at_s_by(p.road, x, y, p.s - along, &surface_t).unwrap_or(p)
}

/// A point nobody was at (esmini's fresh Position: no current road) asked at height `z`: of
/// the roads near it, the one XYZ2TrackPos weighs nearest (`track_pos::segment_choice`: the
/// distance beyond the road's width from its nearest lane-0 OSI segment, plus 3 m where the
/// point lies beyond the road's ends and the height difference above 2 m; the first road in
/// the file at a tie), at the s it interpolates there. So an off-road point beside a road's
/// end takes the road going on from there, and a point under a bridge the road below.
fn fresh_point(net: &RoadNetwork, x: f64, y: f64, z: f64) -> Option<LanePosition> {
    let mut best: Option<(usize, f64, f64)> = None;
    for r in net.roads_near(x, y) {
        let Some(road) = net.roads.get(r) else { continue };
        let Some((s, w)) = super::track_pos::segment_choice(road, x, y, z) else { continue };
        if best.is_none_or(|(_, _, bw)| w < bw) {
            best = Some((r, s, w));
        }
    }
    let (r, s, _) = best?;
    net.locate_at_s_by(r, x, y, s, &surface_t)
}

/// A point nobody was at (esmini's fresh Position: no current road, z asked at 0) takes the s
/// XYZ2TrackPos interpolates on the lane-0 OSI segment it weighs nearest
/// (`track_pos::segment_s`), on the road as off it: where a segment spans a change of
/// curvature that s is not the exact projection's (ref_point.xodr past its bend: 5 cm on the
/// road, 1-2 m off it), and on a road climbing more than 2 m the z penalty can pick a segment
/// far from it. `None` where the road has no segment (the exact projection stands).
fn on_chosen_segment(net: &RoadNetwork, lp: LanePosition, x: f64, y: f64, z: f64) -> Option<LanePosition> {
    let road = net.roads.get(lp.road)?;
    let s = super::track_pos::segment_s(road, x, y, z)?;
    net.locate_at_s_by(lp.road, x, y, s, &surface_t)
}

/// The s XYZ2TrackPos interpolates for (x, y) on the lane-0 OSI segment of `road` holding
/// `s_near`, the point's exact projection ([`super::track_pos::segment_s_near`]). `None` inside
/// a line geometry (a metre or more from its ends) of a road without a varying lane offset,
/// where that s is the exact projection's: lane 0's vertices there share one heading and
/// XYZ2TrackPos projects on their line.
pub(crate) fn segment_s_near(net: &RoadNetwork, road: usize, x: f64, y: f64, s_near: f64) -> Option<f64> {
    let r = net.roads.get(road)?;
    if let Some(g) = r.geometries.get(r.geometry_index_at(s_near)) {
        if !lane_offset_varies(r) && matches!(g.shape, opendrive::Shape::Line) && s_near - g.s >= 1.0 && g.s + g.length - s_near >= 1.0 {
            return None;
        }
    }
    super::track_pos::segment_s_near(r, x, y, s_near)
}

/// [`world_to_lane`] from a current road, at the s XYZ2TrackPos interpolates on the lane-0 OSI
/// segment of the road found (asked at height `z`): for a jump, where the point may lie far off
/// the road and the segment's s then differs from the exact projection's by metres.
pub(crate) fn world_to_lane_on_segment(net: &RoadNetwork, x: f64, y: f64, z: f64, current: (usize, f64, i32)) -> Option<LanePosition> {
    let lp = world_to_lane(net, x, y, Some(current))?;
    Some(on_chosen_segment(net, lp, x, y, z).unwrap_or(lp))
}

/// A point measured to as esmini's Position::Distance maps it, by a fresh Position (no current
/// road): the hinted road when the point lies on it (a shortcut, see `conditions::distance::
/// to_point`), else the memoised full search without a current road, so that roads the point
/// lies on equally (the connecting roads crossing a junction's centre) go to the first road, as
/// XYZ2TrackPos keeps it, not to the one whose lane centre is a rounding nearer.
pub(crate) fn world_to_lane_fresh(net: &RoadNetwork, x: f64, y: f64, hint: Option<(usize, f64)>) -> Option<LanePosition> {
    if let Some((road, s)) = hint {
        if let Some(p) = net.locate_on_road_by(road, x, y, s, &surface_t) {
            if p.is_on_road() {
                return Some(unshifted(net, p, x, y));
            }
        }
    }
    world_to_lane_memo(net, x, y, None)
}

/// [`world_to_lane`] for points that are asked about again and again (fixed positions): the
/// hinted road first, then a memo of full searches.
pub(crate) fn world_to_lane_memo(net: &RoadNetwork, x: f64, y: f64, hint: Option<(usize, f64)>) -> Option<LanePosition> {
    if let Some((road, s)) = hint {
        if let Some(p) = net.locate_on_road_by(road, x, y, s, &surface_t) {
            if p.is_on_road() {
                return Some(unshifted(net, p, x, y));
            }
        }
    }
    let k: Key = (net as *const RoadNetwork as usize, x.to_bits(), y.to_bits(), hint.map(|h| h.0));
    if let Some(hit) = MEMO.with(|m| m.borrow().iter().find(|e| e.0 == k).map(|e| e.1)) {
        return hit;
    }
    let r = net.world_to_lane_at_height(x, y, hint.is_none().then_some(0.0), hint.map(|h| h.0), &surface_t).map(|p| unshifted(net, p, x, y));
    MEMO.with(|m| {
        let mut m = m.borrow_mut();
        if m.len() >= MEMO_SIZE {
            m.remove(0);
        }
        m.push((k, r));
    });
    r
}

/// One run's entries (`crate::run_memos`).
pub(crate) struct Store(Vec<(Key, Option<LanePosition>)>);

impl Store {
    /// No entries.
    pub(crate) fn new() -> Store {
        Store(Vec::new())
    }

    /// Exchange these entries with the thread's.
    pub(crate) fn swap_with_thread(&mut self) {
        MEMO.with(|m| std::mem::swap(&mut *m.borrow_mut(), &mut self.0));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two roads: a paramPoly3 arc-ish road 0 (100 m) linked to a straight road 1 along +x.
    fn net() -> RoadNetwork {
        let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="0" length="100" junction="-1"><link><successor elementType="road" elementId="1" contactPoint="start"/></link>
<planView><geometry s="0" x="0" y="0" hdg="0" length="100"><paramPoly3 aU="0" bU="100" cU="0" dU="0" aV="0" bV="0" cV="5" dV="-2" pRange="normalized"/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
<road id="1" length="100" junction="-1"><link><predecessor elementType="road" elementId="0" contactPoint="end"/></link>
<planView><geometry s="0" x="100" y="300" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
</OpenDRIVE>"#;
        opendrive::parse_str(xodr, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn hinted_lookup_agrees_with_the_full_search_on_the_road() {
        let n = net();
        for k in 0..40 {
            let s = 1.0 + 2.4 * k as f64;
            let Some(p) = n.roads.first().map(|r| r.reference_pose(s)) else { panic!("road 0") };
            // 1.75 m to the right of the reference line: lane -1's centre.
            let (x, y) = (p.x + 1.75 * p.hdg.sin(), p.y - 1.75 * p.hdg.cos());
            let full = n.world_to_lane(x, y, Some(0)).unwrap_or_else(|| panic!("full search"));
            let fast = world_to_lane(&n, x, y, Some((0, (s - 3.0).max(0.0), 0))).unwrap_or_else(|| panic!("fast"));
            assert_eq!((full.road, full.lane_id), (fast.road, fast.lane_id));
            assert!((full.s - s).abs() < 1e-6 && (fast.s - s).abs() < 1e-6, "{} {} {s}", full.s, fast.s);
            assert!((fast.offset - full.offset).abs() < 1e-9 && fast.offset.abs() < 1e-6);
        }
    }

    #[test]
    fn off_the_hinted_road_the_full_search_answers() {
        let n = net();
        // A point on road 1, hinted with road 0: found on road 1 all the same.
        let p = world_to_lane(&n, 150.0, 298.25, Some((0, 50.0, 0))).unwrap_or_else(|| panic!("found"));
        assert_eq!((p.road, p.lane_id), (1, -1));
        assert!((p.s - 50.0).abs() < 1e-9);
        // Asked twice, the memo answers the same.
        let a = world_to_lane_memo(&n, 150.0, 298.25, Some((0, 50.0)));
        let b = world_to_lane_memo(&n, 150.0, 298.25, Some((0, 50.0)));
        assert_eq!(a, b);
        assert_eq!(a.map(|p| p.road), Some(1));
    }

    #[test]
    fn memoized_reference_poses_are_bit_identical() {
        let n = net();
        let Some(road) = n.roads.first() else { panic!("road 0") };
        super::super::pose_memo::clear();
        for k in 0..600 {
            let s = (k % 300) as f64 * 0.33;
            assert_eq!(super::super::pose_memo::reference_pose(road, s), road.reference_pose(s));
        }
    }

    #[test]
    fn bounded_road_distance_matches_the_unbounded_one() {
        use super::super::road_distance::{road_distance, road_distance_within};
        let n = net();
        // From road 0 at s = 40 to road 1 at s = 30: 60 + 30 m.
        assert_eq!(road_distance(&n, 0, 40.0, 1, 30.0), Some(90.0));
        assert_eq!(road_distance_within(&n, 0, 40.0, 1, 30.0, 100.0), Some(90.0));
        assert_eq!(road_distance_within(&n, 0, 40.0, 1, 30.0, 50.0), None);
    }
}
