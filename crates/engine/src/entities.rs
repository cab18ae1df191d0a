//! The engine's entities: each scenario entity's dimensions and performance, and its state
//! (pose, speed, attachment to the road network, timers for the state conditions).

use crate::angles::wrap;
use crate::angles::wrap_2pi;
use crate::roads::lane_position::LanePos;
use opendrive::RoadNetwork;
use openscenario::{EntityObject, Scenario};

/// What kind of object an entity is (for CollisionCondition by type).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EntityKind {
    Vehicle,
    Pedestrian,
    Misc,
    External,
}

/// One entity during a run.
#[derive(Debug, Clone)]
pub(crate) struct Entity {
    pub name: String,
    pub kind: EntityKind,
    /// Bounding box: centre (x, y, z) relative to the reference point, length, width, height.
    pub bbox: [f64; 6],
    pub max_speed: f64,
    pub max_acc: f64,
    pub max_dec: f64,
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub h: f64,
    pub speed: f64,
    pub accel: f64,
    pub yaw_rate: f64,
    /// World velocity of the last step (for relative speeds).
    pub vel: (f64, f64),
    /// World acceleration of the last step: the change of `vel` over it (esmini's object
    /// acceleration, ScenarioEngine::prepareGroundTruth; AccelerationConditions read it).
    pub acc_vec: (f64, f64),
    /// Vertical velocity and acceleration of the last step: the change of `z`, and of that
    /// rate, over it (esmini's velZ_ / accZ_; a teleport's velocity has none). The vertical
    /// Speed-, RelativeSpeed- and AccelerationConditions read them.
    pub vel_z: f64,
    pub acc_z: f64,
    /// Nearest lane (also when off the road), `None` without a road network.
    pub lane: Option<LanePos>,
    /// Whether the reference point lies on a lane.
    pub on_road: bool,
    /// Heading relative to the driving direction it faces (lane changes tilt it).
    pub yaw_offset: f64,
    pub visible: bool,
    pub odometer: f64,
    /// Set when an action moved the entity along the road this step (the default controller
    /// then leaves it alone).
    pub moved_by_action: bool,
    /// Something set the speed this step: a longitudinal action or the default controller
    /// (esmini's `DirtyBit::SPEED`); without it a standing entity's speed is derived from its
    /// displacement (`motion.rs`).
    pub speed_set: bool,
    /// The last move ended at a road end with no continuation (position status).
    pub at_road_end: bool,
    /// The status a controller's placement found (`place_driven`), taken into `at_road_end`
    /// at the next step's end-of-road test: esmini makes that test before it steps the
    /// controllers, so it reads the placement of the step before.
    pub road_end_after_controller: Option<bool>,
    /// Put where esmini leaves a position it could not set (a RoutePosition FromCurrentEntity,
    /// or a road-relative position from such an entity): at the origin without a road, where
    /// its default controller cannot move it (motion.rs).
    pub roadless: bool,
    /// The EndOfRoad state conditions see (updated from `at_road_end` after each step).
    pub end_of_road: bool,
    pub end_of_road_since: f64,
    pub offroad_since: Option<f64>,
    pub standstill_since: Option<f64>,
    /// A controller was activated on it (recorded; behaviour is part 2).
    pub controller_active: bool,
    /// Which OverrideControllerValueAction values are active, in esmini's `OverrideType`
    /// order (`actions/override_controller.rs`): releasing one restarts a ghost.
    pub overrides_active: [bool; crate::actions::override_controller::state::OVERRIDE_KINDS],
    /// Driven from outside now under esmini's override rule (external/): the default
    /// controller and the storyboard's motion actions leave it to the outside.
    pub outside: bool,
    /// The entity exists (AddEntityAction / DeleteEntityAction toggle this; `actions/add_delete_entity.rs`).
    pub active: bool,
    /// Added (put in place) during this step: the next `after_move` derives no velocity, yaw
    /// rate or odometer from the jump.
    pub appeared: bool,
    /// Teleported during this step: the jump is not travel (esmini's `DirtyBit::TELEPORT`
    /// skips the odometer and takes the velocity from speed and heading).
    pub teleported: bool,
    /// esmini's last write of the position's orientation was absolute (SetInertiaPos,
    /// SetHeading: EvaluateHPR with H_ABS, turned from the road by GetAngleDifference, in
    /// [-π, π]); false after a move along the lane (SetLanePos: H_REL, the relative heading
    /// held in [0, 2π)). Decides Object::pos_.GetH()'s bits at exactly ±π from the road.
    pub heading_abs: bool,
    /// The end-of-road status an action's placement by a world point left this step
    /// (XYZ2TrackPos sets POS_STATUS_END_OF_ROAD anew), for the ACC's stop at a road's end.
    pub placed_end_status: Option<bool>,
    /// (road, lane, section start, section end) where the entity's lane is known to run
    /// parallel to the reference line: no heading drift to compute while it stays there.
    pub parallel_lane: Option<(usize, i32, f64, f64)>,
    /// The route assigned by AssignRouteAction / AcquirePositionAction: junction choices follow it.
    pub route: Option<std::sync::Arc<routing::Route>>,
    /// esmini's Route::ReplaceMinimalWaypoints found the route's first waypoint not directly
    /// linked to the second (CalculcateWPDirWrtWP leaves its direction 0): every move along
    /// the route fails ("Unexpected lack of connection in route"), so the default controller
    /// stops the entity where it is (ScenarioEngine::defaultController, SetSpeed(0)).
    pub route_broken: bool,
    /// The attitude its last placement by world pose found on a sloped or banked road
    /// (`place_world`), and the pose it was found for; see [`Entity::placed_pitch_roll`].
    pub placed_attitude: Option<PlacedAttitude>,
}

