//! Paths from already-resolved world poses, one constructor per shape.

use crate::angle;
use crate::error::Error;
use crate::nurbs::Nurbs;
use crate::nurbs_path::NurbsPath;
use crate::path::{Curve, Path};
use crate::polyline::Polyline;
use crate::pose::Pose;
use crate::sampled::Sampled;
use crate::spiral::Spiral;
use crate::time_table::TimeTable;
use crate::ESMINI_SMALL;

/// Upper bound on vertices / control points / knots / segments accepted from a file.
pub const MAX_ITEMS: usize = 100_000;
/// Upper bound on a trajectory's length in metres (hostile input).
pub const MAX_LENGTH: f64 = 1.0e6;

/// Vertices closer than this (m) are the same point.
const SAME_POINT: f64 = 1e-9;

/// esmini's player merges polyline vertices this close (m; its `--traj_filter` default)...
const FILTER_RADIUS: f64 = 0.1;
/// ... whose headings differ by less than this (rad)...
const FILTER_HEADING: f64 = 0.1;
/// ... unless the next distinct vertex is this much later (s): then the entity stands still.
const FILTER_TIME: f64 = 1.0;

/// A polyline vertex as resolved: its pose, time stamp, whether its position gives a heading
/// of its own and whether it is a relative position (esmini never merges those).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolylineVertex {
    pub pose: Pose,
    pub time: Option<f64>,
    pub explicit_heading: bool,
    pub relative: bool,
}

/// esmini's PolyLineShape::FinalizeVertices as its player runs it (traj_filter 0.1): the
/// first and last vertices stay; a vertex within 0.1 m of the one kept before it (and within
/// 0.1 rad of its heading, esmini's signed difference) is dropped — or, when the next distinct
/// vertex comes more than a second later, put on the kept one (the entity stands still there).
/// Relative positions are never merged. A missing time counts as 0.
pub fn filter_vertices(v: &[PolylineVertex]) -> Vec<PolylineVertex> {
    if v.len() <= 2 {
        return v.to_vec();
    }
    let same = |a: &PolylineVertex, b: &PolylineVertex| {
        !a.relative
            && !b.relative
            && (a.pose.x - b.pose.x).hypot(a.pose.y - b.pose.y) < FILTER_RADIUS + ESMINI_SMALL
            && angle::diff(a.pose.heading, b.pose.heading) < FILTER_HEADING + ESMINI_SMALL
    };
    let time = |x: &PolylineVertex| x.time.unwrap_or(0.0);
    let mut w: Vec<PolylineVertex> = v.to_vec();
    let (mut a, mut b, mut c) = (0usize, 1usize, 2usize);
    while c < w.len() {
        if same(&w[a], &w[b]) {
            if same(&w[a], &w[c]) {
                // b and c both close to a: c takes b's place
                w[b] = w[c];
                c += 1;
            } else {
                if time(&w[c]) - time(&w[a]) < FILTER_TIME + ESMINI_SMALL {
                    // no stand-still: b goes, c is the new a
                    a += 1;
                    w[a] = w[c];
                } else {
                    // stand-still: b takes a's place (and pose), c is the new a
                    let keep = PolylineVertex { pose: w[a].pose, relative: w[a].relative, explicit_heading: w[a].explicit_heading, time: w[b].time };
                    a += 1;
                    w[a] = keep;
                    a += 1;
                    w[a] = w[c];
                }
                b = c + 1;
                c += 2;
            }
        } else {
            a += 1;
            w[a] = w[b];
            b += 1;
            c += 1;
        }
    }
    if b < w.len() {
        a += 1;
        w[a] = w[b];
    }
    w.truncate(a + 1);
    w
}

/// One clothoid-spline segment with its start resolved (None: continue from the previous
/// segment's end, or from the path's start pose for the first).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SplineSegment {
    pub start: Option<Pose>,
    pub curvature_start: f64,
    pub curvature_end: f64,
    pub length: f64,
    /// Heading offset added at the start of the segment (rad).
    pub h_offset: f64,
    pub time_start: Option<f64>,
}

fn check_count(shape: &'static str, what: &'static str, found: usize, needed: usize) -> Result<(), Error> {
    if found > MAX_ITEMS {
        return Err(Error::TooMany { shape, what, max: MAX_ITEMS, found });
    }
    if found < needed {
        return Err(Error::TooFew { shape, what, needed, found });
    }
    Ok(())
}

