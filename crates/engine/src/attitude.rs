//! Pitch and roll of an entity as esmini's AngleCondition reads them (TrigByAngle, with
//! Position's pitch and roll). On a road the entity lies on the surface: esmini composes the
//! road's rotation (reference heading, pitch −atan of the elevation slope, roll the
//! superelevation) with the entity's own (its heading from the road, and the pitch offset
//! GetPOffset adds where the superelevation changes) as full rotations (Position::EvaluateHPR,
//! R0R12EulerAngles: `compose`, `on_road`). Following a polyline trajectory whose vertices
//! give their own heights, it pitches with the path instead (esmini's trajectory vertex
//! pitch, corner-blended).

use crate::actions::state::ActionRt;
use crate::angles::wrap;
use crate::entities::Entity;
use crate::roads::banking::roll_at;
use crate::roads::LanePos;
use crate::sim::Sim;
use opendrive::{Road, RoadNetwork};
use std::f64::consts::FRAC_PI_2;

/// The road's pitch and roll along its s direction at `lp`.
pub(crate) fn road_pitch_roll(net: &RoadNetwork, lp: &LanePos) -> (f64, f64) {
    let Some(road) = net.roads.get(lp.road) else { return (0.0, 0.0) };
    let s = lp.s.clamp(0.0, road.length);
    (-road.elevation_slope_at(s).atan(), roll_at(road, s).0)
}

/// Pitch and roll of entity `e` lying on the road surface where it is: the road's rotation
/// composed with the entity's heading from the road and GetPOffset's pitch (`on_road`; on a
/// level stretch the road's own, turned around when the entity faces against s); (0, 0) off
/// the road.
pub(crate) fn surface_pitch_roll(net: &RoadNetwork, e: &Entity) -> (f64, f64) {
    if let Some(placed) = e.placed_pitch_roll() {
        return placed;
    }
    let Some(lp) = e.lane else { return (0.0, 0.0) };
    let Some(road) = net.roads.get(lp.road) else { return (0.0, 0.0) };
    let s = lp.s.clamp(0.0, road.length);
    if let Some(t) = lp.pose(net).map(|q| q.t) {
        // esmini's h_relative: the turn from the road that moving keeps (the yaw offset from
        // the way the entity faces), and the lane's drift GetHOffset adds to it.
        let h_relative = e.yaw_offset + if lp.dir < 0.0 { std::f64::consts::PI } else { 0.0 };
        let drift = crate::positions::lane_drift(net, lp.road, lp.lane_id, s);
        if let Some([_, p, r]) = on_road(road, s, t, h_relative + drift, h_relative) {
            return (p, r);
        }
    }
    let (p, r) = road_pitch_roll(net, &lp);
    let h_ref = crate::roads::pose_memo::reference_pose(road, s).hdg;
    let facing = if wrap(e.h - h_ref).abs() <= FRAC_PI_2 { 1.0 } else { -1.0 };
    (p * facing, r * facing)
}

/// esmini's R0R12EulerAngles: the rotation `road` = (heading, pitch, roll), Rz·Ry·Rx,
/// followed by `rel`, as heading in [0, 2π), pitch and roll in (−π, π] (esmini puts those in
/// [0, 2π) too: the same angles). The matrix product's terms in esmini's order, and its
/// guard against gimbal lock; with no pitch and roll the heading is `entities::
/// esmini_euler_heading`'s to the bit.
pub(crate) fn compose(road: [f64; 3], rel: [f64; 3]) -> [f64; 3] {
    let m = guarded_product(rotation(road), rotation(rel));
    let h = crate::angles::wrap_2pi(m[1][0].atan2(m[0][0]));
    let p = (-m[2][0]).atan2((m[2][1] * m[2][1] + m[2][2] * m[2][2]).sqrt());
    let r = m[2][1].atan2(m[2][2]);
    [h, p, r]
}

/// esmini's CalcRelAnglesFromRoadAndAbsAngles: the turn (heading, pitch, roll) from the
/// rotation `road` to the absolute one `abs`, as the road's inverse (InvertMatrix3's
/// Gauss-Jordan elimination, no pivoting) times the absolute rotation, with the same guard
/// against gimbal lock as `compose`; every angle in [0, 2π). The terms in esmini's order, so
/// that a turn of a right angle falls on esmini's side of it (the guard keeps the sign of a
/// cosine that is a rounding error away from 0).
pub(crate) fn relative(road: [f64; 3], abs: [f64; 3]) -> [f64; 3] {
    let m = guarded_product(invert(rotation(road)), rotation(abs));
    let wrap = crate::angles::wrap_2pi;
    [wrap(m[1][0].atan2(m[0][0])), wrap((-m[2][0]).atan2((m[2][1] * m[2][1] + m[2][2] * m[2][2]).sqrt())), wrap(m[2][1].atan2(m[2][2]))]
}

