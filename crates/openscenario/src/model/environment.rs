//! Environment: time of day, weather, road condition.

use super::{BoundingBox, Properties};
use crate::params::ParameterDeclaration;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Environment {
    pub name: String,
    pub parameters: Vec<ParameterDeclaration>,
    pub time_of_day: Option<TimeOfDay>,
    pub weather: Option<Weather>,
    pub road_condition: Option<RoadCondition>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TimeOfDay {
    pub animation: bool,
    pub date_time: String,
}

crate::xml_enum! {
    CloudState {
        SkyOff = "skyOff", Free = "free", Cloudy = "cloudy", Overcast = "overcast", Rainy = "rainy",
    }
}
crate::xml_enum! {
    FractionalCloudCover {
        ZeroOktas = "zeroOktas", OneOktas = "oneOktas", TwoOktas = "twoOktas", ThreeOktas = "threeOktas",
        FourOktas = "fourOktas", FiveOktas = "fiveOktas", SixOktas = "sixOktas", SevenOktas = "sevenOktas",
        EightOktas = "eightOktas", NineOktas = "nineOktas",
    }
}
crate::xml_enum! {
    PrecipitationType { Dry = "dry", Rain = "rain", Snow = "snow" }
}
crate::xml_enum! {
    Wetness {
        Dry = "dry", Moist = "moist", WetWithPuddles = "wetWithPuddles", LowFlooded = "lowFlooded",
        HighFlooded = "highFlooded",
    }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Weather {
    /// 1.0 cloudState (deprecated).
    pub cloud_state: Option<CloudState>,
    pub fractional_cloud_cover: Option<FractionalCloudCover>,
    pub temperature: Option<f64>,
    pub atmospheric_pressure: Option<f64>,
    pub sun: Option<Sun>,
    pub fog: Option<Fog>,
    pub precipitation: Option<Precipitation>,
    pub wind: Option<Wind>,
    pub dome_image: Option<DomeImage>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sun {
    pub azimuth: f64,
    pub elevation: f64,
    /// `illuminance` (1.2+) or the 1.0 `intensity`.
    pub illuminance: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fog {
    pub visual_range: f64,
    pub bounding_box: Option<BoundingBox>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Precipitation {
    pub precipitation_type: PrecipitationType,
    /// `precipitationIntensity` (1.1+) or the 1.0 `intensity`.
    pub intensity: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Wind {
    pub direction: f64,
    pub speed: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DomeImage {
    pub file: String,
    pub azimuth_offset: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RoadCondition {
    pub friction_scale_factor: f64,
    pub wetness: Option<Wetness>,
    pub properties: Properties,
}