/// Pitch and roll esmini's Position::EvaluateHPR gave a position set from world coordinates,
/// kept with the pose (x, y, heading) it was computed for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlacedAttitude {
    pub pose: (f64, f64, f64),
    pub pitch: f64,
    pub roll: f64,
}

/// (longitudinal, lateral) parts of a world vector in a frame turned by `h` (esmini's
/// RotateVec2D by −h, as in Position::GetVelLong / GetVelLat / GetAccLong).
pub(crate) fn in_frame((vx, vy): (f64, f64), h: f64) -> (f64, f64) {
    let (sin, cos) = h.sin_cos();
    (vx * cos + vy * sin, -vx * sin + vy * cos)
}

impl Entity {
    /// The acceleration vector's component along the heading (esmini's Position::GetAccLong):
    /// a car turning at constant speed has one, its speed's rate has none.
    pub(crate) fn acc_long(&self) -> f64 {
        in_frame(self.acc_vec, self.h).0
    }

    /// The end-of-road status a position set from world coordinates takes (Position::
    /// SetInertiaPos → XYZ2TrackPos sets it afresh): a point beyond its road's end has it, and so
    /// does a point on an end without a link element (XYZ2TrackPos ends with
    /// SetLongitudinalTrackPos, which flags s within SMALL_NUMBER of such an end).
    /// A teleport, which copies the location only, keeps the status it had instead.
    pub(crate) fn set_end_status_from_world(&mut self, net: &RoadNetwork) {
        if let Some(status) = self.end_status_from_world(net) {
            self.at_road_end = status;
        }
    }

    /// That status, for the entity's position as it is now; None off every road.
    pub(crate) fn end_status_from_world(&self, net: &RoadNetwork) -> Option<bool> {
        self.lane
            .map(|lp| crate::roads::past_end::past_road_end(net, lp.road, lp.s, self.x, self.y) || crate::roads::past_end::unlinked_end_at(net, lp.road, lp.s))
    }

    /// esmini's ScenarioEngine::step, after every object's (default) move: an object whose
    /// position status says end of road (`at_road_end`), already flagged there in an earlier
    /// step (`end_of_road`), and whose velocity, measured at the last step, is zero is stopped
    /// ("object at end of road and not moving, enforce zero speed"). Not moving is NEAR_ZERO:
    /// below SMALL_NUMBER (1e-6 m/s), so the rounding left by the move onto the end counts.
    pub(crate) fn stop_if_stuck_at_road_end(&mut self) {
        if self.at_road_end && self.end_of_road && self.standing_still() {
            // Object::SetSpeed marks the speed as applied: it is not measured from the motion.
            self.speed = 0.0;
            self.speed_set = true;
        }
    }

    /// esmini's NEAR_ZERO of the velocity x and y (ScenarioEngine::step's end-of-road rule): the
    /// whole last step's motion, an action's included.
    pub(crate) fn standing_still(&self) -> bool {
        use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL;
        self.vel.0.abs() < SMALL && self.vel.1.abs() < SMALL
    }