/// The product a·b, its terms summed in esmini's order, with esmini's guard against gimbal
/// lock on the two cosines the angles are read from (`entities::gimbal_guard`).
fn guarded_product(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            for k in 0..3 {
                *v += a[i][k] * b[k][j];
            }
        }
    }
    m[0][0] = crate::entities::gimbal_guard(m[0][0]);
    m[2][2] = crate::entities::gimbal_guard(m[2][2]);
    m
}

/// esmini's InvertMatrix3: Gauss-Jordan elimination on the matrix augmented with the identity,
/// without pivoting (a rotation's diagonal is never exactly 0 here: its cosines of ±π/2 are
/// rounding errors, not zeros; a zero pivot leaves the identity, where esmini logs an error
/// and leaves its output untouched).
fn invert(m: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut a = [[0.0; 6]; 3];
    for i in 0..3 {
        a[i][..3].copy_from_slice(&m[i]);
        a[i][i + 3] = 1.0;
    }
    for i in 0..3 {
        let pivot = a[i][i];
        if pivot == 0.0 {
            return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        }
        for v in a[i].iter_mut() {
            *v /= pivot;
        }
        let row = a[i];
        for (k, other) in a.iter_mut().enumerate() {
            if k != i {
                let factor = other[i];
                for (v, r) in other.iter_mut().zip(row.iter()) {
                    *v -= factor * r;
                }
            }
        }
    }
    let mut inv = [[0.0; 3]; 3];
    for i in 0..3 {
        inv[i].copy_from_slice(&a[i][3..]);
    }
    inv
}

/// Rz(h)·Ry(p)·Rx(r), each entry as esmini's R0R12EulerAngles writes it.
fn rotation([h, p, r]: [f64; 3]) -> [[f64; 3]; 3] {
    let (sx, cx) = h.sin_cos();
    let (sy, cy) = p.sin_cos();
    let (sz, cz) = r.sin_cos();
    [[cx * cy, cx * sy * sz - sx * cz, sx * sz + cx * sy * cz], [sx * cy, cx * cz + sx * sy * sz, sx * sy * cz - cx * sz], [-sy, cy * sz, cy * cz]]
}

/// The orientation (heading, pitch, roll) esmini gives a position at (s, t) of `road` (t along
/// the surface) turned by `h_rel` from the road's reference heading, with no pitch or roll of
/// its own (Position::EvaluateHPR): the road's rotation composed with (h_rel, GetPOffset, 0),
/// where GetPOffset = cos(h_relative)·atan(tan(superelevation′)·−t) reads the relative heading
/// the position held before (`offset_h_rel`: 0 for a position made afresh, such as a
/// scenario's WorldPosition). `None` where the road is level there (no slope, roll or change
/// of roll): then the heading is the plain sum and pitch and roll are 0.
pub(crate) fn on_road(road: &Road, s: f64, t: f64, h_rel: f64, offset_h_rel: f64) -> Option<[f64; 3]> {
    let slope = road.elevation_slope_at(s);
    let (roll, rate) = roll_at(road, s);
    if slope == 0.0 && roll == 0.0 && rate == 0.0 {
        return None;
    }
    let h_road = crate::roads::pose_memo::reference_pose(road, s).hdg;
    let p_offset = offset_h_rel.cos() * (rate.tan() * -t).atan();
    Some(compose([h_road, -slope.atan(), roll], [h_rel, p_offset, 0.0]))
}

/// The heading esmini's position holds after SetInertiaPosMode(x, y, 0, h, 0, 0, Z_ABS | H_ABS |
/// P_REL | R_ABS) (ControllerOffroadFollower::Step): EvaluateHPR composes the road's heading
/// and pitch but no roll (R_ABS) with (h − h_road, GetPOffset, 0), so on a road without slope
/// the heading is `h` itself, whatever the banking. `None` where the road has no slope.
/// (GetPOffset left out: it turns the heading only together with a slope.)
pub(crate) fn heading_roll_absolute(road: &Road, s: f64, h: f64) -> Option<f64> {
    let slope = road.elevation_slope_at(s);
    if slope == 0.0 {
        return None;
    }
    let h_road = crate::roads::pose_memo::reference_pose(road, s).hdg;
    Some(compose([h_road, -slope.atan(), 0.0], [crate::angles::angle_difference(h, h_road), 0.0, 0.0])[0])
}

