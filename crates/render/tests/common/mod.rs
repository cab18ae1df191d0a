//! A hand-built scenario whose picture geometry is known in closed form.
#![allow(dead_code)]

use commonroad::*;

/// One straight lanelet (0,0)–(100,0) right, (0,4)–(100,4) left; a car (the ego) from x=20
/// at 10 m/s for `steps` steps at y=2; a pedestrian; the planning problem starting at the car.
pub(crate) fn straight(steps: u64) -> (Scenario, PlanningProblemSet) {
    let header = Header {
        benchmark_id: BenchmarkId::parse("ZAM_Test-1_1_T-1").unwrap(),
        date: Date::new(2026, 1, 1).unwrap(),
        author: "t".into(),
        affiliation: "".into(),
        source: "".into(),
        time_step_size: 0.1,
    };
    let mut s = Scenario::new(header);
    let mut ids = IdAllocator::new();
    let bounds = LaneletBounds::new(vec![Point::new(0.0, 4.0), Point::new(100.0, 4.0)], vec![Point::new(0.0, 0.0), Point::new(100.0, 0.0)]).unwrap();
    let lane = ids.lanelet();
    let mut l = Lanelet::new(lane, bounds, LaneletType::Urban);
    l.left_marking = Some(LineMarking::Solid);
    l.right_marking = Some(LineMarking::Dashed);
    s.network.lanelets.push(l);
    let st = |t: u64, x: f64, y: f64, h: f64| State { time_step: t, x, y, orientation: h, velocity: 10.0, acceleration: 0.0, yaw_rate: 0.0 };
    let ego = ids.obstacle();
    s.dynamic_obstacles.push(DynamicObstacle {
        id: ego,
        obstacle_type: DynamicObstacleType::Car,
        shape: Shape::rectangle(4.5, 1.8).unwrap(),
        initial_state: st(0, 20.0, 2.0, 0.0),
        trajectory: (1..=steps).map(|t| st(t, 20.0 + t as f64, 2.0, 0.0)).collect(),
    });
    s.dynamic_obstacles.push(DynamicObstacle {
        id: ids.obstacle(),
        obstacle_type: DynamicObstacleType::Pedestrian,
        shape: Shape::circle(0.5).unwrap(),
        initial_state: st(0, 60.0, 0.5, std::f64::consts::FRAC_PI_2),
        trajectory: (1..=steps).map(|t| st(t, 60.0, 0.5 + 0.01 * t as f64, std::f64::consts::FRAC_PI_2)).collect(),
    });
    let problems = PlanningProblemSet {
        problems: vec![PlanningProblem {
            id: ids.planning_problem(),
            initial_state: PlanningInitialState { x: 20.0, y: 2.0, orientation: 0.0, velocity: 10.0, yaw_rate: 0.0, slip_angle: 0.0, acceleration: None },
            goal_states: vec![GoalState {
                time: TimeInterval::new(1, 50).unwrap(),
                position: Some(GoalPosition::Rectangles(vec![PlacedRectangle {
                    rectangle: Rectangle::new(10.0, 4.0).unwrap(),
                    center: Point::new(90.0, 2.0),
                    orientation: 0.0,
                }])),
                orientation: None,
                velocity: None,
            }],
        }],
    };
    (s, problems)
}

/// Options showing the whole map of [`straight`] at `time`.
pub(crate) fn whole(time: f64) -> render::RenderOptions {
    render::RenderOptions { time, frame: render::Frame::WholeMap, ..Default::default() }
}

/// Where world (x, y) lands in the picture `layout` describes.
pub(crate) fn px_of(layout: &render::Layout, x: f64, y: f64) -> (u32, u32) {
    let px = (x - layout.world.min_x) * layout.scale;
    let py = layout.map.y0 + (layout.world.max_y - y) * layout.scale;
    (px as u32, py as u32)
}

/// Where world (x, y) lands in the 1200-px whole-map picture of [`straight`], by hand: the
/// content spans x 0..100 (margin 2 + 5 % of 100 = 7 m → 114 m wide, 1200/114 px/m) and is
/// far flatter than the minimal aspect 1/4, so the map area is 300 px high, centred on y = 2,
/// below the header strip of `header` pixels.
pub(crate) fn straight_px(x: f64, y: f64, header: f64) -> (u32, u32) {
    let scale = 1200.0 / 114.0;
    let left = 50.0 - 57.0;
    let top = 2.0 + 150.0 / scale;
    (((x - left) * scale) as u32, (header + (top - y) * scale) as u32)
}

pub(crate) fn decode_png(bytes: &[u8]) -> tiny_skia::Pixmap {
    tiny_skia::Pixmap::decode_png(bytes).expect("a PNG")
}

pub(crate) fn pixel(pm: &tiny_skia::Pixmap, (x, y): (u32, u32)) -> [u8; 3] {
    let c = pm.pixel(x, y).expect("inside").demultiply();
    [c.red(), c.green(), c.blue()]
}

pub(crate) fn rgb(c: render::scene::prim::Rgba) -> [u8; 3] {
    [c.r, c.g, c.b]
}