    pub(crate) fn from_scenario(scenario: &Scenario) -> Vec<Entity> {
        scenario.entities.iter().map(Entity::from_model).collect()
    }

    /// The run state of one scenario entity, at rest at the origin.
    pub(crate) fn from_model(e: &openscenario::Entity) -> Entity {
        let (kind, perf) = match &e.object {
            EntityObject::Vehicle(v) => (EntityKind::Vehicle, Some(v.performance)),
            EntityObject::Pedestrian(_) => (EntityKind::Pedestrian, None),
            EntityObject::MiscObject(_) => (EntityKind::Misc, None),
            EntityObject::External { .. } => (EntityKind::External, None),
        };
        let bbox = e.object.bounding_box().map_or([0.0; 6], |b| [b.center.x, b.center.y, b.center.z, b.length, b.width, b.height]);
        let big = 1e10;
        Entity {
            name: e.name.clone(),
            kind,
            bbox,
            max_speed: perf.map_or(big, |p| p.max_speed),
            max_acc: perf.map_or(big, |p| p.max_acceleration),
            max_dec: perf.map_or(big, |p| p.max_deceleration),
            x: 0.0,
            y: 0.0,
            z: 0.0,
            h: 0.0,
            speed: 0.0,
            accel: 0.0,
            yaw_rate: 0.0,
            vel: (0.0, 0.0),
            acc_vec: (0.0, 0.0),
            vel_z: 0.0,
            acc_z: 0.0,
            lane: None,
            on_road: false,
            yaw_offset: 0.0,
            visible: true,
            odometer: 0.0,
            moved_by_action: false,
            speed_set: false,
            at_road_end: false,
            road_end_after_controller: None,
            roadless: false,
            end_of_road: false,
            end_of_road_since: 0.0,
            offroad_since: None,
            standstill_since: None,
            controller_active: false,
            overrides_active: [false; crate::actions::override_controller::state::OVERRIDE_KINDS],
            outside: false,
            active: true,
            appeared: false,
            teleported: false,
            heading_abs: false,
            placed_end_status: None,
            parallel_lane: None,
            route: None,
            route_broken: false,
            placed_attitude: None,
        }
    }

    /// The pitch and roll the entity's position holds while it stands where its last placement
    /// by world pose put it. esmini's EvaluateHPR composes the road's rotation with the pitch
    /// GetPOffset reads from the relative heading the position held *before*: 0 for a position
    /// made afresh (a scenario's WorldPosition), so an entity placed facing against the road is
    /// pitched the other way until its first move along the lane composes it again with the
    /// heading it now holds (`attitude::surface_pitch_roll`). `None` once it moved or turned.
    pub(crate) fn placed_pitch_roll(&self) -> Option<(f64, f64)> {
        self.placed_attitude.filter(|a| a.pose == (self.x, self.y, self.h)).map(|a| (a.pitch, a.roll))
    }

    /// Place the entity on a lane position, heading along the direction it faces plus `yaw_offset`.
    pub(crate) fn set_lane_pos(&mut self, net: &RoadNetwork, lp: LanePos) {
        self.lane = Some(lp);
        self.heading_abs = false;
        if let Some(p) = lp.pose(net) {
            self.x = p.x;
            self.y = p.y;
            self.z = p.z;
            self.h = self.heading_on(net, &lp, &p);
            self.on_road = inside_real_lane(net, &lp, &p) || self.lane_contains(net, &lp, p.t);
        }
    }

    /// Gives the entity `route` (or none) in place of the one it had: a new route is not broken
    /// (`route_broken` belongs to the route it replaces).
    pub(crate) fn set_route(&mut self, route: Option<std::sync::Arc<routing::Route>>) {
        self.route = route;
        self.route_broken = false;
    }

    /// esmini's SetHeadingRelativeRoadDirection(0) (LatLaneChangeAction::Start's "align to
    /// road"): no turn from the direction the entity faces along its lane, the heading evaluated
    /// at once. Whether there was a lane pose to evaluate it on.
    pub(crate) fn align_with_lane(&mut self, net: &RoadNetwork) -> bool {
        self.yaw_offset = 0.0;
        let Some(lp) = self.lane else { return false };
        let Some(pose) = lp.pose(net) else { return false };
        self.h = self.heading_on(net, &lp, &pose);
        true
    }

