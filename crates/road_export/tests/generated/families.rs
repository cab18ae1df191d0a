//! The shapes real maps have, each drawn with random parameters: roads on lines, arcs,
//! clothoids and S-bends with lane widths varying and lanes appearing or ending, both
//! directions side by side; recorded-map chains of many short pieces with irregular, noisy
//! points and slanted cuts; forks and merges from one cross-section; off- and on-ramps; T- and
//! 4-way intersections whose arms end on slanted or bowed cross-sections; roundabout rings.

use super::builder::*;
use commonroad::*;
use std::f64::consts::PI;

/// A family of shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Family {
    Road,
    Recorded,
    Fork,
    Merge,
    OffRamp,
    OnRamp,
    TJunction,
    Crossing,
    Roundabout,
}

pub(crate) const FAMILIES: [Family; 9] =
    [Family::Road, Family::Recorded, Family::Fork, Family::Merge, Family::OffRamp, Family::OnRamp, Family::TJunction, Family::Crossing, Family::Roundabout];

/// A random curvature profile of about `len` m: a line, an arc, a clothoid, an S-bend or a
/// sequence (radii never below `min_radius`).
fn profile(rng: &mut Rng, len: f64, min_radius: f64) -> (Vec<(f64, f64, f64)>, &'static str) {
    let k = |rng: &mut Rng| rng.sign() / rng.range(min_radius, 6.0 * min_radius);
    match rng.int(0, 4) {
        0 => (vec![(len, 0.0, 0.0)], "line"),
        1 => {
            let kk = k(rng);
            (vec![(len, kk, kk)], "arc")
        }
        2 => (vec![(len, 0.0, k(rng))], "clothoid"),
        3 => {
            let kk = k(rng).abs();
            (vec![(len / 4.0, 0.0, kk), (len / 4.0, kk, 0.0), (len / 4.0, 0.0, -kk), (len / 4.0, -kk, 0.0)], "S-bend")
        }
        _ => {
            let (a, b) = (k(rng), k(rng));
            (vec![(len / 3.0, 0.0, 0.0), (len / 3.0, a, a), (len / 3.0, a, b)], "line-arc-clothoid")
        }
    }
}

/// How points are placed: regular (hand-made and converted maps) or recorded (irregular,
/// noisy, twins).
fn style(rng: &mut Rng, recorded: bool) -> Style {
    if recorded {
        Style { spacing: (0.5, 10.0), noise: rng.range(0.0, 0.004), twins: rng.range(0.0, 0.1) }
    } else {
        let d = rng.range(1.0, 5.0);
        Style { spacing: (d, d), noise: 0.0, twins: 0.0 }
    }
}

/// Cuts along `len`: `pieces` pieces; with `short`, some shorter than 1 m.
fn cuts(rng: &mut Rng, len: f64, pieces: usize, short: bool) -> Vec<f64> {
    let mut w: Vec<f64> = (0..pieces).map(|_| if short && rng.chance(0.15) { rng.range(0.02, 0.1) } else { rng.range(0.5, 1.5) }).collect();
    let total: f64 = w.iter().sum();
    w.iter_mut().for_each(|x| *x *= len / total);
    // pieces shorter than 1 m stay short after the scaling only if asked
    let mut out = vec![0.0];
    for x in w {
        out.push(out.last().copied().unwrap_or(0.0) + if short && x < 0.1 * len / pieces as f64 { rng.range(0.3, 0.95) } else { x });
    }
    let end = out.last().copied().unwrap_or(len);
    out.iter_mut().for_each(|c| *c *= len / end);
    out
}

/// Slant (tan of the angle) and bow per cut; the first and last only when `ends`.
fn slants(rng: &mut Rng, cuts: &[f64], width: f64, ends: bool) -> Vec<(f64, f64)> {
    (0..cuts.len())
        .map(|k| {
            let inner = k > 0 && k + 1 < cuts.len();
            if !(inner || ends) || rng.chance(0.5) {
                return (0.0, 0.0);
            }
            // the shift must stay well inside the pieces beside the cut
            let room = [k.checked_sub(1).map(|j| cuts[k] - cuts[j]), cuts.get(k + 1).map(|c| c - cuts[k])].into_iter().flatten().fold(f64::INFINITY, f64::min);
            let most = (0.3 * room / (0.5 * width)).min(0.6);
            let bow = if rng.chance(0.3) { rng.range(-0.03, 0.03) } else { 0.0 };
            (rng.range(-most, most), bow.clamp(-0.3 * room / (0.25 * width * width), 0.3 * room / (0.25 * width * width)))
        })
        .collect()
}