fn check_num(shape: &'static str, what: impl Into<String>, v: f64) -> Result<f64, Error> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::BadNumber { shape, what: what.into(), constraint: "", value: v })
    }
}

fn check_pose(shape: &'static str, what: impl Into<String>, p: &Pose) -> Result<(), Error> {
    if p.is_finite() {
        Ok(())
    } else {
        let v = [p.x, p.y, p.z, p.heading].into_iter().find(|v| !v.is_finite()).unwrap_or(f64::NAN);
        Err(Error::BadNumber { shape, what: what.into(), constraint: "", value: v })
    }
}

fn check_length(shape: &'static str, length: f64) -> Result<(), Error> {
    if length.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(Error::ZeroLength { shape });
    }
    if length > MAX_LENGTH {
        return Err(Error::BadNumber { shape, what: "the total length".into(), constraint: " ≤ 1e6 m", value: length });
    }
    Ok(())
}

/// Time stamps if every item has one; a warning if only some do.
fn all_or_none(shape: &'static str, times: &[Option<f64>], warnings: &mut Vec<String>) -> Option<Vec<f64>> {
    let have = times.iter().filter(|t| t.is_some()).count();
    if have == times.len() && have > 0 {
        return Some(times.iter().map(|t| t.unwrap_or(0.0)).collect());
    }
    if have > 0 {
        warnings.push(format!("{shape}: only {have} of {} time stamps given; the time stamps are ignored", times.len()));
    }
    None
}

impl Path {
    /// A polyline through `vertices` (pose, optional time), none giving a heading of its own.
    pub fn polyline(vertices: &[(Pose, Option<f64>)], closed: bool) -> Result<Path, Error> {
        let v: Vec<PolylineVertex> =
            vertices.iter().map(|(pose, time)| PolylineVertex { pose: *pose, time: *time, explicit_heading: false, relative: false }).collect();
        Path::polyline_of(&v, closed)
    }

    /// A polyline through `vertices`, filtered as esmini's player filters them (see
    /// [`filter_vertices`]). Repeated vertices are dropped from the geometry (their time
    /// stamps stay: the entity waits there); a closed polyline gets a segment back to its
    /// first vertex.
    pub fn polyline_of(vertices: &[PolylineVertex], closed: bool) -> Result<Path, Error> {
        const SHAPE: &str = "Polyline";
        check_count(SHAPE, "vertices", vertices.len(), 2)?;
        let mut warnings = Vec::new();
        for (i, v) in vertices.iter().enumerate() {
            check_pose(SHAPE, format!("vertex {i}"), &v.pose)?;
            if let Some(t) = v.time {
                check_num(SHAPE, format!("time of vertex {i}"), t)?;
            }
        }
        let filtered = filter_vertices(vertices);
        if filtered.len() < vertices.len() {
            warnings.push(format!(
                "{SHAPE}: {} of {} vertices lie within {FILTER_RADIUS} m of a neighbour and are merged, as esmini's player merges them (traj_filter)",
                vertices.len() - filtered.len(),
                vertices.len()
            ));
        }
        let mut xyz: Vec<[f64; 3]> = Vec::with_capacity(filtered.len() + 1);
        let mut explicit: Vec<Option<f64>> = Vec::with_capacity(filtered.len() + 1);
        let mut stamps = Vec::with_capacity(filtered.len());
        let mut s = 0.0;
        for (i, v) in filtered.iter().enumerate() {
            let p = &v.pose;
            match xyz.last() {
                Some(q) if (p.x - q[0]).hypot(p.y - q[1]) <= SAME_POINT => {
                    warnings.push(format!("{SHAPE}: vertex {i} repeats the previous one and adds no segment"));
                }
                Some(q) => {
                    s += (p.x - q[0]).hypot(p.y - q[1]);
                    xyz.push([p.x, p.y, p.z]);
                    explicit.push(v.explicit_heading.then_some(p.heading));
                }
                None => {
                    xyz.push([p.x, p.y, p.z]);
                    explicit.push(v.explicit_heading.then_some(p.heading));
                }
            }
            stamps.push((s, v.time));
        }
        if xyz.len() < 2 {
            // Every vertex at one point: esmini keeps the entity there (for the time the
            // stamps span, if any).
            warnings.push(format!("{SHAPE}: all vertices lie at one point; the path has no length"));
        }
        if closed && xyz.len() > 1 {
            if let (Some(first), Some(last)) = (xyz.first().copied(), xyz.last()) {
                if (first[0] - last[0]).hypot(first[1] - last[1]) > SAME_POINT {
                    xyz.push(first);
                }
            }
        }
        let line = Polyline::new(&xyz, &explicit, closed);
        let length = line.length();
        if length > MAX_LENGTH {
            return Err(Error::BadNumber { shape: SHAPE, what: "the total length".into(), constraint: " ≤ 1e6 m", value: length });
        }
        // esmini reads a vertex without a time as time 0 (ScenarioReader: strtod of nothing);
        // stamps need not rise.
        let times: Vec<Option<f64>> = stamps.iter().map(|p| p.1).collect();
        let given = times.iter().filter(|t| t.is_some()).count();
        let times = if given == 0 {
            None
        } else {
            if given < times.len() {
                warnings.push(format!("{SHAPE}: only {given} of {} vertices have a time stamp; the others count as time 0, as in esmini", times.len()));
            }
            if closed && xyz.len() > filtered.len() {
                warnings.push(format!("{SHAPE}: closed and timed; the closing segment has no time stamps and takes no time"));
            }
            Some(TimeTable::unordered(SHAPE, stamps.iter().map(|(s, t)| (*s, t.unwrap_or(0.0))).collect())?)
        };
        Ok(Path { curve: Curve::Polyline(line), length, closed, times, warnings })
    }

