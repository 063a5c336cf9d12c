//! The orientation of three points given in input coordinates, decided
//! exactly also where their products overflow: the one place the queries
//! (the domain's sides and corners, the shape of an edge) turn input
//! points into a sign.

use crate::diagram::Diagram;
use crate::geometry::predicates::{orientation, Orientation};
use crate::geometry::Point;

impl Diagram {
    /// The exact orientation of `a`, `b`, `c` (input coordinates), asked in
    /// the construction's coordinates: the power of two that keeps the
    /// input's products within `f64` (`geometry::scale`), so that an input
    /// of 1e300 (whose products overflow as they are) is decided exactly
    /// too. A point that does not scale exactly (a query point far beyond
    /// the input) is asked as it is.
    pub(crate) fn turn(&self, a: Point, b: Point, c: Point) -> Orientation {
        let k = self.scale.to_internal;
        let exact = |p: Point| {
            let q = p.scaled(k);
            q.x.is_finite() && q.y.is_finite() && q.scaled(self.scale.to_input) == p
        };
        if [a, b, c].into_iter().all(exact) {
            orientation(a.scaled(k), b.scaled(k), c.scaled(k))
        } else {
            orientation(a, b, c)
        }
    }
}