    /// The heading on lane position `lp` (at pose `p`): the direction it faces plus
    /// `yaw_offset`, plus the lane's drift (along a lane that widens or narrows the path drifts
    /// sideways; esmini's heading follows it).
    pub(crate) fn heading_on(&mut self, net: &RoadNetwork, lp: &LanePos, p: &crate::roads::lane_position::LanePose) -> f64 {
        let known_parallel = self.parallel_lane.is_some_and(|(r, l, a, b)| r == lp.road && l == lp.lane_id && lp.s >= a && lp.s < b);
        let drift = if known_parallel { 0.0 } else { self.drift(net, lp) };
        wrap_2pi(lp.facing_heading(p) + self.yaw_offset + drift)
    }

    /// Turn the entity to the absolute heading `h` as esmini's Position::SetHeading does
    /// (EvaluateHPR with H_ABS): the angle to the road (h_relative, less the lane's drift) is
    /// what later moves along the lane keep, and they go the way it faces (MoveAlongS's
    /// HEADING_DIRECTION: IsAngleForward of that angle).
    ///
    /// On a lane the heading goes through esmini's matrices: the heading held is the road's
    /// rotation composed with the turn from it (R0R12EulerAngles), and the angle to the road is
    /// found back from it (CalcRelAnglesFromRoadAndAbsAngles against the road's heading plus
    /// the lane's drift, GetHOffset); both guard their cosines against gimbal lock, so a
    /// heading at a right angle to the road comes out a micro-radian to one side, and that
    /// side decides which way the entity then drives (IsAngleForward: backward only strictly
    /// between π/2 and 3π/2).
    pub(crate) fn set_heading_on_lane(&mut self, net: &RoadNetwork, h: f64) {
        self.h = wrap_2pi(h);
        self.heading_abs = true;
        let Some(mut lp) = self.lane else { return };
        let Some(p) = lp.pose(net) else { return };
        let drift = self.drift(net, &lp);
        // The road's heading as esmini's geometry gives it: the file's hdg in [0, 2π) (Geometry::
        // GetHdg; a road along +x written with hdg 2π has heading 0, whose sine is exactly 0).
        let h_road = wrap_2pi(p.road_heading);
        self.h = esmini_euler_heading(h_road, crate::angles::angle_difference(h, h_road));
        // esmini's h_relative_ is taken from GetHRoad() (the reference line's heading, no turn
        // from a changing superelevation) plus GetHOffset.
        let h_ref = lp.reference_heading(net).map_or(h_road, wrap_2pi);
        let [h_rel, _, _] = crate::attitude::relative([h_ref + drift, 0.0, 0.0], [self.h, 0.0, 0.0]);
        let (quarter, three_quarters) = (std::f64::consts::FRAC_PI_2, 3.0 * std::f64::consts::FRAC_PI_2);
        lp.dir = if h_rel > quarter && h_rel < three_quarters { -1.0 } else { 1.0 };
        self.yaw_offset = wrap(self.h - drift - lp.facing_heading(&p));
        self.lane = Some(lp);
    }

    /// The heading drift on lane position `lp` (see `lane_slope`); remembers a section where the
    /// lane runs parallel, so that the next steps there skip the question.
    pub(crate) fn drift(&mut self, net: &RoadNetwork, lp: &LanePos) -> f64 {
        let Some(road) = net.roads.get(lp.road) else { return 0.0 };
        let section = road.section_index_at(lp.s);
        if crate::roads::lane_shape::lane_shape(road, section, lp.lane_id).parallel {
            self.parallel_lane = road.section_range(section).map(|(a, b)| (lp.road, lp.lane_id, a, b));
            return 0.0;
        }
        crate::roads::lane_slope::drift_angle(road, section, lp.lane_id, lp.s)
    }

    /// Place the entity at a world pose; attach it to the nearest lane (`hint`: road preferred)
    /// of the types esmini snaps the entity's own position to (a pedestrian's include sidewalks).
    pub(crate) fn set_world(&mut self, net: Option<&RoadNetwork>, x: f64, y: f64, z: Option<f64>, h: f64) {
        let sidewalks = self.kind == EntityKind::Pedestrian;
        // The entity's own position: GetPOffset reads the heading from the road it held.
        let prior_h_rel = self.lane.map_or(0.0, |l| self.yaw_offset + if l.dir < 0.0 { std::f64::consts::PI } else { 0.0 });
        let current = self.lane;
        self.place_world(net, x, y, z, h, sidewalks, prior_h_rel, current);
    }

