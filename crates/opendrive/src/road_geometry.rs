//! Geometry of one road in road coordinates: reference-line pose at s, elevation,
//! lane offset, lane-section lookup, lane borders and lane centres.
//!
//! Conventions: s along the reference line, t to its left (+t left). Lane borders are t
//! values (left lanes positive). Borders from `<width>` are cumulated outward from the
//! centre lane, which sits at t = laneOffset(s). Borders from `<border>` records (used only
//! when a lane has no `<width>`) give the outer border's t directly, measured from the
//! centre lane (t = laneOffset + border(ds)); the value is signed like t.

use crate::geometry::CurvePose;
use crate::model::lanes::{Lane, LaneSection};
use crate::model::poly::{piecewise_slope, piecewise_value, record_at};
use crate::model::road::Road;

/// Inner and outer border of a lane at some s (t values; inner is nearer the centre lane).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneBorders {
    pub inner: f64,
    pub outer: f64,
    /// t of the lane centre, rounded as esmini computes it (`LaneSection::GetCenterOffset`:
    /// the summed widths out to this lane's outer border minus half its width, then signed
    /// and added to the lane offset, `Position::Lane2Track`). The midpoint of the borders
    /// can differ from it in the last bit, and entities placed on one lane then sit a hair
    /// apart; that sign decides ties (e.g. the cross-track term of FollowReferenceController).
    pub center: f64,
}

impl LaneBorders {
    /// t of the lane centre, as esmini rounds it (the field `center`).
    pub fn center(&self) -> f64 {
        self.center
    }
    /// Signed width |outer − inner| taken positive when the lane opens outward.
    pub fn width(&self) -> f64 {
        (self.outer - self.inner).abs()
    }
    /// Whether t lies between the borders (inclusive).
    pub fn contains(&self, t: f64) -> bool {
        let (lo, hi) = if self.inner <= self.outer { (self.inner, self.outer) } else { (self.outer, self.inner) };
        t >= lo && t <= hi
    }
}

/// A point in world coordinates with the reference line's heading at its s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WorldPose {
    pub x: f64,
    pub y: f64,
    /// Elevation of the reference line at s (superelevation not applied).
    pub z: f64,
    /// Heading of the road's reference line at s (not the lane's driving direction).
    pub heading: f64,
}

impl Road {
    /// Index of the geometry in force at `s`.
    pub fn geometry_index_at(&self, s: f64) -> usize {
        self.geometries.partition_point(|g| g.s <= s).saturating_sub(1)
    }

    /// Reference-line pose at `s` (clamped to [0, length]).
    pub fn reference_pose(&self, s: f64) -> CurvePose {
        let s = s.clamp(0.0, self.length);
        match self.geometries.get(self.geometry_index_at(s)) {
            Some(g) => g.pose_at((s - g.s).max(0.0)),
            None => CurvePose::default(),
        }
    }

    /// Elevation z at `s` (0 without elevation records).
    pub fn elevation_at(&self, s: f64) -> f64 {
        piecewise_value(&self.elevation, s)
    }

    /// Elevation slope dz/ds at `s`.
    pub fn elevation_slope_at(&self, s: f64) -> f64 {
        piecewise_slope(&self.elevation, s)
    }

    /// Lane offset (t of the centre lane) at `s`.
    pub fn lane_offset_at(&self, s: f64) -> f64 {
        piecewise_value(&self.lane_offsets, s)
    }

    /// [start, end) of lane section `idx` in road s.
    pub fn section_range(&self, idx: usize) -> Option<(f64, f64)> {
        let start = self.lane_sections.get(idx)?.s;
        let end = self.lane_sections.get(idx + 1).map_or(self.length, |n| n.s);
        Some((start, end.max(start)))
    }

    /// Index of the lane section in force at `s`: the last starting at or before `s`;
    /// a zero-length section at the very end is skipped in favour of the one before it.
    pub fn section_index_at(&self, s: f64) -> usize {
        let mut i = self.lane_sections.partition_point(|sec| sec.s <= s).saturating_sub(1);
        while i > 0 && self.section_range(i).is_some_and(|(a, b)| b - a <= 1e-9) {
            i -= 1;
        }
        i
    }

