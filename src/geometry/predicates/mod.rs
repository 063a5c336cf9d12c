//! Sign predicates.
//!
//! Sign convention: [`orientation`] is `CounterClockwise` when `c` lies to the
//! left of the directed line `a → b`; [`in_circle`] is `Inside` when `d` lies
//! strictly inside the circle through `a`, `b`, `c` given in counter-clockwise
//! order.
//!
//! Precision: both are exact for every finite `f64` input whose intermediate
//! products neither overflow nor underflow (Shewchuk's adaptive expansions,
//! through the `robust` crate). The builder keeps coordinates within
//! `2^-60 ..= 2^60` in magnitude (see `scale`), where that holds unless two
//! points are closer than about `1e-70` times the input extent.
//!
//! In the `fault-injection` test build these predicates can be told to lie
//! (see `fault`); the construction must stay valid whatever they answer.
//!
//! This room holds the signs every other part of `geometry` stands on:
//! these exact predicates on points and `point_predicates` (how deep a new
//! point lies in a vertex's circle, to rank). The questions of a new
//! segment, which need the vertex solvers and a certified stage, are a
//! floor higher (`segments`).

use super::arithmetic::expansion::Expansion;
use super::fault;
use super::point::Point;

pub(crate) mod point_predicates;

/// Which side of a directed line a point lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    /// To the left of the line (counter-clockwise turn).
    CounterClockwise,
    /// To the right of the line (clockwise turn).
    Clockwise,
    /// On the line.
    Collinear,
}

impl Orientation {
    /// `1`, `-1` or `0`: counter-clockwise, clockwise, collinear.
    pub(crate) fn sign(self) -> i8 {
        match self {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::Collinear => 0,
        }
    }
}

/// Where a point lies with respect to a circle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CirclePosition {
    /// Strictly inside.
    Inside,
    /// Strictly outside.
    Outside,
    /// On the circle.
    On,
}

#[inline]
fn coord(p: Point) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

/// The orientation of the triple `(a, b, c)`: exact.
#[inline]
pub fn orientation(a: Point, b: Point, c: Point) -> Orientation {
    if !fault::active() {
        return exact_orientation(a, b, c);
    }
    let det = fault::perturb_difference((b.x - a.x) * (c.y - a.y), (b.y - a.y) * (c.x - a.x));
    sign_of(det)
}

/// [`orientation`], exact even in fault injection: for checking the input,
/// which is not the construction's to get wrong.
#[inline]
pub(crate) fn exact_orientation(a: Point, b: Point, c: Point) -> Orientation {
    sign_of(robust::orient2d(coord(a), coord(b), coord(c)))
}

/// The order of the directions from `centre` to `p` and to `q` by angle
/// counter-clockwise from the positive x axis, in `[0, 2π)`, exactly: by the
/// half-plane first (angles in `[0, π)`, then `[π, 2π)`), then by the exact
/// orientation within one. Equal directions compare equal.
pub(crate) fn compare_directions(centre: Point, p: Point, q: Point) -> std::cmp::Ordering {
    let lower = |r: Point| r.y < centre.y || (r.y == centre.y && r.x < centre.x);
    match (lower(p), lower(q)) {
        (false, true) => std::cmp::Ordering::Less,
        (true, false) => std::cmp::Ordering::Greater,
        _ => match exact_orientation(centre, p, q) {
            Orientation::CounterClockwise => std::cmp::Ordering::Less,
            Orientation::Clockwise => std::cmp::Ordering::Greater,
            Orientation::Collinear => std::cmp::Ordering::Equal,
        },
    }
}

/// The turn from the direction `a → b` to the direction `c → d`: the sign
/// of `cross(b − a, d − c)`, exact (counter-clockwise: `d − c` points left
/// of `b − a`; collinear: the directions are parallel or opposite). For
/// directions that differ by an angle near the rounding of a unit vector,
/// where the orientation of rounded normals says nothing.
pub(crate) fn turn(a: Point, b: Point, c: Point, d: Point) -> Orientation {
    if fault::active() {
        let (left, right) = ((b.x - a.x) * (d.y - c.y), (b.y - a.y) * (d.x - c.x));
        return sign_of(fault::perturb_difference(left, right));
    }
    exact_turn(a, b, c, d)
}