    /// [`Entity::set_world`] where the entity's lane (preferred) is not where its position was
    /// (`current`, XYZ2TrackPos's current road): the looming controller moves its lane along
    /// the road before placing it.
    pub(crate) fn set_world_from(&mut self, net: Option<&RoadNetwork>, x: f64, y: f64, h: f64, current: Option<LanePos>) {
        let sidewalks = self.kind == EntityKind::Pedestrian;
        let prior_h_rel = self.lane.map_or(0.0, |l| self.yaw_offset + if l.dir < 0.0 { std::f64::consts::PI } else { 0.0 });
        self.place_world(net, x, y, None, h, sidewalks, prior_h_rel, current);
    }

    /// Where esmini leaves an entity whose position it could not set: the origin, heading 0,
    /// on no road (`roadless`). Its first move from there already fails at the road's end
    /// (frame 0 for the Init), so the next step stops it (motion.rs).
    pub(crate) fn place_nowhere(&mut self) {
        (self.x, self.y, self.z, self.h) = (0.0, 0.0, 0.0, 0.0);
        self.lane = None;
        self.on_road = false;
        self.roadless = true;
        self.at_road_end = true;
        self.moved_by_action = true;
        self.teleported = true;
    }

    /// [`Entity::set_world`] with the lane types given: a teleport copies the location of a
    /// position of its own, which snaps to driving lanes only, whatever the entity (esmini's
    /// TeleportAction: Position::CopyLocation).
    pub(crate) fn set_world_snapping(&mut self, net: Option<&RoadNetwork>, x: f64, y: f64, z: Option<f64>, h: f64, sidewalks: bool) {
        // The teleport's position was made afresh (relative heading 0 for GetPOffset; no
        // current road for XYZ2TrackPos to hold, nor one to prefer: the entity's own road is
        // not asked first).
        self.lane = None;
        self.place_world(net, x, y, z, h, sidewalks, 0.0, None);
    }

