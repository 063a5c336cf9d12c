//! The geometric view of a site of the separated diagram.
//!
//! Every input segment becomes three sites: its two endpoints (point sites)
//! and the *open* segment between them. The open segment's own region is the
//! set of points whose nearest point on the closed segment is an interior
//! point, i.e. the strip between the perpendiculars at the two endpoints;
//! beyond those perpendiculars the endpoints' regions take over. That is why
//! the distance from a point to a segment site is the distance to the
//! supporting line when the foot falls inside the segment and the distance to
//! the nearer endpoint otherwise: outside the strip the segment site is never
//! the nearest site, and this value keeps the distance continuous (it is the
//! distance to the closed segment).
//!
//! Endpoints are recognised by exact coordinate equality: the builder stores
//! each endpoint once and hands the same coordinates to the point site and to
//! the segment site, so no tolerance is wanted (or safe) here.

use super::arc::CircularArc;
use super::arithmetic::real::{unit_near_inverse, Real};
use super::point::Point;

/// A site as geometry: a point, or an open segment whose endpoints are
/// separate point sites. More kinds may come (circular arcs), so a `match`
/// outside this crate needs a wildcard arm.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Site {
    /// A point site.
    Point(Point),
    /// The open segment from `a` to `b` (`a != b`). The direction `a → b`
    /// carries no meaning for the diagram; solvers may use either.
    Segment {
        /// One endpoint.
        a: Point,
        /// The other endpoint.
        b: Point,
    },
    /// An open circular arc; its endpoints are separate point sites.
    Arc(CircularArc),
}

impl Site {
    /// `true` for a point site.
    #[inline]
    pub fn is_point(&self) -> bool {
        matches!(self, Site::Point(_))
    }

    /// The point of a point site; `None` for a segment.
    #[inline]
    pub fn as_point(&self) -> Option<Point> {
        match *self {
            Site::Point(p) => Some(p),
            Site::Segment { .. } | Site::Arc(_) => None,
        }
    }

    /// The two ends of a segment or an arc; a point twice.
    #[inline]
    pub(crate) fn ends(&self) -> [Point; 2] {
        match *self {
            Site::Point(p) => [p, p],
            Site::Segment { a, b } => [a, b],
            Site::Arc(arc) => [arc.start(), arc.end()],
        }
    }

    /// The site with its coordinates multiplied by `factor`.
    pub(crate) fn scaled(&self, factor: f64) -> Site {
        match *self {
            Site::Point(p) => Site::Point(p.scaled(factor)),
            Site::Segment { a, b } => Site::Segment { a: a.scaled(factor), b: b.scaled(factor) },
            Site::Arc(arc) => Site::Arc(arc.scaled(factor)),
        }
    }

    /// One point that stands for the site: the point itself, or a
    /// segment's or arc's midpoint (what a vertex at infinity sees of it,
    /// and where a vertex no solver can place goes).
    pub(crate) fn midpoint(&self) -> Point {
        match *self {
            Site::Point(p) => p,
            Site::Segment { a, b } => Point::new(0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y),
            Site::Arc(arc) => arc.midpoint(),
        }
    }

    /// Whether `p` is an endpoint of this segment site (exact coordinate
    /// equality; `-0.0 == 0.0`). Always `false` for a point site.
    #[inline]
    pub fn has_endpoint(&self, p: Point) -> bool {
        match *self {
            Site::Point(_) => false,
            Site::Segment { a, b } => a == p || b == p,
            Site::Arc(arc) => arc.start() == p || arc.end() == p,
        }
    }

    /// The endpoint of this segment site that is not `p`, when `p` is one of
    /// its endpoints; `None` otherwise (and for point sites).
    #[inline]
    pub fn other_endpoint(&self, p: Point) -> Option<Point> {
        match *self {
            Site::Segment { a, b } if a == p => Some(b),
            Site::Segment { a, b } if b == p => Some(a),
            Site::Arc(arc) if arc.start() == p => Some(arc.end()),
            Site::Arc(arc) if arc.end() == p => Some(arc.start()),
            _ => None,
        }
    }

    /// The point of the (closed) site nearest to `p`: the point itself, or
    /// for a segment the foot of the perpendicular from `p` when it falls
    /// inside the segment, else the nearer endpoint.
    ///
    /// Precision: the foot is `a + τ (b - a)` with `τ` from
    /// [`segment_parameter`]; a few ulps of the segment's extent.
    pub fn nearest_point(&self, p: Point) -> Point {
        match *self {
            Site::Point(q) => q,
            Site::Segment { a, b } => {
                let t = segment_parameter(a, b, p);
                if t > 0.0 && t < 1.0 {
                    Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
                } else if t >= 0.5 {
                    b
                } else {
                    // t <= 0, or NaN for a zero-length segment.
                    a
                }
            }
            Site::Arc(arc) => arc.nearest_point(p),
        }
    }