/// [`turn`], exact even in fault injection (for the splitting's sweep).
pub(crate) fn exact_turn(a: Point, b: Point, c: Point, d: Point) -> Orientation {
    let (ux, uy, vx, vy) = (b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y);
    let (left, right) = (ux * vy, uy * vx);
    // Each difference and product is off by at most half an ulp while the
    // products are normal numbers; the bound covers both, with room
    // (Shewchuk-style, products of rounded differences).
    let det = left - right;
    let size = left.abs() + right.abs();
    if det.abs() > 8.0 * f64::EPSILON * size && det.is_finite() && size > 1e-290 {
        return sign_of(det);
    }
    let mut exact = Expansion::default();
    exact.add_product_of_differences((b.x, a.x), (d.y, c.y));
    exact.add_product_of_differences((b.y, a.y), (c.x, d.x));
    match exact.sign() {
        1 => Orientation::CounterClockwise,
        -1 => Orientation::Clockwise,
        _ => Orientation::Collinear,
    }
}

#[inline]
fn sign_of(det: f64) -> Orientation {
    if det > 0.0 {
        Orientation::CounterClockwise
    } else if det < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

/// Whether `d` lies inside the circle through the counter-clockwise triple
/// `(a, b, c)`: exact.
#[inline]
pub fn in_circle(a: Point, b: Point, c: Point, d: Point) -> CirclePosition {
    let det = if fault::active() {
        // The same determinant split into the two halves whose difference
        // decides the sign, so that relative noise can flip it near zero.
        let (adx, ady) = (a.x - d.x, a.y - d.y);
        let (bdx, bdy) = (b.x - d.x, b.y - d.y);
        let (cdx, cdy) = (c.x - d.x, c.y - d.y);
        let alift = adx * adx + ady * ady;
        let blift = bdx * bdx + bdy * bdy;
        let clift = cdx * cdx + cdy * cdy;
        let plus = alift * (bdx * cdy) + blift * (cdx * ady) + clift * (adx * bdy);
        let minus = alift * (cdx * bdy) + blift * (adx * cdy) + clift * (bdx * ady);
        fault::perturb_difference(plus, minus)
    } else {
        robust::incircle(coord(a), coord(b), coord(c), coord(d))
    };
    if det > 0.0 {
        CirclePosition::Inside
    } else if det < 0.0 {
        CirclePosition::Outside
    } else {
        CirclePosition::On
    }
}

/// For three collinear points, whether `p` lies strictly between `a` and `b`.
/// Exact: it compares coordinates only.
#[inline]
pub fn strictly_between(a: Point, b: Point, p: Point) -> bool {
    if a.x != b.x {
        (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x)
    } else {
        (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y)
    }
}

/// Whether the foot of `p` on the line `ab` lies strictly between `a` and
/// `b`: `(p − a)·(b − a) > 0` and `(p − b)·(a − b) > 0`, exact.
pub(crate) fn foot_strictly_inside(a: Point, b: Point, p: Point) -> bool {
    let dot_sign = |o: Point, q: Point| {
        // rounded differences and products, each within half an ulp (as
        // `exact_turn` bounds them), decide unless the dot is near zero
        let (left, right) = ((q.x - o.x) * (p.x - o.x), (q.y - o.y) * (p.y - o.y));
        let dot = left + right;
        if dot.abs() > 8.0 * f64::EPSILON * (left.abs() + right.abs()) && dot.is_finite() && left.abs() + right.abs() > 1e-290 {
            return if dot > 0.0 { 1 } else { -1 };
        }
        let mut exact = Expansion::default();
        exact.add_product_of_differences((q.x, o.x), (p.x, o.x));
        exact.add_product_of_differences((q.y, o.y), (p.y, o.y));
        exact.sign()
    };
    dot_sign(a, b) > 0 && dot_sign(b, a) > 0
}

/// Whether the circle "through `a`, `b` and the point at infinity on the left
/// of `a → b`" contains `p`: the open half-plane left of `a → b`, plus the
/// open segment `ab` itself (the limit of circles through `a` and `b` whose
/// centre runs off to the left). Exact.
#[inline]
pub fn in_half_plane_circle(a: Point, b: Point, p: Point) -> bool {
    match orientation(a, b, p) {
        Orientation::CounterClockwise => true,
        Orientation::Clockwise => false,
        Orientation::Collinear => !fault::active() && strictly_between(a, b, p),
    }
}

/// Whether `p` is strictly closer to `a` than to `b`: exact.
#[inline]
pub fn strictly_closer(p: Point, a: Point, b: Point) -> bool {
    strictly_closer_given(p, a, p.distance_squared(a), b, p.distance_squared(b))
}

/// [`strictly_closer`] for a caller that already has the rounded squared
/// distances `da = p.distance_squared(a)` and `db = p.distance_squared(b)`
/// (a walk compares each site with several others).
///
/// A floating-point filter answers when the two squared distances differ by
/// more than their rounding error can explain; otherwise the exact sign of
/// `|p - a|^2 - |p - b|^2` is computed with expansions.
#[inline]
pub fn strictly_closer_given(p: Point, a: Point, da: f64, b: Point, db: f64) -> bool {
    if fault::active() {
        return fault::perturb(da) < fault::perturb(db);
    }
    // Each squared distance is within 4 ulps (relative) of its true value
    // (two differences, two squares, one sum); below 1e-290 subnormal
    // results would break that bound, so the exact path decides there.
    let sum = da + db;
    if (da - db).abs() > 9.0 * f64::EPSILON * sum && sum > 1e-290 {
        return da < db;
    }
    exact_distance_difference_sign(p, a, b) < 0
}

/// The sign of `|p - a|^2 - |p - b|^2`, exactly.
#[cold]
fn exact_distance_difference_sign(p: Point, a: Point, b: Point) -> i8 {
    let mut e = Expansion::default();
    e.add_squared_difference(p.x, b.x);
    e.add_squared_difference(p.y, b.y);
    e.negate();
    e.add_squared_difference(p.x, a.x);
    e.add_squared_difference(p.y, a.y);
    e.sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn orientation_signs() {
        assert_eq!(orientation(p(0., 0.), p(1., 0.), p(0., 1.)), Orientation::CounterClockwise);
        assert_eq!(orientation(p(0., 0.), p(1., 0.), p(0., -1.)), Orientation::Clockwise);
        assert_eq!(orientation(p(0., 0.), p(1., 1.), p(3., 3.)), Orientation::Collinear);
    }

    #[test]
    fn orientation_is_exact_near_degeneracy() {
        // 0.1 + 0.2 style rounding: a point one ulp off the line is not collinear.
        let a = p(0.5, 0.5);
        let b = p(12.0, 12.0);
        let c = p(24.0, f64::from_bits(24.0f64.to_bits() + 1));
        assert_eq!(orientation(a, b, c), Orientation::CounterClockwise);
        let c = p(24.0, 24.0);
        assert_eq!(orientation(a, b, c), Orientation::Collinear);
    }

    #[test]
    fn in_circle_cocircular_lattice_points() {
        // The four corners of a unit square are cocircular.
        let (a, b, c) = (p(0., 0.), p(1., 0.), p(1., 1.));
        assert_eq!(in_circle(a, b, c, p(0., 1.)), CirclePosition::On);
        assert_eq!(in_circle(a, b, c, p(0.5, 0.5)), CirclePosition::Inside);
        assert_eq!(in_circle(a, b, c, p(2., 2.)), CirclePosition::Outside);
        // One ulp inside the circle.
        let y = f64::from_bits(1.0f64.to_bits() - 1);
        assert_eq!(in_circle(a, b, c, p(0., y)), CirclePosition::Inside);
    }

    #[test]
    fn half_plane_circle_boundary_cases() {
        let (a, b) = (p(0., 0.), p(2., 0.));
        assert!(in_half_plane_circle(a, b, p(1., 1e-300)));
        assert!(!in_half_plane_circle(a, b, p(1., -1e-300)));
        assert!(in_half_plane_circle(a, b, p(1., 0.)), "open segment is inside");
        assert!(!in_half_plane_circle(a, b, p(3., 0.)), "beyond an endpoint is outside");
        assert!(!in_half_plane_circle(a, b, p(0., 0.)), "the endpoint is on the circle");
    }

    #[test]
    fn strictly_closer_decides_ties_and_near_ties_exactly() {
        let (a, b) = (p(-1.0, 0.0), p(1.0, 0.0));
        assert!(!strictly_closer(p(0.0, 5.0), a, b), "equidistant");
        assert!(!strictly_closer(p(0.0, 5.0), b, a), "equidistant");
        assert!(strictly_closer(p(-1e-300, 5.0), a, b));
        assert!(!strictly_closer(p(1e-300, 5.0), a, b));
        // Distances of about 1 that differ by 1e-40: invisible to doubles.
        let q = p(1.0, -1e-20);
        let (c, d) = (p(1e-20, -1.0), p(-1e-20, -1.0));
        assert!(strictly_closer(q, c, d));
        assert!(!strictly_closer(q, d, c));
        assert!(!strictly_closer(q, q, q));
        assert!(strictly_closer(q, q, c));
    }

    #[test]
    fn strictly_between_vertical() {
        assert!(strictly_between(p(1., 0.), p(1., 4.), p(1., 2.)));
        assert!(!strictly_between(p(1., 0.), p(1., 4.), p(1., 4.)));
        assert!(!strictly_between(p(1., 0.), p(1., 4.), p(1., -2.)));
    }

    #[test]
    fn directions_sort_by_angle_exactly() {
        // around the origin, so that 1e-300 off the axis is not rounded away
        let c = Point::new(0.0, 0.0);
        let at = Point::new;
        let mut d =
            vec![at(0.0, -1.0), at(-1.0, 0.0), at(1.0, 1e-300), at(1.0, 0.0), at(-1.0, -1e-300), at(0.0, 1.0), at(1.0, -1e-300)];
        d.sort_by(|&p, &q| compare_directions(c, p, q));
        let expected =
            vec![at(1.0, 0.0), at(1.0, 1e-300), at(0.0, 1.0), at(-1.0, 0.0), at(-1.0, -1e-300), at(0.0, -1.0), at(1.0, -1e-300)];
        assert_eq!(d, expected);
        assert_eq!(compare_directions(c, at(2.0, 2.0), at(1.0, 1.0)), std::cmp::Ordering::Equal);
    }

    #[test]
    fn turn_between_directions_one_ulp_apart_is_exact() {
        // (1, 1) against (1 + 6ε, 1) and (1, 1 + 8ε), from other origins:
        // within the filter's bound, so decided by the exact stage
        let e = f64::EPSILON;
        let (a, b) = (p(0.0, 0.0), p(1.0, 1.0));
        assert_eq!(turn(a, b, p(5.0, 7.0), p(6.0 + 6.0 * e, 8.0)), Orientation::Clockwise);
        assert_eq!(turn(a, b, p(5.0, 7.0), p(6.0, 8.0 + 8.0 * e)), Orientation::CounterClockwise);
        assert_eq!(turn(p(0.0, 0.0), p(3.0, 1.0), p(2.0, 2.0), p(-4.0, 0.0)), Orientation::Collinear);
        assert_eq!(turn(p(0.0, 0.0), p(1.0, 0.0), p(0.0, 0.0), p(0.0, 1.0)), Orientation::CounterClockwise);
    }
}
