//! The question the insertion of a segment asks about a Voronoi vertex:
//! does the segment reach into the vertex's circle. Asked by
//! `segment_predicates`, answered by `oracle` and, for its most common
//! true zero, by `quadratic_vertex`.

use crate::geometry::point::Point;

/// The question asked about a vertex and a new segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Reach {
    /// Does the closed segment `a b` come nearer to the centre than the
    /// radius: `dist(c, ab) − r`, negative inside.
    Distance { a: Point, b: Point },
    /// Does the segment leave `from` (a point on the circle) towards the
    /// inside: `−(c − from)·(to − from)`, negative inside.
    Entering { from: Point, to: Point },
}

impl Reach {
    /// The two points the question names (`a`, `b` or `from`, `to`).
    pub(super) fn points(&self) -> [Point; 2] {
        match *self {
            Reach::Distance { a, b } => [a, b],
            Reach::Entering { from, to } => [from, to],
        }
    }
}