fn lane(rng: &mut Rng, reversed: bool, pieces: usize, vary: bool) -> LaneSpec {
    let w0 = rng.range(2.6, 4.2);
    let w1 = if vary { (w0 + rng.range(-1.0, 1.0)).clamp(2.3, 4.8) } else { w0 };
    LaneSpec { w0, w1, reversed, first: 0, last: pieces - 1, taper_in: None, taper_out: None }
}

/// Lanes: `fwd` forward on the right, `back` reversed on the left; with `vary`, widths change
/// along the road and the outermost forward lane may appear or end at a cut.
fn lanes(rng: &mut Rng, fwd: usize, back: usize, pieces: usize, vary: bool, cuts: &[f64]) -> Vec<LaneSpec> {
    let mut v: Vec<LaneSpec> = (0..fwd + back).map(|i| lane(rng, i >= fwd, pieces, vary)).collect();
    if vary && fwd > 1 && pieces > 2 && rng.chance(0.5) {
        let l = &mut v[0];
        if rng.chance(0.5) {
            l.first = rng.int(1, pieces - 1);
            if rng.chance(0.5) {
                l.taper_in = Some((cuts[l.first + 1] - cuts[l.first]).min(40.0) * 0.8);
            }
        } else {
            l.last = rng.int(0, pieces - 2);
            if rng.chance(0.5) {
                l.taper_out = Some((cuts[l.last + 1] - cuts[l.last]).min(40.0) * 0.8);
            }
        }
    }
    v
}

/// Draws one network of `family`; its description names the shape and its parameters.
pub(crate) fn draw(rng: &mut Rng, family: Family) -> (LaneletNetwork, String) {
    let mut net = Net::new();
    let recorded = family == Family::Recorded || rng.chance(0.3);
    let st = style(rng, recorded);
    let what = match family {
        Family::Road | Family::Recorded => road(rng, &mut net, st, family == Family::Recorded),
        Family::Fork | Family::Merge => split(rng, &mut net, st, true),
        Family::OffRamp | Family::OnRamp => split(rng, &mut net, st, false),
        Family::TJunction => junction(rng, &mut net, st, 3),
        Family::Crossing => junction(rng, &mut net, st, 4),
        Family::Roundabout => roundabout(rng, &mut net, st),
    };
    if matches!(family, Family::Merge | Family::OnRamp) {
        reverse(&mut net.net);
    }
    net.place(rng.range(-PI, PI), rng.range(-2000.0, 2000.0), rng.range(-2000.0, 2000.0));
    let how = if recorded { format!(", recorded points (noise {:.1} mm, twins {:.0} %)", 1000.0 * st.noise, 100.0 * st.twins) } else { String::new() };
    (net.net, format!("{family:?}: {what}{how}"))
}

fn road(rng: &mut Rng, net: &mut Net, st: Style, short: bool) -> String {
    let len = rng.range(40.0, 250.0);
    let (fwd, back) = (rng.int(1, 4), rng.int(0, 3));
    let width = 4.0 * (fwd + back) as f64;
    let (segs, shape) = profile(rng, len, (2.0 * width).max(25.0));
    let pieces = if short { rng.int(5, 25) } else { rng.int(1, 5) };
    let c = cuts(rng, len, pieces, short);
    let path = Path::new((0.0, 0.0, 0.0), &segs);
    let c: Vec<f64> = c.iter().map(|x| x * path.len() / len).collect();
    let ls = lanes(rng, fwd, back, pieces, true, &c);
    let appear = if ls[0].first > 0 || ls[0].last + 1 < pieces { ", a lane appearing/ending" } else { "" };
    let slant = slants(rng, &c, width, true);
    let spec = RoadSpec { path, lanes: ls, cuts: c, slant, style: st, start_points: None, end_points: None, kind: LaneletType::Urban };
    net.road(rng, &spec);
    format!("{shape} {len:.0} m, {fwd}+{back} lanes, {pieces} pieces{appear}")
}

