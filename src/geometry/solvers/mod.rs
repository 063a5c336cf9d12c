//! Vertex solvers: the position of a Voronoi vertex computed directly from its
//! sites, never from old edge geometry, so errors do not accumulate.
//!
//! Precision: not exact. The circumcentre is computed relative to the corner
//! opposite the longest side, which keeps the error near a few ulps of the
//! circle's radius also for needle-shaped triangles, and with the
//! denominator's sign always right. A solver that finds no solution says so, and the caller (the
//! topology) decides what to store.
//!
//! This room holds the vertex solvers, in `f64` or any `Real` arithmetic:
//! the circumcircle of three points here, every mix of point and segment
//! sites in `segment_solvers`. They use the sign predicates to choose a
//! root; the certified polish of a segment vertex is in `segments`.

use super::point::Point;

pub(crate) mod segment_solvers;

/// The centre and radius of the circle through three points, or `None` when
/// the points are collinear (as computed), where no such circle exists.
#[inline]
pub fn circumcircle(a: Point, b: Point, c: Point) -> Option<(Point, f64)> {
    // Work relative to the corner opposite the longest side, which is an end
    // of the shortest side: the short side's coordinate differences, where a
    // nearly degenerate triangle keeps its information, then come out of one
    // rounding-free subtraction instead of the difference of two rounded
    // long ones. (A cyclic rotation keeps the orientation.)
    // Where two sides tie for the longest (an isosceles triangle: common
    // on integer grids), the corner with the least coordinates among the
    // two, so that every rotation of the same three points gives the same
    // circle bit for bit: a vertex's sites are stored in some rotation,
    // which differs between builds (one thread or two, another insertion
    // order), and its place must not.
    let (ab, bc, ca) = (a.distance_squared(b), b.distance_squared(c), c.distance_squared(a));
    let before = |p: Point, q: Point| p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y)).is_lt();
    // (whether the corner opposite `side` comes before the one opposite `other`)
    let longer = |side: f64, p: Point, other: f64, q: Point| side > other || (side == other && before(p, q));
    let (a, b, c) = if longer(bc, a, ab, c) && longer(bc, a, ca, b) {
        (a, b, c)
    } else if longer(ca, b, ab, c) {
        (b, c, a)
    } else {
        (c, a, b)
    };
    let (bx, by) = (b.x - a.x, b.y - a.y);
    let (cx, cy) = (c.x - a.x, c.y - a.y);
    // The denominator is the orientation determinant. When rounding could
    // have changed its sign (Shewchuk's first error bound), the adaptive
    // predicate gives it instead, so it never comes out 0 or of the wrong
    // sign for three non-collinear sites.
    let (left, right) = (bx * cy, by * cx);
    let mut orient = left - right;
    const HALF_EPSILON: f64 = f64::EPSILON / 2.0;
    if orient.abs() <= (3.0 + 16.0 * HALF_EPSILON) * HALF_EPSILON * (left.abs() + right.abs()) {
        orient = robust::orient2d(
            robust::Coord { x: a.x, y: a.y },
            robust::Coord { x: b.x, y: b.y },
            robust::Coord { x: c.x, y: c.y },
        );
    }
    let d = 2.0 * orient;
    if d == 0.0 {
        return None;
    }
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    let ux = (cy * b2 - by * c2) / d;
    let uy = (bx * c2 - cx * b2) / d;
    if !(ux.is_finite() && uy.is_finite()) {
        return None;
    }
    Some((Point::new(a.x + ux, a.y + uy), (ux * ux + uy * uy).sqrt()))
}

