//! Questions about a new point site that rank rather than decide: how
//! deep it lies inside the circle of a vertex (the sign of conflict itself
//! is exact, in `predicates`).

use crate::geometry::fault;
use crate::geometry::point::Point;

/// The circle of a vertex of point sites, as the construction stores it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum VertexCircle {
    /// A finite vertex: its centre and radius.
    Finite { centre: Point, radius: f64 },
    /// A vertex at infinity beyond the hull edge `x → y` (the point at
    /// infinity on its left): the site `x` and the stored unit direction.
    AtInfinity { x: Point, direction: Point },
}

/// How deep `p` lies inside the circle of a vertex (negative inside): the
/// power `|p - c|^2 - r^2` of `p` for a finite vertex, minus the squared
/// distance beyond the hull edge for a vertex at infinity (perturbed in
/// fault injection; NaN gives `+∞`). Only used to choose among candidates.
#[inline]
pub(crate) fn conflict_depth(circle: VertexCircle, p: Point) -> f64 {
    let depth = match circle {
        VertexCircle::AtInfinity { x, direction: c } => {
            let beyond = (p.x - x.x) * c.x + (p.y - x.y) * c.y;
            -beyond * beyond.abs()
        }
        VertexCircle::Finite { centre, radius: r } => p.distance_squared(centre) - r * r,
    };
    let depth = fault::perturb(depth);
    if depth.is_nan() {
        f64::INFINITY
    } else {
        depth
    }
}