    /// One clothoid from `start`: curvature κ + κ'·s for s in [0, length]; `time` is
    /// (startTime, stopTime), spread linearly over the length.
    pub fn clothoid(start: Pose, curvature: f64, curvature_prime: f64, length: f64, time: (Option<f64>, Option<f64>), closed: bool) -> Result<Path, Error> {
        let seg = SplineSegment {
            start: Some(start),
            curvature_start: curvature,
            curvature_end: curvature + curvature_prime * length,
            length,
            h_offset: 0.0,
            time_start: time.0,
        };
        let mut path = Path::spirals(start, &[seg], time.1, closed, &|p| p)?;
        for w in path.warnings.iter_mut() {
            *w = w.replace("ClothoidSpline", "Clothoid");
        }
        Ok(path)
    }

    /// Clothoid segments one after the other; `time_end` is the time at the end of the last.
    /// Zero-length segments are skipped with a warning. The path is esmini's one-metre polyline
    /// of the segments (see `sampled.rs`).
    pub fn clothoid_spline(start: Pose, segments: &[SplineSegment], time_end: Option<f64>, closed: bool) -> Result<Path, Error> {
        Path::clothoid_spline_placed(start, segments, time_end, closed, &|p| p)
    }

    /// [`Path::clothoid_spline`] where a segment without a start of its own begins at the previous
    /// one's end as `place` puts that pose in the world: esmini's ClothoidSplineShape::Freeze
    /// starts it from the previous segment's end set by SetInertiaPos(x, y, h), whose heading is
    /// composed with the road's pitch and roll there (EvaluateHPR), so on a sloped or banked road
    /// it is not the spiral's own end heading. Only the heading of the placed pose is taken.
    pub fn clothoid_spline_placed(start: Pose, segments: &[SplineSegment], time_end: Option<f64>, closed: bool, place: crate::Placer) -> Result<Path, Error> {
        let exact = Path::spirals(start, segments, time_end, closed, place)?;
        if exact.length < 1.0 {
            return Ok(exact);
        }
        // The length stays the curve's: esmini moves on to the true length, standing at the
        // last vertex over the final fraction of a metre.
        let sampled = Sampled::new(exact.length, 1.0, |s| exact.pose_at(s));
        Ok(Path { curve: Curve::Sampled(sampled), length: exact.length, closed, times: exact.times, warnings: exact.warnings })
    }

