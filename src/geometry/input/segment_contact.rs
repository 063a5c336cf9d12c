//! How two closed segments meet, and whether a point lies inside a
//! segment: the contact rules of the input, decided exactly —
//! exact orientation signs ([`exact_orientation`], never perturbed by fault
//! injection) and coordinate comparisons ([`strictly_between`]), no epsilon
//! anywhere. The input check (`construct/input_check/`) asks these.

use std::cell::OnceCell;
use std::cmp::Ordering;

use crate::geometry::arithmetic::bigfloat::BigFloat;
use crate::geometry::point::Point;
use crate::geometry::predicates::{exact_orientation as orientation, strictly_between, Orientation};

/// How two distinct, non-degenerate segments `s` and `t` meet, if they meet
/// in anything other than a common endpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SegmentContact {
    Cross,
    Overlap,
    /// An endpoint of `t` lies inside `s`.
    EndpointOfSecondOnFirst,
    /// An endpoint of `s` lies inside `t`.
    EndpointOfFirstOnSecond,
}

/// Exact classification of two distinct non-degenerate segments.
pub(crate) fn segment_contact(s: [Point; 2], t: [Point; 2]) -> Option<SegmentContact> {
    let [a, b] = s;
    let [c, d] = t;
    let (oc, od) = (orientation(a, b, c), orientation(a, b, d));
    if oc == Orientation::Collinear && od == Orientation::Collinear {
        // On one line the segments are intervals; distinct intervals share
        // more than a point exactly when an endpoint of one lies strictly
        // inside the other (a common endpoint alone is allowed).
        let inside =
            strictly_between(a, b, c) || strictly_between(a, b, d) || strictly_between(c, d, a) || strictly_between(c, d, b);
        return inside.then_some(SegmentContact::Overlap);
    }
    let (oa, ob) = (orientation(c, d, a), orientation(c, d, b));
    if opposite(oc, od) && opposite(oa, ob) {
        return Some(SegmentContact::Cross);
    }
    // Not both collinear, so each of c, d, a, b that lies on the other's
    // line is the only point where the two segments can meet: a conflict
    // when it is inside the other segment, fine when it is a common endpoint
    // or beyond the other segment's ends.
    let on_s = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(a, b, p);
    let on_t = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(c, d, p);
    if on_s(c, oc) || on_s(d, od) {
        Some(SegmentContact::EndpointOfSecondOnFirst)
    } else if on_t(a, oa) || on_t(b, ob) {
        Some(SegmentContact::EndpointOfFirstOnSecond)
    } else {
        None
    }
}

/// Strictly on opposite sides.
fn opposite(p: Orientation, q: Orientation) -> bool {
    matches!(
        (p, q),
        (Orientation::Clockwise, Orientation::CounterClockwise) | (Orientation::CounterClockwise, Orientation::Clockwise)
    )
}

/// Whether the point lies in the open interior of the segment.
pub(crate) fn inside_segment(p: Point, s: [Point; 2]) -> bool {
    orientation(s[0], s[1], p) == Orientation::Collinear && strictly_between(s[0], s[1], p)
}

/// The lexicographic order of points: by `x`, then by `y` (`-0.0` equals
/// `+0.0`; no NaN here). The order in which the input check sweeps.
pub(crate) fn lex_cmp(a: Point, b: Point) -> Ordering {
    cmp_f64(a.x, b.x).then_with(|| cmp_f64(a.y, b.y))
}

/// A key whose order is [`lex_cmp`]'s, for sorting (`-0.0` and `+0.0`
/// alike; no NaN).
pub(crate) fn lex_key(p: Point) -> (u64, u64) {
    (ordered_bits(p.x), ordered_bits(p.y))
}

/// The bits of `v` turned so that unsigned order is numeric order.
fn ordered_bits(v: f64) -> u64 {
    let bits = (v + 0.0).to_bits(); // -0.0 + 0.0 is +0.0
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | (1 << 63)
    }
}