    /// Place the entity at a world pose facing `h` (esmini's Position::SetInertiaPosMode with
    /// an absolute heading): where the road is sloped or banked, the heading esmini's position
    /// then holds is the road's rotation composed with the turn from it (EvaluateHPR, see
    /// `attitude::on_road`: on a banked road GetPOffset's pitch turns it), which a
    /// RelativeObjectPosition or a trajectory starting there takes; the turn from the lane
    /// (what moving along it keeps) is the plain difference; beyond the road's end the road
    /// is taken as level. `prior_h_rel`: the heading from the road the position held before;
    /// `current`: the lane it was on (XYZ2TrackPos's current road).
    #[allow(clippy::too_many_arguments)]
    fn place_world(&mut self, net: Option<&RoadNetwork>, x: f64, y: f64, z: Option<f64>, h: f64, sidewalks: bool, prior_h_rel: f64, current: Option<LanePos>) {
        self.heading_abs = true;
        self.x = x;
        self.y = y;
        self.h = wrap_2pi(h);
        self.placed_attitude = None;
        let Some(net) = net else {
            self.z = z.unwrap_or(0.0);
            self.lane = None;
            self.on_road = false;
            return;
        };
        let hint = self.lane.map(|l| (l.road, l.s));
        // A fresh position (no road yet) is asked at its z, 0 when not given (XYZ2TrackPos).
        let z_asked = if hint.is_none() { Some(z.unwrap_or(0.0)) } else { z };
        match crate::roads::locate::world_to_lane_at(net, x, y, z_asked, hint, current.map(|l| (l.road, l.s, l.lane_id))) {
            Some(lp) => {
                // esmini's IsAngleForward of the heading its position holds (a heading within a
                // micro-radian of ±π/2 is 1e-6 off, `esmini_reported_heading`): against the
                // road only beyond a right angle, so a car facing +y put across a road along +x
                // by a heading rounded a hair past π/2 drives against s. An exact right angle
                // is forward; 1e-9 absorbs the last bits in which our road heading may differ
                // from esmini's (h 0 across a road along −y drives along it, as in esmini).
                let rel = wrap(esmini_reported_heading(h) - lp.heading);
                let dir = if rel.abs() <= std::f64::consts::FRAC_PI_2 + 1e-9 { 1.0 } else { -1.0 };
                // esmini attaches the entity to the nearest lane of the types it snaps to
                // (LaneSection::GetClosestLaneIdx), measuring the offset from that lane's centre.
                let (lane_id, offset) = crate::roads::lane_snap::snap_located(net, &lp, sidewalks);
                let l = LanePos { road: lp.road, lane_id, s: lp.s, offset, dir };
                self.lane = Some(l);
                // A position set from world coordinates (Position::XYZ2TrackPos) has a road
                // again: an entity left nowhere (`place_nowhere`) that an action put back on
                // the map (e.g. a ghost's trajectory) drives on from there.
                self.roadless = false;
                // esmini's Position::IsOffRoad looks across the road only: a point past the
                // road's end (XYZ2TrackPos: s at the end, t across the heading there) within
                // the road's width is on the road
                self.on_road = net.roads.get(lp.road).is_some_and(|r| !crate::roads::offroad::is_off_road(r, lp.s, lp.t));
                // The heading relative to the lane leaves out the lane's drift (esmini's
                // EvaluateHPR: h_relative = h − h_road − h_offset), which moving adds back.
                let drift = self.drift(net, &l);
                self.yaw_offset = wrap(h - drift - if dir < 0.0 { lp.heading + std::f64::consts::PI } else { lp.heading });
                // Beyond the road's end XYZ2TrackPos leaves the road's pitch and roll at 0.
                let past_end = crate::roads::past_end::past_road_end(net, lp.road, lp.s, x, y);
                let tilted =
                    net.roads.get(lp.road).filter(|_| !past_end).and_then(|r| crate::attitude::on_road(r, lp.s, lp.t, wrap(h - lp.heading), prior_h_rel));
                if let Some([h3, pitch, roll]) = tilted {
                    self.h = h3;
                    self.placed_attitude = Some(PlacedAttitude { pose: (x, y, h3), pitch, roll });
                }
                // the road's surface there, its banking and the lane's own height included (the
                // height a move along the lane then keeps: a step's vertical speed reads the
                // difference)
                self.z = z.unwrap_or_else(|| {
                    net.roads.get(lp.road).map_or(0.0, |r| {
                        let raised = crate::roads::pose_memo::lane_borders_at(r, lane_id, lp.s)
                            .and_then(|b| crate::roads::lane_height::lift(r, lp.s, lane_id, offset, b))
                            .map_or(0.0, |lift| lift.1);
                        r.elevation_at(lp.s) + crate::roads::banking::banked(r, lp.s, lp.t, 0.0).1 + raised
                    })
                });
            }
            None => {
                self.lane = None;
                self.on_road = false;
                self.z = z.unwrap_or(0.0);
            }
        }
    }

    fn lane_contains(&self, net: &RoadNetwork, lp: &LanePos, t: f64) -> bool {
        let Some(road) = net.roads.get(lp.road) else { return false };
        !crate::roads::offroad::is_off_road(road, lp.s, t)
    }

    /// Bounding-box centre in world coordinates.
    pub(crate) fn box_center(&self) -> (f64, f64) {
        let (s, c) = self.h.sin_cos();
        (self.x + self.bbox[0] * c - self.bbox[1] * s, self.y + self.bbox[0] * s + self.bbox[1] * c)
    }
}

/// Cheap sufficient test for being on the road (the full test sums the widths of every lane on
/// a side): inside its own lane, that lane not of type `none`, on a road without lane offset
/// (the off-road rule measures widths from the centre lane but compares |t|).
fn inside_real_lane(net: &RoadNetwork, lp: &LanePos, p: &crate::roads::lane_position::LanePose) -> bool {
    let Some((a, b)) = p.lane else { return false };
    if p.t < a.min(b) - 1e-9 || p.t > a.max(b) + 1e-9 {
        return false;
    }
    let Some(road) = net.roads.get(lp.road) else { return false };
    if !(0.0..=road.length).contains(&lp.s) || road.lane_offset_at(lp.s) != 0.0 {
        return false;
    }
    let Some(sec) = road.section_at(lp.s) else { return false };
    lp.lane_id == 0 || sec.left.iter().chain(&sec.right).any(|l| l.id == lp.lane_id && l.kind != opendrive::LaneType::None)
}