/// A road whose rightmost lane forks (also continuing: `fork`) or turns off as a ramp, from
/// one cross-section; the rest of the lanes go on as another road.
fn split(rng: &mut Rng, net: &mut Net, st: Style, fork: bool) -> String {
    let fwd = rng.int(if fork { 1 } else { 2 }, 3);
    let len = rng.range(30.0, 120.0);
    let (segs, shape) = profile(rng, len, 40.0);
    let path = Path::new((0.0, 0.0, 0.0), &segs);
    let pieces = rng.int(1, 3);
    let c: Vec<f64> = cuts(rng, path.len(), pieces, false);
    let ls = lanes(rng, fwd, 0, pieces, false, &c);
    let slant = slants(rng, &c, 4.0 * fwd as f64, false);
    let widths: Vec<f64> = ls.iter().map(|l| l.w1).collect();
    let a = net.road(rng, &RoadSpec { path, lanes: ls, cuts: c, slant, style: st, start_points: None, end_points: None, kind: LaneletType::Highway });
    let (ex, ey) = a.end[fwd];
    // the main road goes on (all lanes for a fork, the others for a ramp)
    let keep = if fork { 0 } else { 1 };
    let len_b = rng.range(30.0, 100.0);
    let k_b = if fork { rng.range(0.0, 1.0 / 200.0) } else { rng.range(-1.0 / 300.0, 1.0 / 300.0) };
    let path_b = Path::new((ex, ey, a.heading_end), &[(len_b, 0.0, k_b)]);
    let lanes_b: Vec<LaneSpec> = widths[keep..].iter().map(|&w| LaneSpec::plain(w, false)).collect();
    let b = net.road(rng, &RoadSpec { start_points: Some(a.end[keep..].to_vec()), ..RoadSpec::whole(path_b, len_b, lanes_b, st, LaneletType::Highway) });
    for i in keep..fwd {
        if let (Some(x), Some(y)) = (a.at(i, true), b.at(i - keep, false)) {
            net.link(x, y);
        }
    }
    // the branch: the rightmost lane's cross-section, bending right
    let w = widths[0];
    let (mx, my) = a.end[1];
    let radius = rng.range(40.0, 150.0);
    let straight = if fork { 0.0 } else { rng.range(0.0, 20.0) };
    let turn = rng.range(0.3, 1.2) * radius;
    let lane_r = LaneSpec::plain(w, false);
    // the branch's reference line is its left edge (its lane lies on the right)
    let path_r =
        Path::new((mx, my, a.heading_end), &[(straight + 0.1, 0.0, 0.0), (turn * 0.4, 0.0, -1.0 / radius), (turn * 0.6, -1.0 / radius, -1.0 / radius)]);
    let len_r = path_r.len();
    let r = net.road(
        rng,
        &RoadSpec {
            path: path_r,
            lanes: vec![lane_r],
            cuts: vec![0.0, len_r],
            slant: vec![],
            style: st,
            start_points: Some(a.end[0..2].to_vec()),
            end_points: None,
            kind: LaneletType::Highway,
        },
    );
    if let (Some(x), Some(y)) = (a.at(0, true), r.at(0, false)) {
        net.link(x, y);
    }
    format!("{shape} {len:.0} m, {fwd} lanes, {} radius {radius:.0} m", if fork { "the right lane forks" } else { "ramp" })
}

