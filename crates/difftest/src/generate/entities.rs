//! The road users a scenario may hold and their definitions: cars (one may have a trailer
//! hitch), trucks, bicycles, trailers, pedestrians and misc objects, each with the bounding box
//! and performance esmini needs, in the order the 1.3 schema gives.

use super::entity_kind::EntityKind;
use super::Gen;

fn bounding_box(cx: f64, w: f64, l: f64, h: f64) -> String {
    format!(r#"<BoundingBox><Center x="{cx}" y="0" z="{}"/><Dimensions width="{w}" length="{l}" height="{h}"/></BoundingBox>"#, h / 2.0)
}

fn axles(front_x: f64, track: f64, wheel: f64) -> String {
    format!(
        r#"<Axles><FrontAxle maxSteering="0.5236" wheelDiameter="{wheel}" trackWidth="{track}" positionX="{front_x}" positionZ="{}"/><RearAxle maxSteering="0.5236" wheelDiameter="{wheel}" trackWidth="{track}" positionX="0" positionZ="{}"/></Axles>"#,
        wheel / 2.0,
        wheel / 2.0
    )
}

impl Gen<'_> {
    /// The definition of an entity of `kind` (the body of its ScenarioObject before any
    /// controller). `hitch`: a car that may tow a trailer.
    pub(crate) fn entity_definition(&mut self, kind: EntityKind, hitch: bool) -> String {
        match kind {
            EntityKind::Car => {
                let max_speed = self.pick(&[69.444, 40.0]);
                let hitch = if hitch { r#"<TrailerHitch dx="-1.2"/>"# } else { "" };
                format!(
                    r#"<Vehicle name="car" vehicleCategory="car"><ParameterDeclarations/>{}<Performance maxSpeed="{max_speed}" maxAcceleration="10" maxDeceleration="10"/>{}<Properties/>{hitch}</Vehicle>"#,
                    bounding_box(1.4, 2.0, 5.04, 1.5),
                    axles(2.98, 1.68, 0.8)
                )
            }
            EntityKind::Truck => format!(
                r#"<Vehicle name="truck" vehicleCategory="truck"><ParameterDeclarations/>{}<Performance maxSpeed="30" maxAcceleration="4" maxDeceleration="8"/>{}<Properties/></Vehicle>"#,
                bounding_box(2.5, 2.5, 8.5, 3.2),
                axles(4.5, 2.0, 1.0)
            ),
            EntityKind::Bicycle => format!(
                r#"<Vehicle name="bicycle" vehicleCategory="bicycle"><ParameterDeclarations/>{}<Performance maxSpeed="12" maxAcceleration="3" maxDeceleration="6"/>{}<Properties/></Vehicle>"#,
                bounding_box(0.5, 0.6, 1.9, 1.7),
                axles(1.05, 0.1, 0.7)
            ),
            EntityKind::Trailer => format!(
                r#"<Vehicle name="trailer" vehicleCategory="trailer"><ParameterDeclarations/>{}<Performance maxSpeed="40" maxAcceleration="5" maxDeceleration="10"/><Axles><RearAxle maxSteering="0.5236" wheelDiameter="0.7" trackWidth="1.68" positionX="0" positionZ="0.35"/></Axles><Properties/><TrailerCoupler dx="3.25"/></Vehicle>"#,
                bounding_box(1.4, 2.0, 4.5, 1.2)
            ),
            EntityKind::Pedestrian => format!(
                r#"<Pedestrian name="walker" mass="80"{} pedestrianCategory="pedestrian"><ParameterDeclarations/>{}<Properties/></Pedestrian>"#,
                self.pedestrian_model(),
                bounding_box(0.0, 0.5, 0.6, 1.8)
            ),
            EntityKind::Misc => {
                let (category, w, l) = self.pick(&[("obstacle", 1.0, 1.0), ("barrier", 2.5, 0.6), ("pole", 0.3, 0.3), ("obstacle", 2.0, 4.0)]);
                format!(
                    r#"<MiscObject name="{category}" mass="100" miscObjectCategory="{category}"><ParameterDeclarations/>{}<Properties/></MiscObject>"#,
                    bounding_box(0.0, w, l, 1.0)
                )
            }
        }
    }
}
