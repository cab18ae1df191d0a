//! `<planView>` geometries.

use super::xml::{elements, irrelevant, Ctx};
use crate::error::Error;
use crate::geometry::{Geometry, PRange, ParamPoly3, Poly3, Shape, Spiral};
use roxmltree::Node;

/// Hostile-input cap on geometries per road.
const MAX_GEOMETRIES: usize = 1_000_000;

pub(super) fn parse_plan_view(ctx: &mut Ctx, node: Node) -> Result<Vec<Geometry>, Error> {
    let mut out = Vec::new();
    for g in elements(node) {
        match g.tag_name().name() {
            "geometry" => {}
            n if irrelevant(n) => continue,
            n => {
                ctx.warn(g, format!("<planView><{n}> is not modelled; ignored"));
                continue;
            }
        }
        ctx.cap(g, "geometries in one road", out.len() + 1, MAX_GEOMETRIES)?;
        let s = ctx.req_f64(g, "s")?;
        let x = ctx.req_f64(g, "x")?;
        let y = ctx.req_f64(g, "y")?;
        let hdg = ctx.req_f64(g, "hdg")?;
        let length = ctx.req_f64(g, "length")?;
        if length < 0.0 {
            return Err(ctx.error(g, format!("<geometry> length must not be negative, found {length}")));
        }
        let mut shape = None;
        for p in elements(g) {
            let name = p.tag_name().name();
            let parsed = match name {
                "line" => Shape::Line,
                "arc" => Shape::Arc { curvature: ctx.req_f64(p, "curvature")? },
                "spiral" => Shape::Spiral(Spiral::new(ctx.req_f64(p, "curvStart")?, ctx.req_f64(p, "curvEnd")?, length)),
                "poly3" => Shape::Poly3(Poly3::new(ctx.req_f64(p, "a")?, ctx.req_f64(p, "b")?, ctx.req_f64(p, "c")?, ctx.req_f64(p, "d")?, length)),
                "paramPoly3" => {
                    let range = match p.attribute("pRange").map(str::trim) {
                        None | Some("normalized") => PRange::Normalized,
                        Some("arcLength") => PRange::ArcLength,
                        Some(other) => return Err(ctx.error(p, format!("pRange: expected `arcLength` or `normalized`, found `{other}`"))),
                    };
                    let u = [ctx.req_f64(p, "aU")?, ctx.req_f64(p, "bU")?, ctx.req_f64(p, "cU")?, ctx.req_f64(p, "dU")?];
                    let v = [ctx.req_f64(p, "aV")?, ctx.req_f64(p, "bV")?, ctx.req_f64(p, "cV")?, ctx.req_f64(p, "dV")?];
                    let pp = ParamPoly3::new(u, v, range, length);
                    if (pp.arc_length() - length).abs() > 1e-3 * length.max(1.0) {
                        ctx.warn(p, format!("paramPoly3 arc length {:.4} m differs from the declared length {length} m; s is scaled to fit", pp.arc_length()));
                    }
                    Shape::ParamPoly3(pp)
                }
                n if irrelevant(n) => continue,
                n => {
                    ctx.warn(p, format!("<geometry><{n}> is not a known geometry; ignored"));
                    continue;
                }
            };
            if shape.is_some() {
                ctx.warn(p, "<geometry> has more than one primitive; the first is used");
            } else {
                shape = Some(parsed);
            }
        }
        let shape = shape.ok_or_else(|| ctx.error(g, "<geometry> needs one of <line>, <arc>, <spiral>, <poly3>, <paramPoly3>"))?;
        out.push(Geometry::new(s, x, y, hdg, length, shape));
    }
    out.sort_by(|a, b| a.s.total_cmp(&b.s));
    Ok(out)
}