    /// The squared distance from `p` to the site: to the point; for a
    /// segment, to its supporting line when the foot of `p` lies inside the
    /// open segment (the segment's Voronoi region lies between the
    /// perpendiculars at its endpoints), else to the nearer endpoint.
    ///
    /// Precision: the line distance is `|cross(b - a, p - a)| / |b - a|`,
    /// computed relative to `a`; its error is a few ulps of `|p - a|`, so it
    /// is relatively accurate unless `p` is much closer to the line than to
    /// `a`. Not exact: decisions must not compare two of these values.
    pub fn distance_squared(&self, p: Point) -> f64 {
        let d = self.distance(p);
        d * d
    }

    /// How far the site reaches in the direction `d` (its support
    /// function, `max d·q` over its points `q`, in units of `|d|`), and a
    /// point reaching that far: a point itself; a segment's farther end;
    /// an arc's circle where `d` lies in its span, else its farther end.
    /// Which sites own a direction at infinity, and where an edge at
    /// infinity goes, are comparisons of these.
    pub(crate) fn support(&self, d: Point) -> (f64, Point) {
        let along = |q: Point| d.x * q.x + d.y * q.y;
        if let Site::Arc(arc) = *self {
            let c = arc.centre();
            // (the direction itself: the centre plus `d` rounds back to the
            // centre where the centre is far larger)
            if arc.spans_direction(d) {
                let n = d.x.hypot(d.y);
                let k = arc.radius() / n;
                return (along(c) + arc.radius() * n, Point::new(c.x + k * d.x, c.y + k * d.y));
            }
        }
        let [p, q] = self.ends();
        if along(p) >= along(q) {
            (along(p), p)
        } else {
            (along(q), q)
        }
    }

    /// The distance from `p` to the site (see [`Site::distance_squared`]).
    ///
    /// Precision: as [`Site::distance_squared`], without the squaring's
    /// overflow or underflow.
    #[inline]
    pub fn distance(&self, p: Point) -> f64 {
        distance_in(self, p, &|x| x)
    }
}

/// [`Site::distance`] in the arithmetic `T` (`lift` turns an `f64` into
/// it; with `f64` itself this is `Site::distance`, operation for
/// operation): with double-double, a distance whose comparison with
/// another is within the rounding of `f64` (a point 1e9 units out, a margin
/// of 1e-9) still has its sign. The differences of coordinates are exact
/// in double-double; which part of the segment is nearest (its interior or
/// an endpoint) is decided in `f64`, where the two formulas agree.
#[inline]
pub(crate) fn distance_in<T: Real>(site: &Site, p: Point, lift: &impl Fn(f64) -> T) -> T {
    let between = |q: Point| (lift(p.x).sub(&lift(q.x)), lift(p.y).sub(&lift(q.y)));
    let to_point = |q: Point| {
        let (dx, dy) = between(q);
        T::hypot(&dx, &dy)
    };
    match *site {
        Site::Point(q) => to_point(q),
        Site::Segment { a, b } => {
            let t = segment_parameter(a, b, p);
            if t > 0.0 && t < 1.0 {
                // the direction in units of about its length (a power of
                // two, exact): a segment 1e-300 long has no square
                let unit = lift(unit_near_inverse((b.x - a.x).abs().max((b.y - a.y).abs())));
                let (ux, uy) = (lift(b.x).sub(&lift(a.x)).mul(&unit), lift(b.y).sub(&lift(a.y)).mul(&unit));
                let (vx, vy) = between(a);
                ux.mul(&vy).sub(&uy.mul(&vx)).abs().div(&T::hypot(&ux, &uy))
            } else {
                smaller(to_point(a), to_point(b))
            }
        }
        // the circle's centre and radius are f64 roundings already: the
        // distance to the circle in `T` is as good as the circle
        Site::Arc(arc) if arc.spans(p) => to_point(arc.centre()).sub(&lift(arc.radius())).abs(),
        Site::Arc(arc) => smaller(to_point(arc.start()), to_point(arc.end())),
    }
}

/// The smaller of two values as `f64::min` picks it (a NaN loses).
#[inline]
pub(crate) fn smaller<T: Real>(x: T, y: T) -> T {
    let (fx, fy) = (x.to_f64(), y.to_f64());
    if fy < fx || fx.is_nan() {
        y
    } else {
        x
    }
}

