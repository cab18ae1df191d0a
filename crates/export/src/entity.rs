//! CommonRoad obstacles as OpenSCENARIO entities: DESIGN.md's Table I read backwards (car →
//! Vehicle car, truck → truck, pedestrian → Pedestrian, building → MiscObject building, …), the
//! shape as a bounding box whose centre is the entity's reference point.
//!
//! The reference point is the box centre, for every entity (BoundingBox `Center` (0, 0,
//! height/2), the rear axle at the reference point): a CommonRoad position *is* the box centre,
//! so a trajectory vertex is the CommonRoad position itself, whatever heading a simulator gives
//! the entity between vertices (esmini blends headings at polyline corners), and the forward
//! conversion, which adds the rotated centre offset to the reference point, gives the centre
//! back exactly. CommonRoad has no axle positions, so nothing is lost by not putting the
//! reference point on a rear axle. A polygon becomes its bounding box in the obstacle's frame,
//! its reference point that box's centre; a circle (a pedestrian's) the square whose half
//! diagonal is the radius, so that the forward conversion's circle (half the box diagonal) is
//! the same circle. CommonRoad has no heights: each kind gets a typical one.

use commonroad::{DynamicObstacleType, EnvironmentObstacleType, Shape, StaticObstacleType};

use crate::options::OscVersion;
use crate::xml::El;

/// The OpenSCENARIO object an obstacle becomes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Object {
    /// `Vehicle` of this `vehicleCategory`.
    Vehicle(&'static str),
    Pedestrian,
    /// `MiscObject` of this `miscObjectCategory`.
    Misc(&'static str),
}

/// The CommonRoad element an entity came from, for the names and the type property.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Element {
    Dynamic(DynamicObstacleType),
    Static(StaticObstacleType),
    Environment(EnvironmentObstacleType),
}

impl Element {
    /// The CommonRoad type as the XSD spells it.
    pub(crate) fn type_name(self) -> &'static str {
        match self {
            Element::Dynamic(t) => t.as_str(),
            Element::Static(t) => t.as_str(),
            Element::Environment(t) => t.as_str(),
        }
    }

    fn element_name(self) -> &'static str {
        match self {
            Element::Dynamic(_) => "dynamicObstacle",
            Element::Static(_) => "staticObstacle",
            Element::Environment(_) => "environmentObstacle",
        }
    }

    /// Table I backwards. Types OpenSCENARIO has no kind for (taxi, priority vehicle, parked
    /// vehicle) become the nearest kind; the `osc2cr:commonRoadType` property keeps the type.
    pub(crate) fn object(self) -> Object {
        use DynamicObstacleType as D;
        use EnvironmentObstacleType as E;
        use StaticObstacleType as S;
        match self {
            Element::Dynamic(t) => match t {
                D::Car | D::Taxi | D::PriorityVehicle => Object::Vehicle("car"),
                D::Truck => Object::Vehicle("truck"),
                D::Bus => Object::Vehicle("bus"),
                D::Motorcycle => Object::Vehicle("motorbike"),
                D::Bicycle => Object::Vehicle("bicycle"),
                D::Train => Object::Vehicle("train"),
                D::Pedestrian => Object::Pedestrian,
                D::Unknown => Object::Misc("obstacle"),
            },
            Element::Static(t) => match t {
                S::ParkedVehicle => Object::Vehicle("car"),
                S::ConstructionZone => Object::Misc("patch"),
                S::RoadBoundary => Object::Misc("barrier"),
                S::Unknown => Object::Misc("obstacle"),
            },
            Element::Environment(t) => match t {
                E::Building => Object::Misc("building"),
                E::Pillar => Object::Misc("streetLamp"),
                E::MedianStrip => Object::Misc("trafficIsland"),
                E::Unknown => Object::Misc("obstacle"),
            },
        }
    }
}

/// An obstacle's box: length and width, and where its centre is in the obstacle's frame (not
/// the origin only for polygons).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BoxShape {
    pub length: f64,
    pub width: f64,
    pub cx: f64,
    pub cy: f64,
}

/// The box of a shape, and a note when it is not the shape itself.
pub(crate) fn box_of(shape: &Shape, pedestrian: bool) -> (BoxShape, Option<String>) {
    match shape {
        Shape::Rectangle(r) => (BoxShape { length: r.length(), width: r.width(), cx: 0.0, cy: 0.0 }, None),
        Shape::Circle(c) if pedestrian => {
            // the forward conversion's circle is half the box diagonal: a square of side r·√2
            let side = c.radius() * std::f64::consts::SQRT_2;
            (BoxShape { length: side, width: side, cx: 0.0, cy: 0.0 }, None)
        }
        Shape::Circle(c) => {
            let d = 2.0 * c.radius();
            (BoxShape { length: d, width: d, cx: 0.0, cy: 0.0 }, Some(format!("a circle of radius {} m is written as its bounding square", c.radius())))
        }
        Shape::Polygon(p) => {
            let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
            for q in p.points() {
                x0 = x0.min(q.x);
                x1 = x1.max(q.x);
                y0 = y0.min(q.y);
                y1 = y1.max(q.y);
            }
            let b = BoxShape { length: (x1 - x0).max(MIN_SIDE), width: (y1 - y0).max(MIN_SIDE), cx: 0.5 * (x0 + x1), cy: 0.5 * (y0 + y1) };
            (b, Some(format!("a polygon of {} points is written as its bounding box", p.points().len())))
        }
    }
}