    /// The lane section in force at `s`.
    pub fn section_at(&self, s: f64) -> Option<&LaneSection> {
        self.lane_sections.get(self.section_index_at(s))
    }

    /// Borders of every lane of one side at `s`, innermost first: (lane id, borders).
    /// `left` selects positive ids. Gaps in the id sequence are tolerated.
    pub fn side_borders(&self, section_idx: usize, left: bool, s: f64) -> Vec<(i32, LaneBorders)> {
        self.side_border_iter(section_idx, left, s).collect()
    }

    /// [`Road::side_borders`] without collecting: the borders are cumulated lazily, so a
    /// caller that needs only the outermost lane allocates nothing.
    pub fn side_border_iter(&self, section_idx: usize, left: bool, s: f64) -> impl ExactSizeIterator<Item = (i32, LaneBorders)> + '_ {
        let (lanes, ds): (&[Lane], f64) = match self.lane_sections.get(section_idx) {
            Some(sec) => (if left { &sec.left } else { &sec.right }, s - sec.s),
            None => (&[], 0.0),
        };
        let sign = if left { 1.0 } else { -1.0 };
        let base = if lanes.is_empty() { 0.0 } else { self.lane_offset_at(s) };
        let mut inner = base;
        // esmini's unsigned sum of the widths from the centre lane out (GetOuterOffset)
        let mut summed = 0.0;
        lanes.iter().map(move |lane| {
            let (outer, center) = if !lane.widths.is_empty() {
                let w = record_at(&lane.widths, ds).map_or(0.0, |r| r.value(ds - r.s));
                summed += w;
                (inner + sign * w, base + sign * (summed - w / 2.0))
            } else if let Some(b) = record_at(&lane.borders, ds) {
                let outer = base + b.value(ds - b.s);
                summed = (outer - base).abs();
                (outer, 0.5 * (inner + outer))
            } else {
                (inner, inner)
            };
            let b = LaneBorders { inner, outer, center };
            inner = outer;
            (lane.id, b)
        })
    }

    /// Borders of lane `lane_id` of section `section_idx` at `s` (centre lane: both at the
    /// lane offset). `None` if the section or lane does not exist.
    pub fn lane_borders(&self, section_idx: usize, lane_id: i32, s: f64) -> Option<LaneBorders> {
        let sec = self.lane_sections.get(section_idx)?;
        if lane_id == 0 {
            sec.center.as_ref()?;
            let t = self.lane_offset_at(s);
            return Some(LaneBorders { inner: t, outer: t, center: t });
        }
        self.side_border_iter(section_idx, lane_id > 0, s).find(|(id, _)| *id == lane_id).map(|(_, b)| b)
    }

    /// t of the centre of lane `lane_id` at `s`.
    pub fn lane_center_t(&self, section_idx: usize, lane_id: i32, s: f64) -> Option<f64> {
        self.lane_borders(section_idx, lane_id, s).map(|b| b.center())
    }

    /// World position of road coordinates (s, t); s clamped to the road.
    pub fn st_to_world(&self, s: f64, t: f64) -> WorldPose {
        let p = self.reference_pose(s);
        let (sin, cos) = p.hdg.sin_cos();
        WorldPose { x: p.x - t * sin, y: p.y + t * cos, z: self.elevation_at(s.clamp(0.0, self.length)), heading: p.hdg }
    }

    /// Heading of the curve t = lane centre + offset at `s`, i.e. the reference heading
    /// corrected by the lateral drift dt/ds of a lane whose width changes.
    pub fn lane_tangent_heading(&self, section_idx: usize, lane_id: i32, s: f64, offset: f64) -> Option<f64> {
        let h = 1e-3;
        let (a, b) = self.section_range(section_idx)?;
        let (s0, s1) = ((s - h).max(a), (s + h).min(b.max(a + 2.0 * h)));
        let t0 = self.lane_center_t(section_idx, lane_id, s0)? + offset;
        let t1 = self.lane_center_t(section_idx, lane_id, s1)? + offset;
        let t = self.lane_center_t(section_idx, lane_id, s)? + offset;
        let p = self.reference_pose(s);
        let dtds = if s1 > s0 { (t1 - t0) / (s1 - s0) } else { 0.0 };
        Some(p.hdg + dtds.atan2(1.0 - p.curvature * t))
    }
}