/// The parameter `τ` of the foot of `p` on the line `a → b`:
/// the foot is `a + τ (b - a)`, inside the open segment exactly when
/// `0 < τ < 1`. `NaN` when `a == b`.
///
/// Precision: `dot(p - a, b - a) / |b - a|^2`, a few ulps of
/// `|p - a| / |b - a|` in absolute terms; the sign near `τ = 0` or `τ = 1` is
/// not exact.
#[inline]
pub(crate) fn segment_parameter(a: Point, b: Point, p: Point) -> f64 {
    let (ux, uy) = (b.x - a.x, b.y - a.y);
    let dot = ux * (p.x - a.x) + uy * (p.y - a.y);
    let length2 = ux * ux + uy * uy;
    if (1e-290..=1e290).contains(&length2) {
        return dot / length2;
    }
    // a segment whose squared length underflows or overflows: its
    // direction in units of about its length (a power of two, exact)
    let unit = unit_near_inverse(ux.abs().max(uy.abs()));
    let (ux, uy) = (ux * unit, uy * unit);
    (ux * (p.x - a.x) + uy * (p.y - a.y)) / (ux * ux + uy * uy) * unit
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_at_every_magnitude() {
        // the slot's lower side and a point above its middle, at 1e-300,
        // 1 and 1e300: the distance is the height, the foot in the middle
        for s in [1e-300, 1e-160, 1.0, 1e160, 1e300] {
            let side = Site::Segment { a: p(0.0, 0.0), b: p(4.0 * s, 0.0) };
            let above = p(2.0 * s, 1.0 * s);
            assert_eq!(segment_parameter(p(0.0, 0.0), p(4.0 * s, 0.0), above), 0.5, "{s}");
            assert!((side.distance(above) / s - 1.0).abs() < 1e-15, "{s}: {}", side.distance(above));
        }
    }

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Site {
        Site::Segment { a: p(ax, ay), b: p(bx, by) }
    }

    #[test]
    fn distance_to_a_point_site() {
        let s = Site::Point(p(1., 1.));
        assert_eq!(s.distance_squared(p(4., 5.)), 25.0);
        assert_eq!(s.nearest_point(p(4., 5.)), p(1., 1.));
        assert!(s.is_point());
        assert!(!s.has_endpoint(p(1., 1.)), "a point site has no endpoints");
    }

    #[test]
    fn distance_to_a_segment_inside_its_strip_is_to_the_line() {
        // Segment (0,0)-(4,0); (1,3) projects to (1,0), inside: distance 3.
        let s = seg(0., 0., 4., 0.);
        assert_eq!(s.distance_squared(p(1., 3.)), 9.0);
        assert_eq!(s.nearest_point(p(1., 3.)), p(1., 0.));
        // Slanted: segment (0,0)-(3,4) (length 5); (-4,3) is at distance
        // |cross((3,4),(-4,3))| / 5 = |9 + 16| / 5 = 5, foot
        // τ = dot((3,4),(-4,3)) / 25 = 0 -> on the perpendicular at a: the
        // nearer endpoint (0,0), also at distance 5.
        let s = seg(0., 0., 3., 4.);
        assert_eq!(s.distance_squared(p(-4., 3.)), 25.0);
        assert_eq!(s.nearest_point(p(-4., 3.)), p(0., 0.));
        // (-1,7): τ = (-3 + 28) / 25 = 1 -> the endpoint b: distance^2 = 16 + 9.
        assert_eq!(s.distance_squared(p(-1., 7.)), 25.0);
        // (-2.5,4.5): τ = (-7.5 + 18) / 25 = 0.42, cross = 3*4.5 + 4*2.5 = 23.5.
        let d = s.distance(p(-2.5, 4.5));
        assert!((d - 23.5 / 5.0).abs() < 1e-15, "{d}");
    }

    #[test]
    fn distance_beyond_an_endpoint_is_to_that_endpoint() {
        let s = seg(0., 0., 4., 0.);
        // Beyond b: (7,4) is 5 from (4,0); its distance to the line is 4.
        assert_eq!(s.distance_squared(p(7., 4.)), 25.0);
        assert_eq!(s.nearest_point(p(7., 4.)), p(4., 0.));
        // Beyond a, on the supporting line.
        assert_eq!(s.distance_squared(p(-2., 0.)), 4.0);
        assert_eq!(s.nearest_point(p(-2., 0.)), p(0., 0.));
    }

    #[test]
    fn endpoints_are_recognised_exactly() {
        let s = seg(0., 0., 4., 0.);
        assert!(s.has_endpoint(p(0., 0.)));
        assert!(s.has_endpoint(p(-0., 0.)), "-0 is 0");
        assert!(s.has_endpoint(p(4., 0.)));
        assert!(!s.has_endpoint(p(4., f64::EPSILON)));
        assert!(!s.has_endpoint(p(2., 0.)), "an interior point is not an endpoint");
        assert_eq!(s.other_endpoint(p(0., 0.)), Some(p(4., 0.)));
        assert_eq!(s.other_endpoint(p(4., 0.)), Some(p(0., 0.)));
        assert_eq!(s.other_endpoint(p(1., 0.)), None);
        assert_eq!(Site::Point(p(0., 0.)).other_endpoint(p(0., 0.)), None);
    }

    #[test]
    fn segment_parameter_marks_the_open_segment() {
        let (a, b) = (p(1., 1.), p(3., 5.));
        assert_eq!(segment_parameter(a, b, a), 0.0);
        assert_eq!(segment_parameter(a, b, b), 1.0);
        assert_eq!(segment_parameter(a, b, p(2., 3.)), 0.5);
        assert!(segment_parameter(a, b, p(0., 0.)) < 0.0);
        assert!(segment_parameter(a, a, p(0., 0.)).is_nan());
    }

    #[test]
    fn zero_length_segment_does_not_panic() {
        let s = seg(1., 1., 1., 1.);
        assert_eq!(s.nearest_point(p(4., 5.)), p(1., 1.));
        assert_eq!(s.distance_squared(p(4., 5.)), 25.0);
    }
}
