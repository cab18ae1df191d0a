//! The kinds of road user a generated scenario holds, with the name prefix that labels them
//! and the length of their bounding box (what placing them on a lane needs).

/// The kind of an entity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EntityKind {
    Car,
    Truck,
    Bicycle,
    Pedestrian,
    Misc,
    Trailer,
}

impl EntityKind {
    /// Its name prefix and feature label.
    pub fn label(self) -> &'static str {
        match self {
            EntityKind::Car => "car",
            EntityKind::Truck => "truck",
            EntityKind::Bicycle => "bicycle",
            EntityKind::Pedestrian => "pedestrian",
            EntityKind::Misc => "misc",
            EntityKind::Trailer => "trailer",
        }
    }
    /// Length of its bounding box, m.
    pub fn length(self) -> f64 {
        match self {
            EntityKind::Car => 5.04,
            EntityKind::Truck => 8.5,
            EntityKind::Bicycle => 1.9,
            EntityKind::Pedestrian => 0.6,
            EntityKind::Misc => 2.0,
            EntityKind::Trailer => 4.5,
        }
    }
}