    /// The exact clothoid segments (a Clothoid shape; the base of a ClothoidSpline).
    fn spirals(start: Pose, segments: &[SplineSegment], time_end: Option<f64>, closed: bool, place: crate::Placer) -> Result<Path, Error> {
        const SHAPE: &str = "ClothoidSpline";
        check_count(SHAPE, "segments", segments.len(), 1)?;
        check_pose(SHAPE, "the start pose", &start)?;
        let mut warnings = Vec::new();
        let mut list = Vec::with_capacity(segments.len());
        let mut stamps: Vec<(f64, Option<f64>)> = Vec::with_capacity(segments.len() + 1);
        let mut at = start;
        let mut s = 0.0;
        for (i, seg) in segments.iter().enumerate() {
            let k0 = check_num(SHAPE, format!("curvatureStart of segment {i}"), seg.curvature_start)?;
            let k1 = check_num(SHAPE, format!("curvatureEnd of segment {i}"), seg.curvature_end)?;
            let len = check_num(SHAPE, format!("length of segment {i}"), seg.length)?;
            let h_off = check_num(SHAPE, format!("hOffset of segment {i}"), seg.h_offset)?;
            if let Some(t) = seg.time_start {
                check_num(SHAPE, format!("timeStart of segment {i}"), t)?;
            }
            if len < 0.0 {
                return Err(Error::BadNumber { shape: SHAPE, what: format!("length of segment {i}"), constraint: " ≥ 0", value: len });
            }
            if let Some(p) = seg.start {
                check_pose(SHAPE, format!("start of segment {i}"), &p)?;
                at = p;
            } else if i > 0 {
                let placed = place(at);
                if placed.heading.is_finite() {
                    at.heading = placed.heading;
                }
            }
            at.heading += h_off;
            stamps.push((s, seg.time_start));
            if len <= 0.0 {
                warnings.push(format!("{SHAPE}: segment {i} has zero length and is skipped"));
                continue;
            }
            if s + len > MAX_LENGTH {
                return Err(Error::BadNumber { shape: SHAPE, what: "the total length".into(), constraint: " ≤ 1e6 m", value: s + len });
            }
            let sp = Spiral::new(at, k0, (k1 - k0) / len, len);
            at = sp.end_pose();
            list.push((s, sp));
            s += len;
        }
        check_length(SHAPE, s)?;
        if let Some(t) = time_end {
            check_num(SHAPE, "timeEnd", t)?;
        }
        stamps.push((s, time_end));
        let times: Vec<Option<f64>> = stamps.iter().map(|p| p.1).collect();
        let times = match all_or_none(SHAPE, &times, &mut warnings) {
            Some(ts) => Some(TimeTable::new(SHAPE, stamps.iter().zip(ts).map(|((s, _), t)| (*s, t)).collect())?),
            None => None,
        };
        Ok(Path { curve: Curve::Spirals(list), length: s, closed, times, warnings })
    }

    /// A NURBS curve: control points (pose, weight, optional time), knots. Only x, y, z of
    /// the poses count: headings follow the curve.
    pub fn nurbs(order: u32, control_points: &[(Pose, Option<f64>, Option<f64>)], knots: &[f64], closed: bool) -> Result<Path, Error> {
        Path::nurbs_with_headings(order, control_points, knots, closed, false)
    }

    /// [`Path::nurbs`]; when `first_gives_heading` (the first control point's position gives a
    /// heading of its own) the headings are blended from the poses' headings as esmini does
    /// (NurbsShape::EvaluateInternal) rather than following the curve.
    pub fn nurbs_with_headings(
        order: u32,
        control_points: &[(Pose, Option<f64>, Option<f64>)],
        knots: &[f64],
        closed: bool,
        first_gives_heading: bool,
    ) -> Result<Path, Error> {
        const SHAPE: &str = "NURBS";
        check_count(SHAPE, "control points", control_points.len(), 2)?;
        check_count(SHAPE, "knots", knots.len(), 0)?;
        let mut warnings = Vec::new();
        let mut pts = Vec::with_capacity(control_points.len());
        for (i, (p, w, t)) in control_points.iter().enumerate() {
            check_pose(SHAPE, format!("control point {i}"), p)?;
            if let Some(t) = t {
                check_num(SHAPE, format!("time of control point {i}"), *t)?;
            }
            pts.push([p.x, p.y, p.z, w.unwrap_or(1.0)]);
        }
        let curve = Nurbs::new(order, pts, knots.to_vec())?;
        let np = NurbsPath::new(curve, first_gives_heading.then(|| control_points.iter().map(|c| c.0.heading).collect()))?;
        let length = np.length();
        check_length(SHAPE, length)?;
        let times: Vec<Option<f64>> = control_points.iter().map(|c| c.2).collect();
        let times = match all_or_none(SHAPE, &times, &mut warnings) {
            Some(ts) => {
                if let Some(i) = ts.windows(2).position(|w| matches!(w, [a, b] if b < a)) {
                    return Err(Error::NotMonotone { shape: SHAPE, what: "control point times", index: i + 1 });
                }
                Some(TimeTable::new(SHAPE, np.time_stamps(&ts))?)
            }
            None => None,
        };
        Ok(Path { curve: Curve::Nurbs(np), length, closed, times, warnings })
    }
}