/// A `n_arms`-way intersection: arms of 1–2 lanes each way ending on slanted or bowed
/// cross-sections, connecting lanelets from every incoming lane to the other arms.
fn junction(rng: &mut Rng, net: &mut Net, st: Style, n_arms: usize) -> String {
    let (fwd, back) = (rng.int(1, 2), rng.int(1, 2));
    let r0 = rng.range(7.0, 14.0) + 2.0 * (fwd + back) as f64;
    let base: Vec<f64> = if n_arms == 3 { vec![0.0, 0.5 * PI, PI] } else { vec![0.0, 0.5 * PI, PI, 1.5 * PI] };
    let jitter = if n_arms == 3 { 0.35 } else { 0.25 };
    let angles: Vec<f64> = base.iter().map(|a| a + rng.range(-jitter, jitter)).collect();
    let mut arms = Vec::new();
    for &th in &angles {
        let len = rng.range(20.0, 60.0);
        let start = (th.cos() * (r0 + len), th.sin() * (r0 + len), th + PI);
        let bend = rng.range(-1.0 / 300.0, 1.0 / 300.0);
        let path = Path::new(start, &[(len, bend, bend)]);
        let pieces = rng.int(1, 2);
        let c = cuts(rng, path.len(), pieces, false);
        let mut slant = slants(rng, &c, 4.0 * (fwd + back) as f64, true);
        if let Some(last) = slant.last_mut() {
            if rng.chance(0.6) {
                *last = (rng.range(-0.4, 0.4), if rng.chance(0.4) { rng.range(-0.02, 0.02) } else { 0.0 });
            }
        }
        let ls = lanes(rng, fwd, back, pieces, false, &c);
        arms.push(net.road(rng, &RoadSpec { path, lanes: ls, cuts: c, slant, style: st, start_points: None, end_points: None, kind: LaneletType::Urban }));
    }
    let mut ids = IdAllocator::starting_at(1_000_000);
    let mut incomings = Vec::new();
    for (a, arm) in arms.iter().enumerate() {
        let mut inc = Incoming {
            id: ids.incoming(),
            incoming_lanelets: (0..fwd).filter_map(|i| arm.at(i, true)).collect(),
            successors_right: vec![],
            successors_straight: vec![],
            successors_left: vec![],
            is_left_of: None,
        };
        for (b, other) in arms.iter().enumerate() {
            if a == b {
                continue;
            }
            let turn = (angles[b] - angles[a] - PI + 3.0 * PI).rem_euclid(2.0 * PI) - PI;
            // (incoming lane, outgoing lane) pairs: outgoing lanes are the reversed ones, the
            // leftmost (from the driver's seat) next to the centre
            let pairs: Vec<(usize, usize)> = if turn < -0.5 {
                vec![(0, fwd + back - 1)]
            } else if turn > 0.5 {
                vec![(fwd - 1, fwd)]
            } else {
                (0..fwd.min(back)).map(|k| (fwd - 1 - k, fwd + k)).collect()
            };
            for (i, o) in pairs {
                let (Some(x), Some(y)) = (arm.at(i, true), other.at(o, false)) else { continue };
                let (Some((from, h0)), Some((to, h1))) = (net.cross_section(x, true), net.cross_section(y, false)) else { continue };
                let n = rng.int(4, 20);
                let Some(c) = net.hermite(from, h0, to, h1, n, LaneletType::Intersection) else { continue };
                net.link(x, c);
                net.link(c, y);
                if turn < -0.5 {
                    inc.successors_right.push(c);
                } else if turn > 0.5 {
                    inc.successors_left.push(c);
                } else {
                    inc.successors_straight.push(c);
                }
            }
        }
        incomings.push(inc);
    }
    net.net.intersections.push(Intersection { id: ids.intersection(), incomings, crossings: vec![] });
    format!("{n_arms} arms, {fwd}+{back} lanes, radius {r0:.0} m")
}