/// Sides thinner than this (a polygon along a line) are widened to it.
const MIN_SIDE: f64 = 0.01;

/// A typical height of each kind (CommonRoad shapes are flat).
fn height(object: Object) -> f64 {
    match object {
        Object::Vehicle("truck") => 3.5,
        Object::Vehicle("bus") => 3.2,
        Object::Vehicle("train") => 3.8,
        Object::Vehicle("bicycle") => 1.7,
        Object::Vehicle(_) => 1.5,
        Object::Pedestrian => 1.8,
        Object::Misc("building") => 10.0,
        Object::Misc("streetLamp") => 6.0,
        Object::Misc("trafficIsland") => 0.2,
        Object::Misc(_) => 1.0,
    }
}

/// A typical mass, kg.
fn mass(object: Object) -> f64 {
    match object {
        Object::Vehicle("truck") | Object::Vehicle("bus") | Object::Vehicle("train") => 12000.0,
        Object::Vehicle("bicycle") => 90.0,
        Object::Vehicle("motorbike") => 250.0,
        Object::Vehicle(_) => 1500.0,
        Object::Pedestrian => 80.0,
        Object::Misc(_) => 500.0,
    }
}

/// One entity of the scenario.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entity {
    pub name: String,
    pub object: Object,
    pub shape: BoxShape,
    /// The highest speed it reaches, m/s (the Performance must allow it).
    pub top_speed: f64,
    /// `Properties` (name, value), in order.
    pub properties: Vec<(&'static str, String)>,
}

/// The property naming the CommonRoad element and type an entity was made of
/// (`dynamicObstacle/taxi`), for types OpenSCENARIO has no kind for.
pub const TYPE_PROPERTY: &str = "osc2cr:commonRoadType";
/// The property holding the CommonRoad id an entity was made of.
pub const ID_PROPERTY: &str = "osc2cr:commonRoadId";

impl Entity {
    /// The entity of an obstacle: named `<type>_<id>`.
    pub(crate) fn obstacle(id: u64, element: Element, shape: BoxShape, top_speed: f64) -> Self {
        Self {
            name: format!("{}_{id}", element.type_name()),
            object: element.object(),
            shape,
            top_speed,
            properties: vec![(ID_PROPERTY, id.to_string()), (TYPE_PROPERTY, format!("{}/{}", element.element_name(), element.type_name()))],
        }
    }

    fn bounding_box(&self) -> El {
        let h = height(self.object);
        El::new("BoundingBox")
            .child(El::new("Center").num("x", 0.0).num("y", 0.0).num("z", 0.5 * h))
            .child(El::new("Dimensions").num("width", self.shape.width).num("length", self.shape.length).num("height", h))
    }

    fn properties(&self) -> El {
        El::new("Properties").children(self.properties.iter().map(|(k, v)| El::new("Property").attr("name", *k).attr("value", v.clone())))
    }

    /// The `ScenarioObject`, with an `ObjectController` when one is given.
    pub(crate) fn scenario_object(&self, version: OscVersion, controller: Option<El>) -> El {
        let object = match self.object {
            Object::Vehicle(category) => {
                let mut v = El::new("Vehicle").attr("name", category).attr("vehicleCategory", category);
                if version == OscVersion::V1_3 {
                    v = v.num("mass", mass(self.object));
                }
                // generous limits: a simulator must not cut a recorded trajectory's speed
                let top = (2.0 * self.top_speed).max(70.0);
                let axle = |name: &'static str, max_steering: f64, x: f64| {
                    let d = if category == "bicycle" || category == "motorbike" { 0.7 } else { 0.8 };
                    El::new(name)
                        .num("maxSteering", max_steering)
                        .num("wheelDiameter", d)
                        .num("trackWidth", self.shape.width.min(2.5))
                        .num("positionX", x)
                        .num("positionZ", 0.5 * d)
                };
                v.child(self.bounding_box())
                    .child(El::new("Performance").num("maxSpeed", top).num("maxAcceleration", 30.0).num("maxDeceleration", 30.0))
                    .child(El::new("Axles").child(axle("FrontAxle", 0.5, 0.3 * self.shape.length)).child(axle("RearAxle", 0.0, 0.0)))
                    .child(self.properties())
            }
            Object::Pedestrian => {
                let mut p = El::new("Pedestrian").attr("name", "pedestrian").attr("pedestrianCategory", "pedestrian").num("mass", mass(self.object));
                if version == OscVersion::V1_0 {
                    p = p.attr("model", "pedestrian");
                }
                p.child(self.bounding_box()).child(self.properties())
            }
            Object::Misc(category) => El::new("MiscObject")
                .attr("name", category)
                .attr("miscObjectCategory", category)
                .num("mass", mass(self.object))
                .child(self.bounding_box())
                .child(self.properties()),
        };
        // the entity object comes first, then its controller (the schema's sequence)
        El::new("ScenarioObject").attr("name", self.name.clone()).child(object).child_opt(controller.map(|c| El::new("ObjectController").child(c)))
    }
}
