//! Colours and line widths: one place for the look of every picture.

use commonroad::{DynamicObstacleType, EnvironmentObstacleType, StaticObstacleType, TrafficLightColor};

use crate::scene::prim::Rgba;

pub const BACKGROUND: Rgba = Rgba::rgb(247, 247, 242);
pub const ROAD: Rgba = Rgba::rgb(168, 168, 168);
/// A lane border without a marking.
pub const BORDER: Rgba = Rgba::rgb(120, 120, 120);
pub const MARKING: Rgba = Rgba::rgb(255, 255, 255);
pub const CURB: Rgba = Rgba::rgb(70, 70, 70);
pub const STOP_LINE: Rgba = Rgba::rgb(255, 255, 255);
pub const OUTLINE: Rgba = Rgba::rgb(30, 30, 30);
/// The ego vehicle: a colour no other type uses, so tests can find it.
pub const EGO: Rgba = Rgba::rgb(255, 102, 0);
pub const GOAL: Rgba = Rgba::rgb(0, 150, 80);
pub const GOAL_FILL: Rgba = Rgba::rgb(0, 200, 100).with_alpha(60);
pub const SIGN: Rgba = Rgba::rgb(200, 20, 20);
pub const TEXT: Rgba = Rgba::rgb(20, 20, 20);
pub const TEXT_BACKGROUND: Rgba = Rgba::rgb(255, 255, 255).with_alpha(220);

/// Line widths in pixels.
pub const BORDER_WIDTH: f64 = 0.8;
pub const MARKING_WIDTH: f64 = 1.5;
pub const OUTLINE_WIDTH: f64 = 1.0;
pub const EGO_OUTLINE_WIDTH: f64 = 2.0;
/// The ego's path over the whole run (and its legend entry): dashes (on, off) and width in
/// pixels, opacity.
pub const EGO_PATH_DASH: (f64, f64) = (6.0, 4.0);
pub const EGO_PATH_WIDTH: f64 = 2.0;
pub const EGO_PATH_ALPHA: u8 = 200;

/// Dashes of a dashed marking, metres (on, off), drawn at least this many pixels long.
pub const DASH_M: (f64, f64) = (3.0, 3.0);
pub const MIN_DASH_PX: f64 = 3.0;

pub fn dynamic_color(t: DynamicObstacleType) -> Rgba {
    match t {
        DynamicObstacleType::Car => Rgba::rgb(31, 119, 180),
        DynamicObstacleType::Taxi => Rgba::rgb(188, 189, 34),
        DynamicObstacleType::Truck => Rgba::rgb(44, 62, 120),
        DynamicObstacleType::Bus => Rgba::rgb(23, 170, 190),
        DynamicObstacleType::Motorcycle => Rgba::rgb(148, 103, 189),
        DynamicObstacleType::Bicycle => Rgba::rgb(120, 170, 40),
        DynamicObstacleType::Pedestrian => Rgba::rgb(220, 40, 160),
        DynamicObstacleType::PriorityVehicle => Rgba::rgb(214, 39, 40),
        DynamicObstacleType::Train => Rgba::rgb(140, 86, 75),
        DynamicObstacleType::Unknown => Rgba::rgb(110, 110, 110),
    }
}

pub fn static_color(t: StaticObstacleType) -> Rgba {
    match t {
        StaticObstacleType::ParkedVehicle => Rgba::rgb(90, 127, 168),
        StaticObstacleType::ConstructionZone => Rgba::rgb(232, 197, 71),
        StaticObstacleType::RoadBoundary => Rgba::rgb(64, 64, 64),
        StaticObstacleType::Unknown => Rgba::rgb(110, 110, 110),
    }
}

pub fn environment_color(t: EnvironmentObstacleType) -> Rgba {
    match t {
        EnvironmentObstacleType::Building => Rgba::rgb(141, 110, 99),
        EnvironmentObstacleType::Pillar => Rgba::rgb(97, 97, 97),
        EnvironmentObstacleType::MedianStrip => Rgba::rgb(129, 168, 122),
        EnvironmentObstacleType::Unknown => Rgba::rgb(110, 110, 110),
    }
}

pub fn light_color(c: TrafficLightColor) -> Rgba {
    match c {
        TrafficLightColor::Red => Rgba::rgb(230, 0, 0),
        TrafficLightColor::RedYellow => Rgba::rgb(255, 140, 0),
        TrafficLightColor::Yellow => Rgba::rgb(255, 210, 0),
        TrafficLightColor::Green => Rgba::rgb(0, 190, 60),
        TrafficLightColor::Inactive => Rgba::rgb(90, 90, 90),
    }
}

/// The header and footer strips.
pub const STRIP: Rgba = Rgba::rgb(255, 255, 255);
pub const STRIP_LINE: Rgba = Rgba::rgb(190, 190, 190);
/// A storyboard event that has just happened; older ones are in `MUTED` text.
pub const MARK_NEW: Rgba = Rgba::rgb(255, 214, 0);
pub const MUTED: Rgba = Rgba::rgb(90, 90, 90);
/// Labels of road users; the ego's label stands out in a light ego colour.
pub const LABEL_BACKGROUND: Rgba = Rgba::rgb(255, 255, 255).with_alpha(225);
pub const EGO_LABEL_BACKGROUND: Rgba = Rgba::rgb(255, 214, 186);

/// How long an event stays highlighted after it happens, s.
pub const MARK_HIGHLIGHT_S: f64 = 2.0;

/// Pixels per font dot of the text of a picture `width` pixels wide: 2 (capitals 14 px high)
/// from 320 px, 3 from 1800 px, so text stays legible at every size.
pub fn text_dot(width: u32) -> f64 {
    if width >= 1800 {
        3.0
    } else if width >= 320 {
        2.0
    } else {
        1.0
    }
}

/// The text `size` of a picture `width` pixels wide (see [`text_dot`]).
pub fn text_size(width: u32) -> f64 {
    text_dot(width) * crate::font::GLYPH_H as f64
}