fn cmp_f64(a: f64, b: f64) -> Ordering {
    if a < b {
        Ordering::Less
    } else if a > b {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// Where two input items first meet: the lexicographically smallest point
/// they share. Either a point of the input (an endpoint or an isolated
/// point), or the crossing of two segments, a rational point kept exactly.
/// Compared exactly with [`ContactPoint::cmp`].
#[derive(Clone, Debug)]
pub(crate) enum ContactPoint {
    /// An input point.
    At(Point),
    /// The crossing point of two segments.
    Crossing(Box<Crossing>),
}

/// The crossing point of two non-parallel segments, kept as the two
/// segments: an `f64` approximation with a bound on its error in each
/// coordinate, which decides most comparisons, and the exact value
/// `(x, y) / den` (`den > 0`) in big numbers, computed only when a
/// comparison needs it.
#[derive(Clone, Debug)]
pub(crate) struct Crossing {
    approx: Point,
    /// `|approx - exact|` is below this in each coordinate (infinite when
    /// the approximation is not trusted).
    error: f64,
    segments: [[Point; 2]; 2],
    exact: OnceCell<ExactCrossing>,
}

#[derive(Clone, Debug)]
struct ExactCrossing {
    num: [BigFloat; 2],
    den: BigFloat,
}

/// Enough bits that the sums and products of degree at most 4 in `f64`s
/// here are never truncated: their exponents span less than `4 · 2100`
/// bits.
const EXACT_BITS: u64 = 1 << 14;

fn big(x: f64) -> BigFloat {
    BigFloat::from_f64(x, EXACT_BITS)
}

impl ContactPoint {
    /// The crossing point of the lines through `s` and `t` (not parallel).
    pub(crate) fn crossing(s: [Point; 2], t: [Point; 2]) -> ContactPoint {
        let (approx, error) = approximate_crossing(s, t);
        ContactPoint::Crossing(Box::new(Crossing { approx, error, segments: [s, t], exact: OnceCell::new() }))
    }

    /// The approximation and its error bound.
    fn approx(&self) -> (Point, f64) {
        match self {
            ContactPoint::At(p) => (*p, 0.0),
            ContactPoint::Crossing(c) => (c.approx, c.error),
        }
    }

    /// Coordinate `axis` as `(numerator, denominator)`, exactly.
    fn exact(&self, axis: usize) -> (BigFloat, BigFloat) {
        match self {
            ContactPoint::At(p) => (big(if axis == 0 { p.x } else { p.y }), big(1.0)),
            ContactPoint::Crossing(c) => {
                let exact = c.exact();
                (exact.num[axis].clone(), exact.den.clone())
            }
        }
    }

    /// The lexicographic order ([`lex_cmp`]) of two contact points, exact.
    pub(crate) fn cmp(&self, other: &ContactPoint) -> Ordering {
        match (self, other) {
            (ContactPoint::At(p), ContactPoint::At(q)) => return lex_cmp(*p, *q),
            // the crossing of one pair of segments (in either order)
            (ContactPoint::Crossing(c), ContactPoint::Crossing(d))
                if c.segments == d.segments || c.segments == [d.segments[1], d.segments[0]] =>
            {
                return Ordering::Equal
            }
            _ => {}
        }
        self.cmp_axis(other, 0).then_with(|| self.cmp_axis(other, 1))
    }

    fn cmp_axis(&self, other: &ContactPoint, axis: usize) -> Ordering {
        let ((p, e), (q, f)) = (self.approx(), other.approx());
        let (u, v) = if axis == 0 { (p.x, q.x) } else { (p.y, q.y) };
        // A correctly rounded difference keeps the sign of the exact one.
        let d = u - v;
        if d.abs() > 2.0 * (e + f) {
            return cmp_f64(d, 0.0);
        }
        if e == 0.0 && f == 0.0 {
            return cmp_f64(u, v);
        }
        let ((a, b), (c, w)) = (self.exact(axis), other.exact(axis));
        // a / b against c / w, both denominators positive.
        match (&(&a * &w) - &(&c * &b)).signum() {
            s if s < 0 => Ordering::Less,
            0 => Ordering::Equal,
            _ => Ordering::Greater,
        }
    }

    /// The side of the line through `s` (from `s[0]` to `s[1]`, distinct)
    /// on which this point lies, exactly: `CounterClockwise` on the left.
    pub(crate) fn side_of(&self, s: [Point; 2]) -> Orientation {
        let c = match self {
            ContactPoint::At(p) => return orientation(s[0], s[1], *p),
            ContactPoint::Crossing(c) => c,
        };
        let [a, b] = s;
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let (px, py) = (c.approx.x - a.x, c.approx.y - a.y);
        let (left, right) = (dx * py, dy * px);
        // The rounding of the differences and products (as in
        // `predicates::turn`), and the approximation's error `e` in each
        // coordinate of the point, times the lengths it multiplies.
        let size = left.abs() + right.abs();
        let bound = 8.0 * f64::EPSILON * size + 2.0 * (dx.abs() + dy.abs()) * c.error;
        let det = left - right;
        if det.abs() > bound && det.is_finite() && size > 1e-290 {
            return if det > 0.0 { Orientation::CounterClockwise } else { Orientation::Clockwise };
        }
        // cross(b - a, num / den - a) has the sign of
        // cross(b - a, num - a · den), den > 0.
        let exact = c.exact();
        let (ax, ay, den) = (big(a.x), big(a.y), &exact.den);
        let (ux, uy) = (&big(b.x) - &ax, &big(b.y) - &ay);
        let (vx, vy) = (&exact.num[0] - &(&ax * den), &exact.num[1] - &(&ay * den));
        match (&(&ux * &vy) - &(&uy * &vx)).signum() {
            s if s > 0 => Orientation::CounterClockwise,
            s if s < 0 => Orientation::Clockwise,
            _ => Orientation::Collinear,
        }
    }
}

impl Crossing {
    /// The exact value, computed on first use.
    fn exact(&self) -> &ExactCrossing {
        self.exact.get_or_init(|| {
            let [s, t] = self.segments;
            let [a, b] = s.map(|p| [big(p.x), big(p.y)]);
            let [c, d] = t.map(|p| [big(p.x), big(p.y)]);
            let sub = |u: &[BigFloat; 2], v: &[BigFloat; 2]| [&u[0] - &v[0], &u[1] - &v[1]];
            let cross = |u: &[BigFloat; 2], v: &[BigFloat; 2]| &(&u[0] * &v[1]) - &(&u[1] * &v[0]);
            // a + (b - a) · u / den, with den = cross(b - a, d - c) and
            // u = cross(c - a, d - c).
            let (r, q) = (sub(&b, &a), sub(&d, &c));
            let mut den = cross(&r, &q);
            let mut u = cross(&sub(&c, &a), &q);
            if den.signum() < 0 {
                den = -&den;
                u = -&u;
            }
            let num = [&(&a[0] * &den) + &(&r[0] * &u), &(&a[1] * &den) + &(&r[1] * &u)];
            ExactCrossing { num, den }
        })
    }
}

/// The crossing point of the lines through `s` and `t` in `f64`, and a
/// bound on its error in each coordinate (infinite where the lines are so
/// nearly parallel, or the numbers so far from 1, that the bound is not
/// worth having).
///
/// With `u = 2^-53`: each rounded difference is within `u` relative, each
/// product of two within `3u` of the exact one, so the computed
/// `den = cross(b - a, d - c)` and `num = cross(c - a, d - c)` are within
/// `E = 5u · (|x₁y₂| + |y₁x₂|)` of theirs (room included); then
/// `t = num / den` within `Δt = (E_num + |t| E_den) / (|den| − E_den) + u|t|`,
/// and `a + (b − a) t` within `1.01 |b − a| Δt + 2.01 u |(b − a) t| + u |x|`
/// per coordinate.
fn approximate_crossing([a, b]: [Point; 2], [c, d]: [Point; 2]) -> (Point, f64) {
    const U: f64 = f64::EPSILON / 2.0;
    let (rx, ry, qx, qy, wx, wy) = (b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y, c.x - a.x, c.y - a.y);
    let cross_with_error = |x1: f64, y1: f64, x2: f64, y2: f64| {
        let (p, q) = (x1 * y2, y1 * x2);
        (p - q, 5.0 * U * (p.abs() + q.abs()), p.abs() + q.abs())
    };
    let (den, den_error, den_size) = cross_with_error(rx, ry, qx, qy);
    let (num, num_error, num_size) = cross_with_error(wx, wy, qx, qy);
    let t = num / den;
    let t_error = (num_error + t.abs() * den_error) / (den.abs() - den_error) + U * t.abs();
    let approx = Point::new(a.x + rx * t, a.y + ry * t);
    let coordinate_error = |r: f64, x: f64| 1.01 * r.abs() * t_error + 2.01 * U * (r * t).abs() + U * x.abs();
    let error = coordinate_error(rx, approx.x).max(coordinate_error(ry, approx.y));
    // products near the subnormal range lose their relative accuracy
    let normal = den_size > 1e-280 && num_size > 1e-280 && den_size < 1e280 && num_size < 1e280;
    let trusted = normal && den.abs() > 2.0 * den_error && error.is_finite() && approx.x.is_finite() && approx.y.is_finite();
    (approx, if trusted { 1.01 * error + f64::MIN_POSITIVE } else { f64::INFINITY })
}

/// The lexicographically smallest point that `s` and `t` share, given
/// how they meet (`segment_contact(s, t)`).
pub(crate) fn first_contact(s: [Point; 2], t: [Point; 2], contact: SegmentContact) -> ContactPoint {
    let min = |[a, b]: [Point; 2]| if lex_cmp(a, b) == Ordering::Greater { b } else { a };
    let inside_of = |[a, b]: [Point; 2], other: [Point; 2]| if inside_segment(a, other) { a } else { b };
    match contact {
        SegmentContact::Cross => ContactPoint::crossing(s, t),
        // On one line the common part starts at the later of the two
        // first ends.
        SegmentContact::Overlap => {
            let (a, b) = (min(s), min(t));
            ContactPoint::At(if lex_cmp(a, b) == Ordering::Less { b } else { a })
        }
        SegmentContact::EndpointOfSecondOnFirst => ContactPoint::At(inside_of(t, s)),
        SegmentContact::EndpointOfFirstOnSecond => ContactPoint::At(inside_of(s, t)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `|approx − exact| ≤ error` in each coordinate, decided exactly.
    fn bound_holds(s: [Point; 2], t: [Point; 2]) -> Result<(), String> {
        let ContactPoint::Crossing(c) = ContactPoint::crossing(s, t) else { unreachable!() };
        if !c.error.is_finite() {
            return Ok(());
        }
        let exact = c.exact();
        for (axis, approx) in [c.approx.x, c.approx.y].into_iter().enumerate() {
            let off = (&(&big(approx) * &exact.den) - &exact.num[axis]).abs();
            let allowed = &big(c.error) * &exact.den;
            if (&off - &allowed).signum() > 0 {
                return Err(format!("{s:?} {t:?}: axis {axis} off by more than {}", c.error));
            }
        }
        Ok(())
    }

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn the_approximate_crossing_is_within_its_bound(
            a in (-1.0..1.0f64, -1.0..1.0f64), b in (-1.0..1.0f64, -1.0..1.0f64),
            c in (-1.0..1.0f64, -1.0..1.0f64), tilt in -1.0..1.0f64,
            steep in prop::sample::select(vec![1.0, 1e-6, 1e-12, 1e-15]),
            scale in prop::sample::select(vec![1.0, 1e-200, 1e200, 3.0e7]),
        ) {
            // t through c, at an angle to s from wide down to nearly parallel
            let (s0, s1) = (p(a.0, a.1), p(b.0, b.1));
            prop_assume!(s0 != s1);
            let (dx, dy) = (s1.x - s0.x, s1.y - s0.y);
            let (ex, ey) = (dx + tilt * steep * -dy, dy + tilt * steep * dx);
            let (t0, t1) = (p(c.0 - ex, c.1 - ey), p(c.0 + ex, c.1 + ey));
            let k = |q: Point| p(q.x * scale, q.y * scale);
            let (s, t) = ([k(s0), k(s1)], [k(t0), k(t1)]);
            // (a tilt lost in rounding leaves them parallel: nothing to check)
            if turn_is_not_zero(s, t) {
                bound_holds(s, t).map_err(TestCaseError::fail)?;
            }
        }
    }

    fn turn_is_not_zero(s: [Point; 2], t: [Point; 2]) -> bool {
        crate::geometry::predicates::exact_turn(s[0], s[1], t[0], t[1]) != Orientation::Collinear
    }

    #[test]
    fn nearly_parallel_crossings_fall_back_to_the_exact_value() {
        let s = [p(0.0, 0.0), p(1.0, 1e-17)];
        let t = [p(0.0, 1e-300), p(1.0, 0.0)];
        bound_holds(s, t).unwrap();
        let (q, r) = (ContactPoint::crossing(s, t), ContactPoint::crossing(t, s));
        assert_eq!(q.cmp(&r), Ordering::Equal);
    }
}
