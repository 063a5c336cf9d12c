//! A finite Voronoi edge as a curve: the one curve type that the
//! construction's middle margin (`segment_predicates`) and the queries
//! (`query::shape`: polylines, Bézier arcs) both walk along.
//!
//! The bisector of two sites is a straight line unless one is a point and
//! the other a segment not ending at it (`Parabola::of_sites`), or one is
//! a circular arc (a conic, walked point by point by `bisector`); a finite
//! edge is the piece of it between the positions of its two vertices.

use super::parabola::Parabola;
use crate::geometry::point::Point;
use crate::geometry::site::Site;

/// A finite edge between two vertex positions: a straight piece, or an arc
/// of a parabola between the parameters of its ends. Its own parameter
/// runs over `[0, 1]`, from the first end to the second.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum EdgeCurve {
    Line(Point, Point),
    Parabola {
        parabola: Parabola,
        from: f64,
        to: f64,
    },
    /// The conic beside an arc between two positions, `left` the site on
    /// its left from `from` to `to`, `witnesses` the third sites of its end
    /// vertices where known: its point at `t` is at the angle `t` of the
    /// way round a point site, else across the chord's point at `t`
    /// (`bisector_point_of_edge`).
    Conic {
        left: Site,
        right: Site,
        from: Point,
        to: Point,
        witnesses: [Option<Site>; 2],
    },
}

impl EdgeCurve {
    /// The edge of the sites `left` and `right` (on its left and right)
    /// from `from` to `to`. A
    /// parabola that cannot be set up in floating point (its focus so close
    /// to the directrix that their distance rounds to zero) is the straight
    /// piece it is within rounding.
    pub(crate) fn between(left: &Site, right: &Site, from: Point, to: Point) -> EdgeCurve {
        let own_end = |s: &Site, t: &Site| t.as_point().is_some_and(|p| s.has_endpoint(p));
        let arc = |s: &Site| matches!(s, Site::Arc(_));
        if (arc(left) || arc(right)) && !own_end(left, right) && !own_end(right, left) {
            return EdgeCurve::Conic { left: *left, right: *right, from, to, witnesses: [None, None] };
        }
        match Parabola::of_sites(left, right) {
            Some(parabola) => EdgeCurve::Parabola { parabola, from: parabola.parameter(from), to: parabola.parameter(to) },
            None => EdgeCurve::Line(from, to),
        }
    }

    /// The same curve, its end vertices' third sites known (see `Conic`).
    pub(crate) fn with_witnesses(self, ends: [Option<Site>; 2]) -> EdgeCurve {
        match self {
            EdgeCurve::Conic { left, right, from, to, .. } => EdgeCurve::Conic { left, right, from, to, witnesses: ends },
            other => other,
        }
    }

    /// The point at parameter `t` (0 at the first end, 1 at the second).
    pub(crate) fn point(&self, t: f64) -> Point {
        match *self {
            EdgeCurve::Line(p, q) => Point::new(p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t),
            EdgeCurve::Parabola { ref parabola, from, to } => parabola.point(from + (to - from) * t),
            EdgeCurve::Conic { ref left, ref right, from, to, witnesses } => match t {
                t if t <= 0.0 => from,
                t if t >= 1.0 => to,
                t => super::bisector::bisector_point_of_edge(left, right, from, to, t, &witnesses),
            },
        }
    }

    /// The direction in which the parameter grows: along the line of a
    /// straight piece, along the directrix of a parabola. (Both are linear
    /// in position, so a difference of two points along it is a difference
    /// of their parameters, also where the curve turns back.)
    pub(crate) fn direction(&self) -> Point {
        match *self {
            EdgeCurve::Line(p, q) | EdgeCurve::Conic { from: p, to: q, .. } => Point::new(q.x - p.x, q.y - p.y),
            EdgeCurve::Parabola { ref parabola, from, to } => {
                let t = parabola.tangent();
                if to >= from {
                    t
                } else {
                    Point::new(-t.x, -t.y)
                }
            }
        }
    }

    /// The parameter of the point of the curve nearest to `q` (exact for
    /// points on it, up to rounding); NaN for a curve of no length.
    pub(crate) fn parameter(&self, q: Point) -> f64 {
        match *self {
            EdgeCurve::Line(p, r) | EdgeCurve::Conic { from: p, to: r, .. } => {
                let (dx, dy) = (r.x - p.x, r.y - p.y);
                ((q.x - p.x) * dx + (q.y - p.y) * dy) / (dx * dx + dy * dy)
            }
            EdgeCurve::Parabola { ref parabola, from, to } => (parabola.parameter(q) - from) / (to - from),
        }
    }
}