/// The unit direction of the Voronoi edge that runs to infinity between two
/// consecutive convex-hull sites `a → b` (hull counter-clockwise... seen from
/// the outside: the left normal of `b - a`). `None` when `a == b`.
#[inline]
pub fn left_normal(a: Point, b: Point) -> Option<Point> {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let len = dx.hypot(dy);
    if len == 0.0 || !len.is_finite() {
        return None;
    }
    Some(Point::new(-dy / len, dx / len))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn circumcircle_of_right_triangle_is_hypotenuse_midpoint() {
        let (c, r) = circumcircle(p(0., 0.), p(4., 0.), p(0., 3.)).unwrap();
        assert!((c.x - 2.0).abs() < 1e-15 && (c.y - 1.5).abs() < 1e-15);
        assert!((r - 2.5).abs() < 1e-15);
    }

    #[test]
    fn circumcircle_far_from_origin() {
        let o = 1e9;
        let (c, r) = circumcircle(p(o, o), p(o + 2., o), p(o, o + 2.)).unwrap();
        assert_eq!((c.x, c.y), (o + 1., o + 1.));
        assert!((r - 2f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn circumcircle_of_nearly_collinear_points() {
        // Sites 1e-20 off a line: the centre is far, and the plain
        // determinant (2e-20 - 1e-20 rounded against terms of size 1) is 0.
        let (a, b, c) = (p(-1.0, 1e-20), p(0.0, 0.0), p(1.0, 1e-20));
        let (centre, r) = circumcircle(a, b, c).unwrap();
        // Exact: centre (0, (1 + 1e-40) / 2e-20), radius its y.
        let y = 0.5e20;
        assert!((centre.x).abs() < 1e-12 * y, "{centre:?}");
        assert!((centre.y - y).abs() < 1e-12 * y && (r - y).abs() < 1e-12 * y, "{centre:?} {r}");
    }

    #[test]
    fn circumcircle_of_a_needle_triangle() {
        // Found by the CGAL cross-check: two sites 3e-17 apart and one 0.5
        // away. Relative to the far site the 1e-20 offsets are rounded away
        // and the centre lands 1.7e-4 off; the exact centre is
        // (0.25, -1.5e-17 - 0.25 * 2e-20 / 3e-17) to within 1e-20.
        let (far, b, c) = (p(0.5, -3e-17), p(-1e-20, -3e-17), p(1e-20, 0.0));
        for (a, b, c) in [(far, b, c), (b, c, far), (c, far, b)] {
            let (centre, r) = circumcircle(a, b, c).unwrap();
            let y = -1.5e-17 - 0.25 * 2e-20 / 3e-17;
            assert!((centre.x - 0.25).abs() < 1e-15 && (centre.y - y).abs() < 1e-15, "{centre:?}");
            assert!((r - far.distance(centre)).abs() < 1e-15);
        }
    }

    /// Every rotation of three points gives the same circle bit for bit,
    /// isosceles triangles (two sides tied for the longest) included: a
    /// build on two threads stores some vertices' sites in another
    /// rotation than one thread does (found on the headline's 1M points,
    /// snapped to an integer grid: one clearance an ulp apart).
    #[test]
    fn every_rotation_gives_the_same_circle() {
        let mut rng = crate::splitmix::SplitMix64(5);
        let mut triples = vec![
            (p(0., 0.), p(4., 0.), p(2., 7.)),
            (p(682_040., 656_170.), p(682_649., 656_778.), p(681_431., 656_778.)),
            (p(1e9, 1e9), p(1e9 + 3., 1e9 + 1.), p(1e9 + 1., 1e9 + 3.)),
        ];
        // isosceles on a grid: an apex on the perpendicular bisector of a base
        for _ in 0..2000 {
            let (x, y, dx, dy, h) =
                (rng.next_u64() % 1000, rng.next_u64() % 1000, rng.next_u64() % 50, rng.next_u64() % 50, 1 + rng.next_u64() % 90);
            let [x, y, dx, dy, h] = [x, y, dx, dy, h].map(|v| v as f64);
            // base (x - dx, y - dy)..(x + dx, y + dy), apex h along the normal
            triples.push((p(x - dx, y - dy), p(x + dx, y + dy), p(x - h * dy, y + h * dx)));
            let [u, v, w, x, y, z] = [0; 6].map(|_| (rng.next_u64() % 64) as f64);
            triples.push((p(u, v), p(w, x), p(y, z)));
        }
        for (a, b, c) in triples {
            let circles = [circumcircle(a, b, c), circumcircle(b, c, a), circumcircle(c, a, b)];
            let bits = circles.map(|o| o.map(|(q, r)| [q.x.to_bits(), q.y.to_bits(), r.to_bits()]));
            assert!(bits[0] == bits[1] && bits[1] == bits[2], "{a:?} {b:?} {c:?}: {circles:?}");
        }
    }

    #[test]
    fn circumcircle_of_collinear_points_is_none() {
        assert!(circumcircle(p(0., 0.), p(1., 1.), p(2., 2.)).is_none());
        assert!(circumcircle(p(0., 0.), p(0., 0.), p(2., 2.)).is_none());
    }

    #[test]
    fn left_normal_points_left() {
        let n = left_normal(p(0., 0.), p(2., 0.)).unwrap();
        assert_eq!((n.x, n.y), (0., 1.));
        assert!(left_normal(p(1., 1.), p(1., 1.)).is_none());
    }
}
