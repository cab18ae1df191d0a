//! Why a shape cannot become a path.

use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    #[error("{shape}: the position of {what} could not be resolved to a world pose")]
    Unresolved { shape: &'static str, what: String },
    #[error("{shape}: expected at least {needed} {what}, found {found}")]
    TooFew { shape: &'static str, what: &'static str, needed: usize, found: usize },
    #[error("{shape}: more than {max} {what} ({found})")]
    TooMany { shape: &'static str, what: &'static str, max: usize, found: usize },
    #[error("{shape}: the path has zero length")]
    ZeroLength { shape: &'static str },
    #[error("{shape}: {what} must be a finite number{constraint}, got {value}")]
    BadNumber { shape: &'static str, what: String, constraint: &'static str, value: f64 },
    #[error("{shape}: {what} decrease at index {index} (expected non-decreasing values)")]
    NotMonotone { shape: &'static str, what: &'static str, index: usize },
    #[error("NURBS: expected {expected} knots (control points + order), found {found}")]
    KnotCount { expected: usize, found: usize },
    #[error("NURBS: order {order} needs 2 ≤ order ≤ number of control points ({control_points})")]
    BadOrder { order: u32, control_points: usize },
    #[error("NURBS: the knot vector spans no parameter range over the curve's domain")]
    EmptyDomain,
}