/// R0R12EulerAngles' guard against gimbal lock: a cosine of magnitude below SMALL_NUMBER
/// becomes ±SMALL_NUMBER (0 counting as positive).
pub(crate) fn gimbal_guard(cos: f64) -> f64 {
    let small = crate::dynamics::ESMINI_SMALL_NUMBER;
    if cos.abs() >= small {
        cos
    } else if cos < 0.0 {
        -small
    } else {
        small
    }
}

/// The heading esmini reports for an entity facing `h` (Object::pos_.GetH()): Position::
/// EvaluateHPR composes the road's rotation with the relative one (R0R12EulerAngles), whose
/// guard against gimbal lock sets a cosine smaller than 1e-6 to ±1e-6, so a heading within a
/// micro-radian of ±π/2 comes out 1e-6 rad from it. A lead exactly ahead or behind on a road
/// along ±y lies on the side of π that this offset picks.
pub(crate) fn esmini_reported_heading(h: f64) -> f64 {
    let (sin, cos) = h.sin_cos();
    if cos.abs() >= crate::dynamics::ESMINI_SMALL_NUMBER {
        return h;
    }
    wrap_2pi(sin.atan2(gimbal_guard(cos)))
}

/// The heading esmini's position holds when turned by `h_rel` from a level road's heading
/// `h_road` (Position::EvaluateHPR: R0R12EulerAngles multiplies the two rotation matrices and
/// takes atan2 of the product's first column, its cosine guarded against gimbal lock, in
/// [0, 2π)). The product's terms in esmini's order, so the result is esmini's to the last bit
/// on a road without pitch or roll: a heading along ±y comes out 1e-6 rad off, and one along
/// ±x can differ from `h_road + h_rel` by an ulp, which is what decides which way a looming
/// car turns past a dead end.
pub(crate) fn esmini_euler_heading(h_road: f64, h_rel: f64) -> f64 {
    crate::attitude::compose([h_road, 0.0, 0.0], [h_rel, 0.0, 0.0])[0]
}

/// Object::pos_.GetH() of entity `en` as its last orientation write left it: after an
/// absolute one (SetInertiaPos, SetHeading: EvaluateHPR with H_ABS) the road's rotation
/// composed with GetAngleDifference(h, road), in [-π, π]; after a move along the lane
/// (SetLanePos: H_REL) with the relative heading esmini holds, in [0, 2π). Facing exactly
/// against a road along π, the first is 0 and the second 2π (6.283185307179586), which decides
/// the sign of the angle to a reference facing the other way (LatDistanceAction, entity frame).
pub(crate) fn position_heading_by_mode(net: Option<&opendrive::RoadNetwork>, en: &Entity) -> f64 {
    match net.zip(en.lane).and_then(|(net, lp)| lp.pose(net)) {
        Some(p) => {
            let rel = crate::angles::angle_difference(en.h, p.road_heading);
            // H_REL: the relative heading esmini holds is in [0, 2π) (CalcRelAnglesFromRoadAndAbsAngles).
            let rel = if en.heading_abs { rel } else { wrap_2pi(rel) };
            esmini_euler_heading(p.road_heading, rel)
        }
        None => esmini_reported_heading(en.h),
    }
}

/// Object::pos_.GetH() of entity `en`: its heading as esmini's position holds it, composed
/// with its road's (Position::EvaluateHPR with an absolute heading, turned from the road's by
/// GetAngleDifference: `esmini_euler_heading`).
pub(crate) fn position_heading(net: Option<&opendrive::RoadNetwork>, en: &Entity) -> f64 {
    match net.zip(en.lane).and_then(|(net, lp)| lp.pose(net)) {
        Some(p) => esmini_euler_heading(p.road_heading, crate::angles::angle_difference(en.h, p.road_heading)),
        None => esmini_reported_heading(en.h),
    }
}

/// Each entity's bounding box `(cx, cy, cz, length, width, height)`, in the order of the
/// trace's entities (the argument [`crate::Trace::to_csv`] takes).
pub fn bounding_boxes(scenario: &Scenario) -> Vec<[f64; 6]> {
    Entity::from_scenario(scenario).iter().map(|e| e.bbox).collect()
}
