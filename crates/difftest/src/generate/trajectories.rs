//! Trajectories laid along the lane graph from where an entity is: polylines (vertices as
//! World or Lane positions, with or without headings and times), clothoids, clothoid splines
//! and NURBS, with times for a TimeReference; the FollowTrajectoryAction (no timing, or
//! absolute or relative timing with a scale and an offset; following mode position or follow;
//! an initial distance offset) and the TrajectoryPosition.

use super::lanes::{along, walk, walk_length, world, Leg, Place};
use super::{f3, Gen};

impl Gen<'_> {
    /// A point `d` metres along `legs`, `drift` metres to the side, as scenario world
    /// coordinates (x, y, h).
    fn point(&self, legs: &[Leg], d: f64, drift: f64) -> Option<(f64, f64, f64)> {
        let p = along(legs, d)?;
        let (x, y, h) = world(&self.map.net, &p, if p.forward { drift } else { -drift })?;
        Some(self.map.scenario_xyh(x, y, h))
    }

    /// A lateral drift profile: none, a lane change of ±3.5 m over the middle, or a slow sway.
    fn drift_profile(&mut self) -> impl Fn(f64) -> f64 {
        let kind = self.pick_index(3);
        let amp = self.pick(&[-3.5, 3.5, 1.5, -1.0]);
        move |u: f64| match kind {
            0 => 0.0,
            1 => amp * (0.5 - 0.5 * (std::f64::consts::PI * ((u - 0.3) / 0.4).clamp(0.0, 1.0)).cos()),
            _ => amp * (std::f64::consts::PI * u).sin() * 0.5,
        }
    }

    /// A trajectory (its XML) starting at `start` along a walk of `length` metres, with times
    /// counting from `t0` at `speed` m/s.
    pub(crate) fn trajectory_from(&mut self, start: Place, length: f64, t0: f64, speed: f64) -> String {
        let legs = walk(&self.map.net, start, length, &mut self.rng);
        let total = walk_length(&legs).max(1.0);
        let speed = speed.abs().max(2.0);
        let name = self.unique("Trajectory");
        let shape = self.pick(&["Polyline", "Polyline", "Clothoid", "ClothoidSpline", "Nurbs"]);
        self.feature(format!("trajectory:shape/{shape}"));
        let drift = self.drift_profile();
        let time_of = |d: f64| ((t0 + d / speed) * 100.0).round() / 100.0;
        let body = match shape {
            "Clothoid" => {
                let (x, y, h) = self.point(&legs, 0.0, 0.0).unwrap_or((0.0, 0.0, 0.0));
                let curvature = self.pick(&[0.0, 0.004, -0.004, 0.01, -0.02]);
                let prime = self.pick(&[0.0, 0.0002, -0.0003]);
                let len = self.num(30.0, total.clamp(31.0, 150.0));
                let stop = time_of(len);
                // 1.0 spells the curvature's rate `curvatureDot`
                let prime_word = if self.since(1) { "curvaturePrime" } else { "curvatureDot" };
                format!(
                    r#"<Clothoid curvature="{curvature}" {prime_word}="{prime}" length="{len}" startTime="{}" stopTime="{stop}"><Position><WorldPosition x="{}" y="{}" h="{}"/></Position></Clothoid>"#,
                    time_of(0.0),
                    f3(x),
                    f3(y),
                    f3(h)
                )
            }
            "ClothoidSpline" => {
                let (x, y, h) = self.point(&legs, 0.0, 0.0).unwrap_or((0.0, 0.0, 0.0));
                let n = 1 + self.pick_index(3);
                let mut segments = String::new();
                let mut d = 0.0;
                let mut k = 0.0;
                for i in 0..n {
                    let len = self.num(20.0, 70.0);
                    let k1 = self.pick(&[0.0, 0.01, -0.01, 0.005]);
                    let start = if i == 0 {
                        format!(r#"<PositionStart><WorldPosition x="{}" y="{}" h="{}"/></PositionStart>"#, f3(x), f3(y), f3(h))
                    } else {
                        String::new()
                    };
                    segments.push_str(&format!(
                        r#"<ClothoidSplineSegment curvatureStart="{k}" curvatureEnd="{k1}" length="{len}" timeStart="{}">{start}</ClothoidSplineSegment>"#,
                        time_of(d)
                    ));
                    d += len;
                    k = k1;
                }
                format!(r#"<ClothoidSpline timeEnd="{}">{segments}</ClothoidSpline>"#, time_of(d))
            }
            "Nurbs" => {
                let order = 2 + self.pick_index(3) as u32;
                let n = order as usize + 1 + self.pick_index(4);
                let mut points = String::new();
                for i in 0..n {
                    let u = i as f64 / (n - 1) as f64;
                    let (x, y, h) = self.point(&legs, u * total, drift(u)).unwrap_or((0.0, 0.0, 0.0));
                    let weight = if self.chance(0.2) { self.num(0.5, 2.0) } else { 1.0 };
                    let heading = if self.chance(0.5) { format!(r#" h="{}""#, f3(h)) } else { String::new() };
                    points.push_str(&format!(
                        r#"<ControlPoint time="{}" weight="{weight}"><Position><WorldPosition x="{}" y="{}"{heading}/></Position></ControlPoint>"#,
                        time_of(u * total),
                        f3(x),
                        f3(y)
                    ));
                }
                // a clamped knot vector: `order` zeros, evenly spaced inner knots, `order` ends
                let inner = n - order as usize;
                let knots: Vec<f64> = (0..n + order as usize)
                    .map(|i| {
                        if i < order as usize {
                            0.0
                        } else if i >= n {
                            (inner + 1) as f64
                        } else {
                            (i + 1 - order as usize) as f64
                        }
                    })
                    .collect();
                let knots: String = knots.iter().map(|k| format!(r#"<Knot value="{k}"/>"#)).collect();
                format!(r#"<Nurbs order="{order}">{points}{knots}</Nurbs>"#)
            }
            _ => {
                let n = 2 + self.pick_index(6);
                let headings = self.chance(0.5);
                self.feature(format!("trajectory:polyline/{}", if headings { "vertex-headings" } else { "no-headings" }));
                let mut vertices = String::new();
                for i in 0..n {
                    let u = i as f64 / (n - 1) as f64;
                    let d = u * total;
                    let position = if self.chance(0.15) {
                        self.feature("trajectory:polyline/lane-vertex");
                        let p = along(&legs, d).unwrap_or(start);
                        self.lane_position_xml(&p, 0.0, "")
                    } else {
                        let (x, y, h) = self.point(&legs, d, drift(u)).unwrap_or((0.0, 0.0, 0.0));
                        let heading = if headings { format!(r#" h="{}""#, f3(h)) } else { String::new() };
                        format!(r#"<WorldPosition x="{}" y="{}"{heading}/>"#, f3(x), f3(y))
                    };
                    vertices.push_str(&format!(r#"<Vertex time="{}"><Position>{position}</Position></Vertex>"#, time_of(d)));
                }
                format!("<Polyline>{vertices}</Polyline>")
            }
        };
        format!(r#"<Trajectory name="{name}" closed="false"><ParameterDeclarations/><Shape>{body}</Shape></Trajectory>"#)
    }

    /// A FollowTrajectoryAction for `actor`, started at about time `t_start`.
    pub(crate) fn follow_trajectory_action(&mut self, actor: &str, t_start: f64) -> String {
        let start = self.place_of(actor);
        let speed = self.entity(actor).map_or(10.0, |e| e.speed).abs().max(3.0);
        let length = self.num(40.0, 250.0);
        let timing = self.pick(&["none", "none", "absolute", "relative"]);
        self.feature(format!("trajectory:time-reference/{timing}"));
        let t0 = if timing == "absolute" { (t_start * 100.0).round() / 100.0 } else { 0.0 };
        if timing == "absolute" {
            // its times are the simulation's: the event starts when they begin
            let rule = self.rule_word("greaterOrEqual");
            self.forced_condition = Some(format!(
                r#"<Condition name="timed" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{t0}" rule="{rule}"/></ByValueCondition></Condition>"#
            ));
        }
        let traj = self.trajectory_from(start, length, t0, speed);
        let time_reference = match timing {
            "none" => "<None/>".to_string(),
            _ => {
                let scale = if self.chance(0.4) { self.num(0.5, 2.0) } else { 1.0 };
                let offset = if self.chance(0.4) { self.num(-1.0, 3.0) } else { 0.0 };
                if scale != 1.0 {
                    self.feature("trajectory:timing-scale");
                }
                if offset != 0.0 {
                    self.feature("trajectory:timing-offset");
                }
                format!(r#"<Timing domainAbsoluteRelative="{timing}" scale="{scale}" offset="{offset}"/>"#)
            }
        };
        let mode = self.pick(&["position", "follow"]);
        self.feature(format!("trajectory:following-mode/{mode}"));
        let offset = if self.chance(0.25) {
            let offset = format!(r#" initialDistanceOffset="{}""#, self.num(0.0, 30.0));
            if self.since(1) {
                self.feature("trajectory:initial-distance-offset");
                offset
            } else {
                String::new()
            }
        } else {
            String::new()
        };
        // 1.0 has the trajectory itself where 1.1 wraps it in a TrajectoryRef
        let traj = if self.since(1) { format!("<TrajectoryRef>{traj}</TrajectoryRef>") } else { traj };
        format!(
            r#"<PrivateAction><RoutingAction><FollowTrajectoryAction{offset}>{traj}<TimeReference>{time_reference}</TimeReference><TrajectoryFollowingMode followingMode="{mode}"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#
        )
    }

    /// A TrajectoryPosition on a trajectory through (or near) `place`.
    pub(crate) fn trajectory_position_at(&mut self, place: &Place, prefix: &str) -> String {
        self.feature(format!("{prefix}TrajectoryPosition"));
        let back = self.num(0.0, 40.0);
        let len = self.map.net.roads.get(place.road).map_or(0.0, |r| r.length);
        let s0 = if place.forward { place.s - back } else { place.s + back }.clamp(0.5, (len - 0.5).max(0.5));
        let start = Place { s: s0, ..*place };
        let s = (place.s - s0).abs();
        let extra = self.num(30.0, 120.0);
        let traj = self.trajectory_from(start, s + extra, 0.0, 10.0);
        let t = if self.chance(0.3) { self.num(-1.5, 1.5) } else { 0.0 };
        format!(r#"<TrajectoryPosition s="{}" t="{t}"><TrajectoryRef>{traj}</TrajectoryRef></TrajectoryPosition>"#, f3(s))
    }
}