/// The orientation esmini's Position::EvaluateRelation leaves a RelativeObject- or
/// RelativeWorldPosition at (s, t) of `road` (t along the surface; `drift`: the lane's
/// GetHOffset there), given the absolute orientation `abs` it asked for (the entity's heading,
/// pitch and roll, turned by the position's own). SetInertiaPosMode sets all three absolute
/// (EvaluateHPR then keeps them and finds the turn from the road, CalcRelAnglesFromRoadAndAbsAngles
/// against its heading plus the drift); then EvaluateHPR runs once more in the position's SET
/// mode (GetModeDefault: heading absolute, pitch and roll relative), composing the road's
/// rotation with the heading's plain difference from the road's, the relative pitch plus
/// GetPOffset (read with the relative heading just found) and the relative roll. On a level
/// road with a level `abs` that is `abs` again: `None` then (the plain heading stands).
/// `past_end`: the point lies beyond the road's end, where XYZ2TrackPos leaves the road's
/// pitch and roll at 0 but not the rate of its roll, which GetPOffset still reads.
pub(crate) fn relation_orientation(road: &Road, s: f64, t: f64, drift: f64, abs: [f64; 3], past_end: bool) -> Option<[f64; 3]> {
    let (slope, (roll, rate)) = match roll_at(road, s) {
        (_, rate) if past_end => (0.0, (0.0, rate)),
        banking => (road.elevation_slope_at(s), banking),
    };
    if slope == 0.0 && roll == 0.0 && rate == 0.0 && abs[1] == 0.0 && abs[2] == 0.0 {
        return None;
    }
    let h_road = crate::roads::pose_memo::reference_pose(road, s).hdg;
    let road_rotation = [h_road, -slope.atan(), roll];
    let [h_rel, p_rel, r_rel] = relative([h_road + drift, road_rotation[1], road_rotation[2]], abs);
    let p_offset = h_rel.cos() * (rate.tan() * -t).atan();
    Some(compose(road_rotation, [crate::angles::angle_difference(abs[0], h_road), p_rel + p_offset, r_rel]))
}

/// The heading esmini gives a relative lane or road position at `lp` turned by `h_rel` from
/// the road's reference direction (the position's own relative heading, GetHRelative) on a
/// sloped or banked road: Position::EvaluateRelation sets it relative (SetHeadingRelative:
/// EvaluateHPR composes the road's rotation with h_rel plus the lane's `drift`), then calls
/// EvaluateHPR once more in the position's SET mode, whose heading is absolute by default
/// (GetModeDefault: H_ABS), so the heading found is taken as a turn from the road again and
/// composed a second time. `None` where the road is level there (the plain sum stands).
pub(crate) fn relative_position_heading(net: &RoadNetwork, lp: &LanePos, h_rel: f64, drift: f64) -> Option<f64> {
    let road = net.roads.get(lp.road)?;
    let s = lp.s.clamp(0.0, road.length);
    let t = lp.pose(net)?.t;
    let [first, _, _] = on_road(road, s, t, h_rel + drift, h_rel)?;
    let h_road = crate::roads::pose_memo::reference_pose(road, s).hdg;
    on_road(road, s, t, wrap(first - h_road), h_rel).map(|[h, _, _]| h)
}

impl<'a> Sim<'a> {
    /// World pitch and roll of entity `idx`.
    pub(crate) fn pitch_roll(&self, idx: usize) -> (f64, f64) {
        let Some(e) = self.entities.get(idx) else { return (0.0, 0.0) };
        let (mut pitch, roll) = self.net.map_or((0.0, 0.0), |net| surface_pitch_roll(net, e));
        let on_path = self.actions.iter().filter(|a| a.running).flat_map(|a| a.instances.iter()).find_map(|inst| match &inst.rt {
            ActionRt::FollowTrajectory(f) if inst.entity == Some(idx) && f.elevated => Some(f.path.pitch_at(f.s) * f.heading_sign),
            _ => None,
        });
        if let Some(p) = on_path {
            pitch = p;
        }
        // what the outside gave (external/)
        let (p, r) = self.external_attitude(idx);
        (p.unwrap_or(pitch), r.unwrap_or(roll))
    }
}
