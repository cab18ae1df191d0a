//! Trajectories and routes, inline or from catalogs.

use super::position::read_position;
use super::Reader;
use crate::attr::Cx;
use crate::catalog::CatalogKind;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

/// A wrapper whose child is a Trajectory or a CatalogReference (TrajectoryRef, 1.0
/// FollowTrajectoryAction).
pub(crate) fn read_trajectory_ref(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<Trajectory, Error> {
    r.inline_or_catalog(cx, wrapper, "Trajectory", CatalogKind::Trajectory, read_trajectory)
}

pub(crate) fn read_trajectory(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Trajectory, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    let shape_el = cx.child(e, "Shape")?;
    let s = cx.choice(shape_el, "Polyline, Clothoid, ClothoidSpline or Nurbs")?;
    let shape = match s.name.as_str() {
        "Polyline" => Shape::Polyline(
            s.children_named("Vertex")
                .map(|v| Ok(Vertex { time: cx.opt_f64(v, "time")?, position: read_position(r, &cx, cx.child(v, "Position")?)? }))
                .collect::<Result<_, Error>>()?,
        ),
        "Clothoid" => Shape::Clothoid {
            curvature: cx.f64(s, "curvature")?,
            // `curvatureDot` is the pre-1.2 spelling.
            curvature_prime: match cx.opt_f64(s, "curvaturePrime")? {
                Some(v) => v,
                None => cx.f64_or(s, "curvatureDot", 0.0)?,
            },
            length: cx.f64(s, "length")?,
            start_time: cx.opt_f64(s, "startTime")?,
            stop_time: cx.opt_f64(s, "stopTime")?,
            position: s.child("Position").map(|p| read_position(r, &cx, p).map(Box::new)).transpose()?,
        },
        "ClothoidSpline" => Shape::ClothoidSpline {
            segments: s
                .children_named("ClothoidSplineSegment")
                .map(|g| {
                    Ok(ClothoidSplineSegment {
                        curvature_start: cx.f64(g, "curvatureStart")?,
                        curvature_end: cx.f64(g, "curvatureEnd")?,
                        length: cx.f64(g, "length")?,
                        h_offset: cx.opt_f64(g, "hOffset")?,
                        time_start: cx.opt_f64(g, "timeStart")?,
                        position_start: g.child("PositionStart").map(|p| read_position(r, &cx, p)).transpose()?,
                    })
                })
                .collect::<Result<_, Error>>()?,
            time_end: cx.opt_f64(s, "timeEnd")?,
        },
        "Nurbs" => Shape::Nurbs {
            order: cx.u32_or(s, "order", 0)?,
            control_points: s
                .children_named("ControlPoint")
                .map(|p| {
                    Ok(ControlPoint {
                        time: cx.opt_f64(p, "time")?,
                        weight: cx.opt_f64(p, "weight")?,
                        position: read_position(r, &cx, cx.child(p, "Position")?)?,
                    })
                })
                .collect::<Result<_, Error>>()?,
            knots: s.children_named("Knot").map(|k| cx.f64(k, "value")).collect::<Result<_, Error>>()?,
        },
        _ => return Err(cx.unexpected(s, "Shape", "Polyline, Clothoid, ClothoidSpline, Nurbs")),
    };
    Ok(Trajectory { name: cx.text(e, "name")?, closed: cx.bool_or(e, "closed", false)?, parameters, shape, origin: cx.loc(e.pos) })
}

/// A wrapper whose child is a Route or a CatalogReference.
pub(crate) fn read_route_ref(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<Route, Error> {
    r.inline_or_catalog(cx, wrapper, "Route", CatalogKind::Route, read_route)
}

pub(crate) fn read_route(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Route, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    let waypoints = e
        .children_named("Waypoint")
        .map(|w| Ok(Waypoint { strategy: cx.enum_(w, "routeStrategy")?, position: read_position(r, &cx, cx.child(w, "Position")?)? }))
        .collect::<Result<_, Error>>()?;
    Ok(Route { name: cx.text(e, "name")?, closed: cx.bool_or(e, "closed", false)?, parameters, waypoints, origin: cx.loc(e.pos) })
}
