//! A lane's own height above the road surface (`<lane><height>`: kerbs, raised sidewalks) as
//! esmini places it in the world: Position::Track2XYZ turns the point (0, t, height) by the
//! road's heading, pitch and roll, so the height lifts the point along the road's tilted normal.

use opendrive::{LaneBorders, Road};

/// The shift lane `lane_id`'s height gives a point `offset` m from the lane's centre at `s`
/// (`borders`: the lane's borders there): across the reference line (horizontal),
/// up, and along the reference heading; `None` when the lane has no height there to give.
/// The roll and pitch are those of [`super::banking::banked`].
pub(crate) fn lift(road: &Road, s: f64, lane_id: i32, offset: f64, borders: LaneBorders) -> Option<(f64, f64, f64)> {
    if !road.has_raised_lanes() {
        return None;
    }
    let section = road.lane_sections.get(road.section_index_at(s))?;
    let lane = section.lane(lane_id).filter(|l| !l.heights.is_empty())?;
    let height = lane.height_at(s - section.s, offset, borders.width());
    if height == 0.0 {
        return None;
    }
    let roll = super::banking::roll_at(road, s).0;
    let pitch = -road.elevation_slope_at(s).atan();
    let (sin_r, cos_r) = roll.sin_cos();
    let (sin_p, cos_p) = pitch.sin_cos();
    Some((-height * sin_r, height * cos_r * cos_p, height * cos_r * sin_p))
}
