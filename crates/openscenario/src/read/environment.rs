//! Environment (inline or from a catalog).

use super::entity::{read_bounding_box, read_properties};
use super::Reader;
use crate::attr::Cx;
use crate::catalog::CatalogKind;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

/// EnvironmentAction: an Environment or a CatalogReference child.
pub(crate) fn read_environment_ref(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<Environment, Error> {
    r.inline_or_catalog(cx, wrapper, "Environment", CatalogKind::Environment, read_environment)
}

pub(crate) fn read_environment(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Environment, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    let time_of_day = e
        .child("TimeOfDay")
        .map(|t| Ok::<_, Error>(TimeOfDay { animation: cx.bool_or(t, "animation", false)?, date_time: cx.text(t, "dateTime")? }))
        .transpose()?;
    let weather = e.child("Weather").map(|w| read_weather(&cx, w)).transpose()?;
    let road_condition = e
        .child("RoadCondition")
        .map(|rc| {
            Ok::<_, Error>(RoadCondition {
                friction_scale_factor: cx.f64_or(rc, "frictionScaleFactor", 1.0)?,
                wetness: cx.opt_enum(rc, "wetness")?,
                properties: read_properties(&cx, rc.child("Properties"))?,
            })
        })
        .transpose()?;
    Ok(Environment { name: cx.text(e, "name")?, parameters, time_of_day, weather, road_condition })
}

fn read_weather(cx: &Cx, w: &Elem) -> Result<Weather, Error> {
    Ok(Weather {
        cloud_state: cx.opt_enum(w, "cloudState")?,
        fractional_cloud_cover: cx.opt_enum(w, "fractionalCloudCover")?,
        temperature: cx.opt_f64(w, "temperature")?,
        atmospheric_pressure: cx.opt_f64(w, "atmosphericPressure")?,
        sun: w
            .child("Sun")
            .map(|s| {
                Ok::<_, Error>(Sun {
                    azimuth: cx.f64_or(s, "azimuth", 0.0)?,
                    elevation: cx.f64_or(s, "elevation", 0.0)?,
                    illuminance: cx.opt_f64_renamed(s, "illuminance", "intensity")?,
                })
            })
            .transpose()?,
        fog: w
            .child("Fog")
            .map(|f| {
                Ok::<_, Error>(Fog {
                    visual_range: cx.f64(f, "visualRange")?,
                    bounding_box: f.child("BoundingBox").map(|b| read_bounding_box(cx, b)).transpose()?,
                })
            })
            .transpose()?,
        precipitation: w
            .child("Precipitation")
            .map(|p| {
                Ok::<_, Error>(Precipitation {
                    precipitation_type: cx.enum_(p, "precipitationType")?,
                    intensity: cx.opt_f64_renamed(p, "precipitationIntensity", "intensity")?,
                })
            })
            .transpose()?,
        wind: w.child("Wind").map(|x| Ok::<_, Error>(Wind { direction: cx.f64(x, "direction")?, speed: cx.f64(x, "speed")? })).transpose()?,
        dome_image: w
            .child("DomeImage")
            .map(|d| {
                Ok::<_, Error>(DomeImage {
                    file: d.child("DomeFile").map(|f| cx.text(f, "filepath")).transpose()?.unwrap_or_default(),
                    azimuth_offset: cx.opt_f64(d, "azimuthOffset")?,
                })
            })
            .transpose()?,
    })
}
