//! Positions of every type esmini 3.6.0 reads — Lane, Road, World, RelativeLane,
//! RelativeObject, RelativeRoad, RelativeWorld, Route (FromCurrentEntity, FromRoadCoordinates,
//! FromLaneCoordinates) and Trajectory — describing places computed from the map, with
//! optional lateral offsets and orientations (relative or absolute, facing either way).
//! (GeoPosition is left out: esmini 3.6.0 cannot read it and quits.) Each production names
//! its feature with the caller's prefix (`init:` for the Init, `position:` elsewhere) and
//! returns where it puts the entity, as far as the generator can tell.

use std::f64::consts::PI;

use super::lanes::{lanes_at, world, Place};
use super::{f3, Area, EntityKind, Gen};

/// What kinds of position a caller accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Scope {
    /// Lane, Road and World positions only (inside routes, trajectories, conditions).
    Plain,
    /// Also RoutePosition and TrajectoryPosition.
    Any,
}

impl Gen<'_> {
    /// An Orientation element, or nothing: mostly none; else relative (often turned by π:
    /// facing the other way) or absolute.
    fn orientation(&mut self, prefix: &str, facing_back: bool) -> (String, bool) {
        if facing_back {
            self.feature(format!("{prefix}orientation:relative-pi"));
            return (r#"<Orientation type="relative" h="3.1416"/>"#.into(), true);
        }
        if !self.rich(Area::Positions) || !self.chance(0.15) {
            return (String::new(), false);
        }
        if self.chance(0.5) {
            self.feature(format!("{prefix}orientation:relative"));
            // the file's text: half a turn is written as 3.1416, as authors do
            let h = self.pick(&["0", "3.1416", "0.2", "-0.3"]);
            let kind = self.orientation_type("relative", prefix);
            // (untyped before 1.3 it is absolute: not facing back)
            let back = h == "3.1416" && (!kind.is_empty() || self.rev_minor >= 3);
            (format!(r#"<Orientation{kind} h="{h}"/>"#), back)
        } else {
            self.feature(format!("{prefix}orientation:absolute"));
            let h = self.num(-PI, PI);
            let kind = self.orientation_type("absolute", prefix);
            (format!(r#"<Orientation{kind} h="{h}"/>"#), false)
        }
    }

    /// The ` type="…"` of an Orientation, or nothing at times: esmini then reads it as
    /// absolute before OpenSCENARIO 1.3 and as relative from 1.3 on.
    fn orientation_type(&mut self, kind: &str, prefix: &str) -> String {
        if self.chance(0.25) {
            self.feature(format!("{prefix}orientation:untyped/1.{}", self.rev_minor));
            return String::new();
        }
        format!(r#" type="{kind}""#)
    }

    /// A LanePosition of `place` with lateral `offset`.
    pub(crate) fn lane_position_xml(&self, place: &Place, offset: f64, orientation: &str) -> String {
        let id = self.road_id(place.road);
        if orientation.is_empty() {
            format!(r#"<LanePosition roadId="{id}" laneId="{}" offset="{offset}" s="{}"/>"#, place.lane, f3(place.s))
        } else {
            format!(r#"<LanePosition roadId="{id}" laneId="{}" offset="{offset}" s="{}">{orientation}</LanePosition>"#, place.lane, f3(place.s))
        }
    }

    /// A WorldPosition at `place` facing its direction of travel (turned by `dh`).
    pub(crate) fn world_position_xml(&self, place: &Place, offset: f64, dh: f64) -> Option<String> {
        let (x, y, h) = world(&self.map.net, place, offset)?;
        let (x, y, h) = self.map.scenario_xyh(x, y, h + dh);
        Some(format!(r#"<WorldPosition x="{}" y="{}" h="{}"/>"#, f3(x), f3(y), f3(normalize(h))))
    }

    /// A position describing `place` without reference to an entity. `facing_back`: the
    /// entity faces against its lane (a parked car or object turned round).
    pub(crate) fn place_position(&mut self, place: &Place, prefix: &str, scope: Scope, facing_back: bool) -> String {
        let mut kinds = vec!["LanePosition", "LanePosition", "RoadPosition", "WorldPosition"];
        if scope == Scope::Any && (self.rich(Area::Positions) || self.rich(Area::Routes)) {
            kinds.extend(["RoutePosition", "RoutePosition"]);
        }
        if scope == Scope::Any && (self.rich(Area::Positions) || self.rich(Area::Trajectories)) {
            kinds.push("TrajectoryPosition");
        }
        let kind = self.pick(&kinds);
        let offset = if self.rich(Area::Positions) && self.chance(0.2) { self.num(-0.8, 0.8) } else { 0.0 };
        if offset != 0.0 {
            self.feature(format!("{prefix}lateral-offset"));
        }
        let xml = match kind {
            "RoadPosition" => {
                let r = &self.map.net.roads[place.road];
                let t = r.lane_center_t(r.section_index_at(place.s), place.lane, place.s).unwrap_or(0.0) + offset;
                let (o, _) = self.orientation(prefix, facing_back);
                let id = self.road_id(place.road);
                if o.is_empty() {
                    format!(r#"<RoadPosition roadId="{id}" s="{}" t="{}"/>"#, f3(place.s), f3(t))
                } else {
                    format!(r#"<RoadPosition roadId="{id}" s="{}" t="{}">{o}</RoadPosition>"#, f3(place.s), f3(t))
                }
            }
            "WorldPosition" => {
                let dh = if facing_back { PI } else { 0.0 };
                match self.world_position_xml(place, offset, dh) {
                    Some(x) => x,
                    None => self.lane_position_xml(place, offset, ""),
                }
            }
            "RoutePosition" => return self.route_position_at(place, prefix),
            "TrajectoryPosition" => return self.trajectory_position_at(place, prefix),
            _ => {
                let (o, _) = self.orientation(prefix, facing_back);
                self.lane_position_xml(place, offset, &o)
            }
        };
        let kind = if xml.starts_with("<LanePosition") { "LanePosition" } else { kind };
        self.feature(format!("{prefix}{kind}"));
        xml
    }

    /// A position relative to entity `reference` (placed at `at`, if known) and where it puts
    /// the entity.
    pub(crate) fn relative_position(&mut self, reference: &str, at: Option<Place>, prefix: &str) -> (String, Option<Place>) {
        let rich = self.rich(Area::Positions);
        let kind = if rich {
            self.pick(&["RelativeLanePosition", "RelativeLanePosition", "RelativeObjectPosition", "RelativeRoadPosition", "RelativeWorldPosition"])
        } else {
            self.pick(&["RelativeLanePosition", "RelativeObjectPosition", "RelativeRoadPosition"])
        };
        self.feature(format!("{prefix}{kind}"));
        if let Some(r) = self.entity(reference) {
            if matches!(r.kind, EntityKind::Misc) || (r.vehicle() && r.speed == 0.0) {
                self.feature(format!("{prefix}relative-to-parked"));
            }
        }
        let ds = self.num(-40.0, 40.0);
        let mut place = at.map(|p| Place { s: if p.forward { p.s + ds } else { p.s - ds }, ..p });
        let xml = match kind {
            "RelativeLanePosition" => {
                let offset = if rich && self.chance(0.2) { self.num(-0.5, 0.5) } else { 0.0 };
                // ds along s, or (1.1+) dsLane along the lane's driving direction
                let along_lane = rich && self.chance(0.3);
                if let (Some(p), Some(a)) = (place.as_mut(), at) {
                    if !along_lane {
                        p.s = a.s + ds;
                    }
                }
                // a lane step that lands on a lane (esmini's Position::SetRelativePosition: the
                // step is counted along s, or with dsLane in the reference's direction of travel)
                let d_lane = match place {
                    Some(p) => {
                        let lanes = lanes_at(&self.map.net, p.road, p.s);
                        let target = |d: i32| relative_lane(p.lane, if along_lane && !p.forward { -d } else { d });
                        let fits: Vec<i32> = [-1, 0, 1].into_iter().filter(|d| *d == 0 || lanes.iter().any(|(l, _)| *l == target(*d))).collect();
                        let d = if self.chance(0.5) { 0 } else { fits[self.pick_index(fits.len())] };
                        if let (Some(pl), Some(&(l, f))) = (place.as_mut(), lanes.iter().find(|(l, _)| *l == target(d))) {
                            pl.lane = l;
                            pl.forward = f;
                        }
                        d
                    }
                    None => self.pick(&[-1, 0, 0, 1]),
                };
                if along_lane {
                    self.feature(format!("{prefix}RelativeLanePosition/dsLane"));
                    format!(r#"<RelativeLanePosition entityRef="{reference}" dLane="{d_lane}" dsLane="{ds}" offset="{offset}"/>"#)
                } else {
                    format!(r#"<RelativeLanePosition entityRef="{reference}" dLane="{d_lane}" ds="{ds}" offset="{offset}"/>"#)
                }
            }
            "RelativeObjectPosition" => {
                let dy = if rich { self.pick(&[-3.5, 0.0, 3.5, 1.8, -1.8]) } else { self.pick(&[-3.5, 0.0, 3.5]) };
                let (o, _) = self.orientation(prefix, false);
                place = self.locate_relative(reference, ds, dy).or(place);
                if o.is_empty() {
                    format!(r#"<RelativeObjectPosition entityRef="{reference}" dx="{ds}" dy="{dy}"/>"#)
                } else {
                    format!(r#"<RelativeObjectPosition entityRef="{reference}" dx="{ds}" dy="{dy}">{o}</RelativeObjectPosition>"#)
                }
            }
            "RelativeWorldPosition" => {
                let dy = self.num(-6.0, 6.0);
                place = None;
                format!(r#"<RelativeWorldPosition entityRef="{reference}" dx="{ds}" dy="{dy}"/>"#)
            }
            _ => {
                let dt = self.pick(&[-3.5, 0.0, 3.5]);
                if let Some(p) = place.as_mut() {
                    p.s = at.map_or(p.s, |a| a.s + ds);
                }
                format!(r#"<RelativeRoadPosition entityRef="{reference}" ds="{ds}" dt="{dt}"/>"#)
            }
        };
        if let Some(p) = place.as_mut() {
            let len = self.map.net.roads.get(p.road).map_or(0.0, |r| r.length);
            p.s = p.s.clamp(0.0, len);
        }
        (xml, place)
    }

    /// Where a point `dx` ahead and `dy` left of entity `reference` lies on the map.
    fn locate_relative(&self, reference: &str, dx: f64, dy: f64) -> Option<Place> {
        let at = self.entity(reference)?.place?;
        let (x, y, h) = world(&self.map.net, &at, 0.0)?;
        let (sin, cos) = h.sin_cos();
        let (px, py) = (x + dx * cos - dy * sin, y + dx * sin + dy * cos);
        let lp = self.map.net.world_to_lane(px, py, Some(at.road))?;
        let forward = lanes_at(&self.map.net, lp.road, lp.s).iter().find(|(l, _)| *l == lp.lane_id).map_or(at.forward, |(_, f)| *f);
        Some(Place { road: lp.road, lane: lp.lane_id, s: lp.s, forward })
    }

    /// A position for a target (teleport, acquire, a condition's point): a place ahead of
    /// entity `actor` along its lane graph, or one relative to an entity.
    pub(crate) fn target_position(&mut self, actor: &str, scope: Scope) -> String {
        let names = self.names();
        if self.rich(Area::Positions) && self.chance(0.25) && !names.is_empty() {
            let reference = names[self.pick_index(names.len())].clone();
            let at = self.entity(&reference).and_then(|e| e.place);
            return self.relative_position(&reference, at, "position:").0;
        }
        let place = self.place_ahead(actor, 20.0, 150.0);
        self.place_position(&place, "position:", scope, false)
    }

    /// A place `lo`..`hi` metres ahead of where entity `name` starts, along its lane graph.
    pub(crate) fn place_ahead(&mut self, name: &str, lo: f64, hi: f64) -> Place {
        let start = self.place_of(name);
        let d = self.num(lo, hi);
        let legs = super::lanes::walk(&self.map.net, start, d, &mut self.rng);
        super::lanes::along(&legs, d).unwrap_or(start)
    }
}

/// esmini's lane `lane_id` stepped by `offset` lanes, the centre lane skipped
/// (roadmanager::GetRelativeLaneId).
pub(super) fn relative_lane(lane_id: i32, offset: i32) -> i32 {
    let r = lane_id + offset;
    if lane_id == 0 || offset == 0 {
        r
    } else if r == 0 || r.signum() != lane_id.signum() {
        r + offset.signum()
    } else {
        r
    }
}

/// An angle in (-π, π].
pub(super) fn normalize(mut h: f64) -> f64 {
    while h > PI {
        h -= 2.0 * PI;
    }
    while h <= -PI {
        h += 2.0 * PI;
    }
    h
}