/// A one- or two-lane ring (counter-clockwise) with 3–4 arms; entries and exits are
/// connecting lanelets that merge into / fork from the outer ring lane at a cross-section.
fn roundabout(rng: &mut Rng, net: &mut Net, st: Style) -> String {
    let ring_lanes = rng.int(1, 2);
    let radius = rng.range(14.0, 35.0);
    let n_arms = rng.int(3, 4);
    let w = rng.range(3.5, 4.5);
    let gap = rng.range(6.0, 12.0);
    let delta = ((gap + w) / radius).min(0.6);
    let arm_angles: Vec<f64> = (0..n_arms).map(|k| 2.0 * PI * k as f64 / n_arms as f64 + rng.range(-0.15, 0.15) + 0.5).collect();
    // ring nodes: exit at θ − δ, entry at θ + δ; the ring's path is its inner edge
    let mut nodes: Vec<f64> = arm_angles.iter().flat_map(|&a| [a - delta, a + delta]).collect();
    nodes.sort_by(f64::total_cmp);
    let circ = 2.0 * PI * radius;
    let path = Path::new((radius * nodes[0].cos(), radius * nodes[0].sin(), nodes[0] + 0.5 * PI), &[(circ, 1.0 / radius, 1.0 / radius)]);
    let mut c: Vec<f64> = nodes.iter().map(|a| (a - nodes[0]) * radius).collect();
    c.push(path.len());
    let pieces = c.len() - 1;
    let ring_lane = |_: usize| LaneSpec { w0: w, w1: w, reversed: false, first: 0, last: pieces - 1, taper_in: None, taper_out: None };
    // inner edge = path: every lane is on its right (forward lanes end at the path)
    let spec = RoadSpec {
        path,
        lanes: (0..ring_lanes).map(ring_lane).collect(),
        cuts: c.clone(),
        slant: vec![],
        style: st,
        start_points: None,
        end_points: None,
        kind: LaneletType::Urban,
    };
    let mut spec = spec;
    // close the ring: the last cross-section is the first
    let first: Vec<P> = (0..=ring_lanes).map(|b| spec.path.at(0.0, -w * (ring_lanes - b) as f64)).collect();
    spec.start_points = Some(first.clone());
    spec.end_points = Some(first);
    let ring = net.road(rng, &spec);
    if let (Some(a), Some(b)) = (ring.ids[0][pieces - 1], ring.ids[0][0]) {
        net.link(a, b);
    }
    if ring_lanes == 2 {
        if let (Some(a), Some(b)) = (ring.ids[1][pieces - 1], ring.ids[1][0]) {
            net.link(a, b);
        }
    }
    let piece_at = |ang: f64| c.iter().position(|&x| (x - (ang - nodes[0]) * radius).abs() < 1e-6);
    for &th in &arm_angles {
        let len = rng.range(20.0, 50.0);
        let r_end = radius + gap;
        let start = (th.cos() * (r_end + len), th.sin() * (r_end + len), th + PI);
        let arm_path = Path::new(start, &[(len, 0.0, 0.0)]);
        let ls = vec![LaneSpec::plain(w, false), LaneSpec::plain(w, true)];
        let arm = net.road(rng, &RoadSpec::whole(arm_path, len, ls, st, LaneletType::Urban));
        let (Some(k_exit), Some(k_entry)) = (piece_at(th - delta), piece_at(th + delta)) else { continue };
        // the outer ring lane is lane 0
        let into = ring.ids[0][k_entry % pieces];
        let before_entry = ring.ids[0][(k_entry + pieces - 1) % pieces];
        let out_of = ring.ids[0][(k_exit + pieces - 1) % pieces];
        if let (Some(inbound), Some(into), Some(_)) = (arm.at(0, true), into, before_entry) {
            if let (Some((from, h0)), Some((to, h1))) = (net.cross_section(inbound, true), net.cross_section(into, false)) {
                if let Some(e) = net.hermite(from, h0, to, h1, rng.int(5, 15), LaneletType::Urban) {
                    net.link(inbound, e);
                    net.link(e, into);
                }
            }
        }
        if let (Some(outbound), Some(out_of)) = (arm.at(1, false), out_of) {
            if let (Some((from, h0)), Some((to, h1))) = (net.cross_section(out_of, true), net.cross_section(outbound, false)) {
                if let Some(x) = net.hermite(from, h0, to, h1, rng.int(5, 15), LaneletType::Urban) {
                    net.link(out_of, x);
                    net.link(x, outbound);
                }
            }
        }
    }
    format!("{ring_lanes}-lane ring radius {radius:.0} m, {n_arms} arms")
}

/// Every lanelet driven the other way (a fork becomes a merge, an off-ramp an on-ramp): the
/// bounds reversed and swapped, links and sides swapped.
fn reverse(net: &mut LaneletNetwork) {
    for l in &mut net.lanelets {
        let rev = |v: &[Point]| v.iter().rev().copied().collect::<Vec<_>>();
        if let Ok(b) = LaneletBounds::new(rev(l.bounds.right()), rev(l.bounds.left())) {
            l.bounds = b;
        }
        std::mem::swap(&mut l.successors, &mut l.predecessors);
        std::mem::swap(&mut l.adjacent_left, &mut l.adjacent_right);
    }
}
