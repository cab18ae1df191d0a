//! Uniform grid over sampled reference-line segments, inflated by each road's lateral
//! reach, so that world → road queries only look at nearby roads.

use crate::model::road::Road;

/// Reference lines are sampled at most this far apart (and closer on curves).
const MAX_STEP: f64 = 2.0;
/// Hostile-input caps: samples per road and per network (a segment is 64 bytes), grid
/// cells, lateral reach. Past a sample cap a road is sampled coarser (and its reach widened
/// to match), never dropped.
pub const MAX_SAMPLES_PER_ROAD: usize = 200_000;
pub const MAX_SEGMENTS: usize = 1_000_000;
const MAX_CELLS: f64 = 4_000_000.0;
const MAX_REACH: f64 = 500.0;
/// Budget of (cell, segment) entries of the grid (4 bytes each), unless the segments alone
/// need more (each is entered at least once).
const MAX_ENTRIES: usize = 2_000_000;

/// A piece of a reference line between two samples.
#[derive(Debug, Clone, Copy)]
pub struct Segment {
    pub road: usize,
    pub s0: f64,
    pub s1: f64,
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
    /// How far from the reference line the road's lanes reach along this segment (+ margin).
    pub reach: f64,
}

impl Segment {
    /// Closest point parameter in [0, 1] and squared distance from (x, y).
    pub fn project(&self, x: f64, y: f64) -> (f64, f64) {
        let (dx, dy) = (self.x1 - self.x0, self.y1 - self.y0);
        let len2 = dx * dx + dy * dy;
        let u = if len2 > 0.0 { (((x - self.x0) * dx + (y - self.y0) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
        let (px, py) = (self.x0 + u * dx - x, self.y0 + u * dy - y);
        (u, px * px + py * py)
    }
}

/// The grid: cell → segment indices, stored compactly (CSR).
#[derive(Debug, Clone, Default)]
pub struct SpatialIndex {
    pub segments: Vec<Segment>,
    min_x: f64,
    min_y: f64,
    cell: f64,
    nx: usize,
    ny: usize,
    cell_start: Vec<u32>,
    items: Vec<u32>,
}

/// Stations along one road's reference line, each with the slack to add to the reach of the
/// segment that starts there, and whether the road had to be sampled coarser than wanted.
fn road_stations(road: &Road, budget: usize) -> (Vec<(f64, f64)>, bool) {
    // (start, end, wanted count) per geometry
    let mut pieces = Vec::with_capacity(road.geometries.len());
    let mut wanted = 0usize;
    for g in &road.geometries {
        let k = g.max_abs_curvature();
        // Chord error of a step h on curvature k is k h²/8: keep it under ~1 cm.
        let step = if k > 0.0 { MAX_STEP.min((0.08 / k).sqrt()) } else { MAX_STEP };
        let end = (g.s + g.length).min(road.length);
        let n = ((end - g.s) / step).ceil().clamp(1.0, 1e15) as usize;
        wanted = wanted.saturating_add(n);
        pieces.push((g.s, end, n));
    }
    // Over budget (a long, tight arc): spread the budget by the wanted counts. A point of a
    // curve between two stations h apart (in s) lies within h/2 of one of them, so adding
    // h/2 to the reach keeps every road found; only the projection's first guess is worse.
    let scale = if wanted > budget { budget as f64 / wanted as f64 } else { 1.0 };
    let mut stations = Vec::with_capacity(wanted.min(budget) + 1);
    for &(a, b, n) in &pieces {
        let m = ((n as f64 * scale).floor() as usize).clamp(1, n);
        let slack = if m < n { 0.5 * (b - a) / m as f64 } else { 0.0 };
        stations.extend((0..m).map(|i| (a + (b - a) * i as f64 / m as f64, slack)));
    }
    stations.push((road.length, 0.0));
    stations.retain(|(s, _)| s.is_finite());
    // keep the larger slack of merged stations
    stations.dedup_by(|b, a| {
        let same = (a.0 - b.0).abs() < 1e-9;
        if same {
            a.1 = a.1.max(b.1);
        }
        same
    });
    (stations, scale < 1.0)
}

/// Appends the segments of road `idx`; returns whether it was sampled coarser than wanted.
fn road_segments(idx: usize, road: &Road, budget: usize, out: &mut Vec<Segment>) -> bool {
    let (stations, coarse) = road_stations(road, budget);
    let reach_at = |s: f64| {
        let sec = road.section_index_at(s);
        let l = road.side_border_iter(sec, true, s).last().map_or(0.0, |(_, b)| b.outer.abs());
        let r = road.side_border_iter(sec, false, s).last().map_or(0.0, |(_, b)| b.outer.abs());
        l.max(r).max(road.lane_offset_at(s).abs())
    };
    let mut prev: Option<(f64, f64, f64, f64, f64)> = None;
    for &(s, slack) in &stations {
        let p = road.reference_pose(s);
        let reach = reach_at(s);
        if let Some((s0, x0, y0, r0, slack0)) = prev {
            out.push(Segment { road: idx, s0, s1: s, x0, y0, x1: p.x, y1: p.y, reach: (r0.max(reach) + 2.0).min(MAX_REACH) + slack0 });
        }
        prev = Some((s, p.x, p.y, reach, slack));
    }
    if stations.len() == 1 {
        if let Some((s0, x0, y0, r0, _)) = prev {
            out.push(Segment { road: idx, s0, s1: s0, x0, y0, x1: x0, y1: y0, reach: (r0 + 2.0).min(MAX_REACH) });
        }
    }
    coarse
}

impl SpatialIndex {
    /// Build the index over all roads; also returns the indices of the roads that had to be
    /// sampled coarser than wanted (hostile-input caps, see [`MAX_SAMPLES_PER_ROAD`]).
    pub fn build(roads: &[Road]) -> (SpatialIndex, Vec<usize>) {
        let mut segments = Vec::new();
        let mut coarse = Vec::new();
        for (i, r) in roads.iter().enumerate() {
            let budget = MAX_SAMPLES_PER_ROAD.min(MAX_SEGMENTS.saturating_sub(segments.len()));
            if road_segments(i, r, budget, &mut segments) {
                coarse.push(i);
            }
        }
        (SpatialIndex::grid(segments), coarse)
    }

    /// The grid over `segments`.
    fn grid(segments: Vec<Segment>) -> SpatialIndex {
        let (mut min_x, mut min_y, mut max_x, mut max_y) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for sg in &segments {
            min_x = min_x.min(sg.x0.min(sg.x1) - sg.reach);
            min_y = min_y.min(sg.y0.min(sg.y1) - sg.reach);
            max_x = max_x.max(sg.x0.max(sg.x1) + sg.reach);
            max_y = max_y.max(sg.y0.max(sg.y1) + sg.reach);
        }
        if segments.is_empty() || !(max_x - min_x).is_finite() || !(max_y - min_y).is_finite() {
            return SpatialIndex { segments, cell: 1.0, ..Default::default() };
        }
        let (w, h) = ((max_x - min_x).max(1.0), (max_y - min_y).max(1.0));
        let mut index = SpatialIndex { segments, min_x, min_y, ..Default::default() };
        index.set_cell(8.0f64.max((w * h / MAX_CELLS).sqrt()), w, h);
        // Many wide segments over a small area (a long, tight arc with very wide lanes) would
        // each be entered in thousands of cells: coarsen the grid until the entries fit the
        // budget. Corpus maps stay far below it, so their grid is unchanged.
        let budget = MAX_ENTRIES.max(4 * index.segments.len());
        while index.entry_count() > budget && index.cell < w.max(h) {
            index.set_cell(index.cell * 2.0, w, h);
        }
        // Two passes (count, fill) keep memory compact and the order deterministic.
        let mut counts = vec![0u32; index.nx * index.ny + 1];
        index.for_each_cell_of_segments(|c, _| counts[c] += 1);
        let mut start = Vec::with_capacity(counts.len());
        let mut acc = 0u32;
        for c in &counts {
            start.push(acc);
            acc = acc.saturating_add(*c);
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; acc as usize];
        index.for_each_cell_of_segments(|c, i| {
            if let Some(slot) = fill.get_mut(c) {
                if let Some(item) = items.get_mut(*slot as usize) {
                    *item = i as u32;
                }
                *slot += 1;
            }
        });
        index.cell_start = start;
        index.items = items;
        index
    }

    fn set_cell(&mut self, cell: f64, w: f64, h: f64) {
        self.cell = cell;
        self.nx = (w / cell).ceil() as usize + 1;
        self.ny = (h / cell).ceil() as usize + 1;
    }

    /// Number of (cell, segment) entries the grid would hold with the current cell size.
    fn entry_count(&self) -> usize {
        self.segments.iter().fold(0usize, |acc, sg| {
            let (cx0, cy0) = self.cell_of(sg.x0.min(sg.x1) - sg.reach, sg.y0.min(sg.y1) - sg.reach);
            let (cx1, cy1) = self.cell_of(sg.x0.max(sg.x1) + sg.reach, sg.y0.max(sg.y1) + sg.reach);
            acc.saturating_add((cx1 + 1).saturating_sub(cx0).saturating_mul((cy1 + 1).saturating_sub(cy0)))
        })
    }

    fn for_each_cell_of_segments(&self, mut f: impl FnMut(usize, usize)) {
        for (i, sg) in self.segments.iter().enumerate() {
            let (cx0, cy0) = self.cell_of(sg.x0.min(sg.x1) - sg.reach, sg.y0.min(sg.y1) - sg.reach);
            let (cx1, cy1) = self.cell_of(sg.x0.max(sg.x1) + sg.reach, sg.y0.max(sg.y1) + sg.reach);
            for cy in cy0..=cy1 {
                for cx in cx0..=cx1 {
                    f(cy * self.nx + cx, i);
                }
            }
        }
    }

    fn cell_of(&self, x: f64, y: f64) -> (usize, usize) {
        let cx = ((x - self.min_x) / self.cell).floor().clamp(0.0, (self.nx.max(1) - 1) as f64) as usize;
        let cy = ((y - self.min_y) / self.cell).floor().clamp(0.0, (self.ny.max(1) - 1) as f64) as usize;
        (cx, cy)
    }

    /// First ring (Chebyshev distance in cells) that can touch the grid from (x, y).
    pub fn first_ring(&self, x: f64, y: f64) -> usize {
        let fx = ((x - self.min_x) / self.cell).floor();
        let fy = ((y - self.min_y) / self.cell).floor();
        let (nx, ny) = (self.nx as f64, self.ny as f64);
        let d = (-fx).max(fx - (nx - 1.0)).max(-fy).max(fy - (ny - 1.0)).max(0.0);
        if d.is_finite() {
            d.min(1e9) as usize
        } else {
            usize::MAX
        }
    }

    /// Append the segment indices stored in the ring of cells at Chebyshev distance `ring`
    /// around the cell of (x, y). Returns false once the ring encloses the whole grid
    /// (larger rings add nothing).
    pub fn ring(&self, x: f64, y: f64, ring: usize, out: &mut Vec<u32>) -> bool {
        if self.nx == 0 || self.ny == 0 {
            return false;
        }
        let fx = ((x - self.min_x) / self.cell).floor();
        let fy = ((y - self.min_y) / self.cell).floor();
        if !fx.is_finite() || !fy.is_finite() || ring > 1_000_000_000 {
            return false;
        }
        let (nx, ny) = (self.nx as f64, self.ny as f64);
        let r = ring as f64;
        let mut visit = |cx: f64, cy: f64| {
            if cx >= 0.0 && cy >= 0.0 && cx < nx && cy < ny {
                let c = cy as usize * self.nx + cx as usize;
                let (a, b) = (self.cell_start.get(c).copied().unwrap_or(0), self.cell_start.get(c + 1).copied().unwrap_or(0));
                if let Some(items) = self.items.get(a as usize..b as usize) {
                    out.extend_from_slice(items);
                }
            }
        };
        if ring == 0 {
            visit(fx, fy);
        } else {
            // Only the cells of the ring that fall inside the grid are visited.
            let lo_x = (fx - r).max(-1.0);
            let hi_x = (fx + r).min(nx);
            let mut cx = lo_x;
            while cx <= hi_x {
                visit(cx, fy - r);
                visit(cx, fy + r);
                cx += 1.0;
            }
            let lo_y = (fy - r + 1.0).max(-1.0);
            let hi_y = (fy + r - 1.0).min(ny);
            let mut cy = lo_y;
            while cy <= hi_y {
                visit(fx - r, cy);
                visit(fx + r, cy);
                cy += 1.0;
            }
        }
        !(fx - r <= 0.0 && fx + r >= nx - 1.0 && fy - r <= 0.0 && fy + r >= ny - 1.0)
    }

    /// Size of one grid cell (m).
    pub fn cell_size(&self) -> f64 {
        self.cell
    }

    /// Largest ring index that can still touch the grid from anywhere inside it.
    pub fn max_ring(&self) -> usize {
        self.nx.max(self.ny)
    }
}
