//! Root attributes, `<location>` and `<scenarioTags>`.

use roxmltree::Node;

use super::cursor::{child, Cursor};
use crate::header::{BenchmarkId, Date, GeoLocation, GeoTransformation, Header};
use crate::scenario::Scenario;
use crate::tags::Tag;
use crate::Error;

fn parse_date(s: &str) -> Option<Date> {
    let mut it = s.trim().splitn(3, '-');
    let y = it.next()?.parse().ok()?;
    let m = it.next()?.parse().ok()?;
    let d = it.next()?.parse().ok()?;
    Date::new(y, m, d).ok()
}

pub(crate) fn header(cx: &mut Cursor, root: Node) -> Result<Header, Error> {
    match root.attribute("commonRoadVersion") {
        Some("2020a") => {}
        other => cx.warn(root, format!("commonRoadVersion {other:?} is not \"2020a\"; reading it as 2020a")),
    }
    let raw_id = root.attribute("benchmarkID").unwrap_or("");
    let benchmark_id = match BenchmarkId::parse(raw_id) {
        Ok(id) => id,
        Err(e) => {
            // commonroad-io renames such a scenario too (with a warning).
            let id = BenchmarkId::for_converted("ZAM", raw_id).or_else(|_| BenchmarkId::parse("ZAM_Unnamed-1")).map_err(|e| cx.err(root, e.to_string()))?;
            cx.warn(root, format!("{e}; using {id}"));
            id
        }
    };
    let date = match root.attribute("date").and_then(parse_date) {
        Some(d) => d,
        None => {
            cx.warn(root, "missing or invalid date; using 1970-01-01");
            Date::new(1970, 1, 1).map_err(|e| cx.err(root, e.to_string()))?
        }
    };
    let step_text = root.attribute("timeStepSize").unwrap_or("");
    let time_step_size = match step_text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => v,
        _ => return Err(cx.err(root, format!("timeStepSize {step_text:?}: expected a positive number of seconds"))),
    };
    let attr = |name| root.attribute(name).unwrap_or("").to_string();
    Ok(Header { benchmark_id, date, author: attr("author"), affiliation: attr("affiliation"), source: attr("source"), time_step_size })
}

pub(crate) fn location_and_tags(cx: &mut Cursor, root: Node, scenario: &mut Scenario) -> Result<(), Error> {
    if let Some(loc) = child(root, "location") {
        scenario.location = location(cx, loc)?;
    }
    if let Some(tags) = child(root, "scenarioTags") {
        for t in tags.children().filter(|n| n.is_element()) {
            let name = t.tag_name().name();
            match Tag::ALL.iter().find(|tag| tag.as_str() == name) {
                Some(tag) => {
                    scenario.tags.insert(*tag);
                }
                None => cx.warn(t, format!("unknown scenario tag <{name}>; skipped")),
            }
        }
    }
    Ok(())
}

fn location(cx: &mut Cursor, loc: Node) -> Result<GeoLocation, Error> {
    let mut out = GeoLocation::default();
    if let Some(n) = child(loc, "geoNameId") {
        let t = cx.text(n);
        out.geo_name_id = t.parse().map_err(|_| cx.err(n, format!("<geoNameId>: expected an integer, found {t:?}")))?;
    }
    if let Some(n) = child(loc, "gpsLatitude") {
        out.gps_latitude = cx.f64(n)?;
    }
    if let Some(n) = child(loc, "gpsLongitude") {
        out.gps_longitude = cx.f64(n)?;
    }
    if let Some(g) = child(loc, "geoTransformation") {
        let mut geo = GeoTransformation::proj(child(g, "geoReference").map_or("", |n| cx.text(n)).to_string());
        if let Some(a) = child(g, "additionalTransformation") {
            geo.x_translation = cx.f64_child(a, "xTranslation")?;
            geo.y_translation = cx.f64_child(a, "yTranslation")?;
            geo.z_rotation = cx.f64_child(a, "zRotation")?;
            geo.scaling = cx.f64_child(a, "scaling")?;
        }
        out.geo_transformation = Some(geo);
    }
    if child(loc, "environment").is_some() {
        cx.warn(loc, "<environment> is not part of the model; skipped");
    }
    Ok(out)
}
