//! Circular arcs as input: [`CircularArc`], an arc between two exact input
//! points on a circle fixed by a third exact datum, and the floating-point
//! geometry every part of the library asks of it (centre, radius, the
//! angular span, distances, nearest points, tangents).
//!
//! The third datum is kept as given: DXF's *bulge* `tan(θ/4)` (θ the signed
//! angle swept from start to end, positive counter-clockwise), or a point
//! the arc passes through. Either fixes the circle as an exact rational
//! one: its centre is `(s + e)/2 + k · perp(e − s)` with `k` rational in
//! the datum (`(1 − β²) / 4β` for a bulge; from the circumcentre for a
//! point). The arc's endpoints are the input's own points, so a chain of
//! segments and arcs stays closed exactly. The centre and radius held here
//! are `f64` roundings of the exact ones, for the floating-point stages;
//! the exact input check goes back to the datum.
//!
//! As with segments, the diagram sees an arc as three sites: its two
//! endpoints, and the open arc. The open arc's region lies within its
//! *cone of influence*: the wedge at the centre between the rays through
//! the endpoints. Beyond it the endpoints are nearer.

use super::arithmetic::real::{power_of_two, rounded_log2, Real};
use super::point::Point;
use crate::error::{Error, ErrorKind};

/// What fixes an arc's circle besides its endpoints.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Datum {
    /// DXF's bulge: `tan(θ/4)`, θ the signed sweep (positive
    /// counter-clockwise); finite and nonzero.
    Bulge(f64),
    /// A point strictly inside the arc, not on the chord's line.
    Through(Point),
}

/// A circular arc from `start` to `end`, less than a full turn, on a
/// circle fixed exactly by a bulge or by a third point on the arc.
///
/// ```
/// use segvoronoi::{CircularArc, Point};
///
/// // the upper half of the unit circle, counter-clockwise from (1, 0)
/// let half = CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0)?;
/// assert_eq!(half.centre(), Point::new(0.0, 0.0));
/// assert_eq!(half.radius(), 1.0);
/// assert!(half.is_counter_clockwise());
/// let same = CircularArc::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0])?;
/// assert_eq!(same.centre(), half.centre());
/// assert!((half.distance(Point::new(0.0, 3.0)) - 2.0).abs() < 1e-15);
/// # Ok::<(), segvoronoi::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircularArc {
    start: Point,
    end: Point,
    datum: Datum,
    /// The rounded centre and radius, from the datum.
    centre: Point,
    radius: f64,
    counter_clockwise: bool,
    /// Whether the sweep is less than a half turn (decided from the datum).
    minor: bool,
}

impl CircularArc {
    /// The arc from `start` to `end` with DXF's `bulge`: `tan(θ/4)` for the
    /// signed sweep θ (positive: counter-clockwise; 1: a half circle; the
    /// sweep grows toward a full turn as `|bulge|` grows).
    ///
    /// Errors ([`ErrorKind::InvalidArc`]): a non-finite coordinate or
    /// bulge, a zero bulge (a straight segment: add it as one), equal
    /// endpoints, or a circle too large or small for `f64`. An arc so flat
    /// that it is straight to within the rounding of its centre (a bulge
    /// below about 2^-42) is one, but [`Builder::add_arc`] refuses it.
    ///
    /// [`Builder::add_arc`]: crate::Builder::add_arc
    pub fn from_bulge(start: impl Into<Point>, end: impl Into<Point>, bulge: f64) -> Result<CircularArc, Error> {
        let (start, end) = (start.into(), end.into());
        let name = || format!("arc ({:?}, {:?}) - ({:?}, {:?}) with bulge {bulge:?}", start.x, start.y, end.x, end.y);
        check_ends(start, end, &name)?;
        if !bulge.is_finite() || bulge == 0.0 {
            return Err(invalid(format!("{}: the bulge must be finite and nonzero (zero is a segment)", name())));
        }
        CircularArc::new(start, end, Datum::Bulge(bulge), name)
    }

    /// The arc from `start` through `via` to `end`.
    ///
    /// Errors ([`ErrorKind::InvalidArc`]): a non-finite coordinate, two of
    /// the three points equal or all three on one line, or a circle too
    /// large or small for `f64`.
    pub fn through(start: impl Into<Point>, via: impl Into<Point>, end: impl Into<Point>) -> Result<CircularArc, Error> {
        let (start, via, end) = (start.into(), via.into(), end.into());
        let name =
            || format!("arc ({:?}, {:?}) through ({:?}, {:?}) to ({:?}, {:?})", start.x, start.y, via.x, via.y, end.x, end.y);
        check_ends(start, end, &name)?;
        if !via.is_finite() {
            return Err(invalid(format!("{}: a coordinate is not finite", name())));
        }
        if via == start || via == end {
            return Err(invalid(format!("{}: the middle point repeats an endpoint", name())));
        }
        if turn_through(start, via, end) == super::predicates::Orientation::Collinear {
            return Err(invalid(format!("{}: the three points are on one line (a segment)", name())));
        }
        CircularArc::new(start, end, Datum::Through(via), name)
    }

    fn new(start: Point, end: Point, datum: Datum, name: impl Fn() -> String) -> Result<CircularArc, Error> {
        let (centre, counter_clockwise, minor) = match datum {
            Datum::Bulge(b) => (bulge_centre(start, end, b), b > 0.0, b.abs() < 1.0),
            Datum::Through(m) => {
                let ccw = turn_through(start, m, end) == super::predicates::Orientation::CounterClockwise;
                // less than a half turn: the angle at `m` is obtuse
                let [start_u, m_u, end_u] = near_unit([start, m, end]);
                (circumcentre(start, m, end), ccw, dot(m_u, start_u, end_u) < 0.0)
            }
        };
        let radius = 0.5 * (centre.distance(start) + centre.distance(end));
        if !centre.is_finite() || !radius.is_finite() || radius <= 0.0 {
            return Err(invalid(format!("{}: its circle is out of the range of f64", name())));
        }
        Ok(CircularArc { start, end, datum, centre, radius, counter_clockwise, minor })
    }

    /// The first endpoint.
    #[inline]
    pub fn start(&self) -> Point {
        self.start
    }

    /// The last endpoint.
    #[inline]
    pub fn end(&self) -> Point {
        self.end
    }

    /// The centre of the circle (rounded to `f64`).
    #[inline]
    pub fn centre(&self) -> Point {
        self.centre
    }

    /// The radius of the circle (rounded to `f64`: the mean of the rounded
    /// centre's distances to the endpoints).
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Whether the arc runs counter-clockwise from start to end.
    #[inline]
    pub fn is_counter_clockwise(&self) -> bool {
        self.counter_clockwise
    }

    /// The bulge as given, or for an arc given by a third point the bulge
    /// of that arc (rounded).
    pub fn bulge(&self) -> f64 {
        match self.datum {
            Datum::Bulge(b) => b,
            Datum::Through(_) => {
                let sweep = self.sweep();
                (sweep / 4.0).tan()
            }
        }
    }

    /// The point the arc was given through, if it was given so.
    pub fn via(&self) -> Option<Point> {
        match self.datum {
            Datum::Through(m) => Some(m),
            Datum::Bulge(_) => None,
        }
    }

    /// The signed angle swept from start to end (positive:
    /// counter-clockwise), in `(-2π, 2π)`.
    pub fn sweep(&self) -> f64 {
        if let Datum::Bulge(b) = self.datum {
            // exact in reals; from the centre's angles a one-ulp arc would
            // lose its sweep to rounding
            return 4.0 * b.atan();
        }
        let angle = |p: Point| (p.y - self.centre.y).atan2(p.x - self.centre.x);
        let mut sweep = angle(self.end) - angle(self.start);
        let full = 2.0 * std::f64::consts::PI;
        if self.counter_clockwise {
            if sweep <= 0.0 {
                sweep += full;
            }
        } else if sweep >= 0.0 {
            sweep -= full;
        }
        sweep
    }

    /// The point at fraction `t` of the sweep (`0`: start, `1`: end).
    pub fn point_at(&self, t: f64) -> Point {
        if t <= 0.0 {
            return self.start;
        }
        if t >= 1.0 {
            return self.end;
        }
        let angle = (self.start.y - self.centre.y).atan2(self.start.x - self.centre.x) + t * self.sweep();
        Point::new(self.centre.x + self.radius * angle.cos(), self.centre.y + self.radius * angle.sin())
    }

    /// The point halfway along the arc.
    pub fn midpoint(&self) -> Point {
        match self.datum {
            // exact in reals: (s + e)/2 - (β/2) perp(e - s)
            Datum::Bulge(b) => {
                let (dx, dy) = (self.end.x - self.start.x, self.end.y - self.start.y);
                Point::new(0.5 * (self.start.x + self.end.x) + 0.5 * b * dy, 0.5 * (self.start.y + self.end.y) - 0.5 * b * dx)
            }
            Datum::Through(_) => self.point_at(0.5),
        }
    }

    /// Whether the circle of centre `centre` and radius `radius` is the
    /// arc's own to within 1e-9 of its radius (a vertex on it, another arc
    /// of it; the arcs' decisions treat such circles as one).
    pub(crate) fn has_circle(&self, centre: Point, radius: f64) -> bool {
        let tolerance = 1e-9 * self.radius();
        (radius - self.radius()).abs() <= tolerance && self.centre().distance(centre) <= tolerance
    }

    /// The arc with start and end swapped (the same point set).
    pub fn reversed(&self) -> CircularArc {
        let datum = match self.datum {
            Datum::Bulge(b) => Datum::Bulge(-b),
            through => through,
        };
        CircularArc { start: self.end, end: self.start, datum, counter_clockwise: !self.counter_clockwise, ..*self }
    }

    /// The arc with every coordinate multiplied by `factor` (a power of two
    /// keeps it exact), the centre and radius recomputed.
    pub(crate) fn scaled(&self, factor: f64) -> CircularArc {
        let datum = match self.datum {
            Datum::Through(m) => Datum::Through(m.scaled(factor)),
            bulge => bulge,
        };
        let (start, end) = (self.start.scaled(factor), self.end.scaled(factor));
        CircularArc::new(start, end, datum, String::new).unwrap_or(CircularArc {
            start,
            end,
            datum,
            centre: self.centre.scaled(factor),
            radius: self.radius * factor.abs(),
            counter_clockwise: self.counter_clockwise,
            minor: self.minor,
        })
    }

    /// The arc moved by `-origin` and then scaled by `unit` (rounded: for
    /// computing near a local origin, not for deciding), its centre and
    /// radius computed again there: near the origin they are accurate to
    /// the arc's own size, where the rounding of a centre far out can be
    /// as large as a tiny arc.
    pub(crate) fn transformed(&self, origin: Point, unit: f64) -> CircularArc {
        let t = |p: Point| Point::new((p.x - origin.x) * unit, (p.y - origin.y) * unit);
        let datum = match self.datum {
            Datum::Through(m) => Datum::Through(t(m)),
            bulge => bulge,
        };
        let (start, end) = (t(self.start), t(self.end));
        // (the turn and the sweep's half are the arc's own: a shift and a
        // positive scaling keep them, where deciding them again, exactly,
        // cost every call of the arcs' vertex solver, and could turn an arc
        // within a rounding of straight the other way)
        let centre = match datum {
            Datum::Bulge(b) => bulge_centre(start, end, b),
            Datum::Through(m) => circumcentre(start, m, end),
        };
        let radius = 0.5 * (centre.distance(start) + centre.distance(end));
        if !centre.is_finite() || !radius.is_finite() || radius <= 0.0 {
            return CircularArc { start, end, datum, centre: t(self.centre), radius: self.radius * unit, ..*self };
        }
        CircularArc { start, end, datum, centre, radius, ..*self }
    }

    /// The exact datum, for the exact input check: `(Some(bulge), None)` or
    /// `(None, Some(via))`.
    pub(crate) fn datum(&self) -> (Option<f64>, Option<Point>) {
        match self.datum {
            Datum::Bulge(b) => (Some(b), None),
            Datum::Through(m) => (None, Some(m)),
        }
    }

    /// The centre and radius of the arc's circle in the arithmetic `T`
    /// (`lift` takes an `f64` there), from its endpoints and its datum as
    /// given, not from the rounded [`centre`](Self::centre): for the
    /// refinement of near ties. `None` where the datum leaves `T`'s range.
    pub(crate) fn circle_in<T: Real>(&self, lift: &impl Fn(f64) -> T) -> Option<(T, T, T)> {
        let (sx, sy, ex, ey) = (lift(self.start.x), lift(self.start.y), lift(self.end.x), lift(self.end.y));
        let half = lift(0.5);
        let (cx, cy) = match self.datum {
            Datum::Bulge(b) => {
                // (s + e)/2 + k·perp(e − s), k = (1 − β²)/4β = (1/β − β)/4
                let beta = lift(b);
                let k = beta.recip().sub(&beta).mul(&lift(0.25));
                let (dx, dy) = (ex.sub(&sx), ey.sub(&sy));
                (sx.add(&ex).mul(&half).sub(&k.mul(&dy)), sy.add(&ey).mul(&half).add(&k.mul(&dx)))
            }
            Datum::Through(m) => {
                // the circumcentre, relative to the start
                let (bx, by) = (lift(m.x).sub(&sx), lift(m.y).sub(&sy));
                let (qx, qy) = (ex.sub(&sx), ey.sub(&sy));
                let d = bx.mul(&qy).sub(&by.mul(&qx)).mul(&lift(2.0));
                let (b2, q2) = (bx.mul(&bx).add(&by.mul(&by)), qx.mul(&qx).add(&qy.mul(&qy)));
                (sx.add(&qy.mul(&b2).sub(&by.mul(&q2)).div(&d)), sy.add(&bx.mul(&q2).sub(&qx.mul(&b2)).div(&d)))
            }
        };
        let radius = T::hypot(&cx.sub(&sx), &cy.sub(&sy));
        [cx.to_f64(), cy.to_f64(), radius.to_f64()].iter().all(|v| v.is_finite()).then_some((cx, cy, radius))
    }

    /// Whether the direction from the centre to `p` lies within the arc's
    /// angular span (the cone of influence), ends included. Floating point:
    /// near the bounding rays the answer may be either.
    pub fn spans(&self, p: Point) -> bool {
        let c = self.centre;
        // (the differences in units of about the radius: exact)
        let unit = self.unit_near_inverse_radius();
        self.spans_from_centre(((p.x - c.x) * unit, (p.y - c.y) * unit), unit)
    }

    /// A power of two near `1 / radius` (within `2^±1000`): differences
    /// from the centre times it are about 1, so that their products
    /// neither underflow near 1e-300 nor overflow near 1e300.
    fn unit_near_inverse_radius(&self) -> f64 {
        power_of_two((-rounded_log2(self.radius)).clamp(-1000.0, 1000.0) as i32)
    }

    /// Whether the direction `d` (from the centre) lies within the arc's
    /// angular span, as [`spans`](Self::spans) says of a point: for a
    /// direction at infinity, where the centre plus `d` could round back
    /// to the centre (a centre far larger than `d`).
    pub(crate) fn spans_direction(&self, d: Point) -> bool {
        let step = super::arithmetic::real::unit_near_inverse(d.x.abs().max(d.y.abs()));
        self.spans_from_centre((d.x * step, d.y * step), self.unit_near_inverse_radius())
    }

    /// `spans` of the direction `d` from the centre, of about unit size;
    /// `unit` the power of two near the inverse radius that brings the
    /// arc's ends' differences from the centre to that size.
    fn spans_from_centre(&self, (dx, dy): (f64, f64), unit: f64) -> bool {
        let c = self.centre;
        let from_centre = |u: Point| ((u.x - c.x) * unit, (u.y - c.y) * unit);
        let cross_to = |u: Point| {
            let (ux, uy) = from_centre(u);
            ux * dy - uy * dx
        };
        // counter-clockwise from `from` to `to`
        let (from, to) = if self.counter_clockwise { (self.start, self.end) } else { (self.end, self.start) };
        let (after_from, before_to) = (cross_to(from) >= 0.0, -cross_to(to) >= 0.0);
        if self.minor {
            after_from && before_to
        } else {
            after_from || before_to
        }
    }

    /// The distance from `p` to the closed arc: to the circle where `p`'s
    /// direction from the centre lies in the span, else to the nearer
    /// endpoint.
    pub fn distance(&self, p: Point) -> f64 {
        self.distance_spanning(p, self.spans(p))
    }

    /// [`distance`](Self::distance) where whether the arc
    /// [`spans`](Self::spans) `p` is known already.
    pub(crate) fn distance_spanning(&self, p: Point, spans: bool) -> f64 {
        if spans {
            (self.centre.distance(p) - self.radius).abs()
        } else {
            self.start.distance(p).min(self.end.distance(p))
        }
    }

    /// The point of the closed arc nearest to `p`.
    pub fn nearest_point(&self, p: Point) -> Point {
        self.nearest_point_spanning(p, self.spans(p))
    }

    /// [`nearest_point`](Self::nearest_point) where whether the arc
    /// [`spans`](Self::spans) `p` is known already.
    pub(crate) fn nearest_point_spanning(&self, p: Point, spans: bool) -> Point {
        if spans {
            let d = self.centre.distance(p);
            if d > 0.0 {
                let k = self.radius / d;
                return Point::new(self.centre.x + k * (p.x - self.centre.x), self.centre.y + k * (p.y - self.centre.y));
            }
            return self.midpoint();
        }
        if self.start.distance_squared(p) <= self.end.distance_squared(p) {
            self.start
        } else {
            self.end
        }
    }

    /// The unit tangent at the endpoint `at` (start or end), pointing into
    /// the arc.
    pub(crate) fn tangent_into(&self, at: Point) -> Point {
        let (rx, ry) = ((at.x - self.centre.x) / self.radius, (at.y - self.centre.y) / self.radius);
        // counter-clockwise motion at the start is the left turn of the radius
        let forward = if self.counter_clockwise { Point::new(-ry, rx) } else { Point::new(ry, -rx) };
        if at == self.start {
            forward
        } else {
            Point::new(-forward.x, -forward.y)
        }
    }

    /// The signed distance of `p` from the circle, positive on the arc's
    /// left (toward the centre for a counter-clockwise arc).
    pub(crate) fn left_of(&self, p: Point) -> f64 {
        let inside = self.radius - self.centre.distance(p);
        if self.counter_clockwise {
            inside
        } else {
            -inside
        }
    }

    /// Whether the arc is straight to within the rounding of its centre: a
    /// minor arc whose radius is over 2^40 times its chord (a bulge below
    /// about 2^-42), which [`Builder::add_arc`] refuses; its centre lies so
    /// far away that the distances taken from it are wrong by more than
    /// the arc's bend. Add its chord as a segment instead.
    ///
    /// ```
    /// use segvoronoi::CircularArc;
    /// assert!(!CircularArc::from_bulge([0.0, 0.0], [10.0, 0.0], 1e-9)?.is_straight_within_rounding());
    /// assert!(CircularArc::from_bulge([0.0, 0.0], [10.0, 0.0], 1e-17)?.is_straight_within_rounding());
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    ///
    /// [`Builder::add_arc`]: crate::Builder::add_arc
    pub fn is_straight_within_rounding(&self) -> bool {
        self.minor && self.radius > FLATTEST * self.start.distance(self.end)
    }
}

/// The points multiplied by the power of two that brings their largest
/// coordinate near 1: exact (unless a coordinate is `2^-1000` of the
/// largest or less, where it rounds to what no product could see), so
/// that the products of the exact predicates neither underflow near
/// `1e-300` nor overflow near `1e300`.
fn near_unit(points: [Point; 3]) -> [Point; 3] {
    let largest = points.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let unit = super::arithmetic::real::unit_near_inverse(largest);
    points.map(|p| Point::new(p.x * unit, p.y * unit))
}

/// The exact turn of `start → via → end`, at any magnitude.
fn turn_through(start: Point, via: Point, end: Point) -> super::predicates::Orientation {
    let [s, m, e] = near_unit([start, via, end]);
    super::predicates::exact_orientation(s, m, e)
}

fn dot(c: Point, u: Point, v: Point) -> f64 {
    (u.x - c.x) * (v.x - c.x) + (u.y - c.y) * (v.y - c.y)
}

fn check_ends(start: Point, end: Point, name: &impl Fn() -> String) -> Result<(), Error> {
    if !start.is_finite() || !end.is_finite() {
        return Err(invalid(format!("{}: a coordinate is not finite", name())));
    }
    if start == end {
        return Err(invalid(format!("{}: the endpoints are equal (a full circle is two arcs)", name())));
    }
    Ok(())
}

fn invalid(message: String) -> Error {
    Error::new(ErrorKind::InvalidArc, message, Vec::new())
}

/// `(s + e)/2 + k perp(e − s)` with `k = (1 − β²) / 4β`, `perp` the left
/// turn: the centre lies left of `s → e` for a counter-clockwise arc of
/// less than a half turn.
fn bulge_centre(s: Point, e: Point, bulge: f64) -> Point {
    let k = if bulge.abs() > 1e150 { -bulge / 4.0 } else { (1.0 - bulge * bulge) / (4.0 * bulge) };
    let (dx, dy) = (e.x - s.x, e.y - s.y);
    Point::new(0.5 * (s.x + e.x) - k * dy, 0.5 * (s.y + e.y) + k * dx)
}

/// The centre of the circle through three points not on one line,
/// computed relative to the first.
fn circumcentre(a: Point, b: Point, c: Point) -> Point {
    // in units of the triangle's size (a power of two), so that the
    // squares neither overflow near 1e300 nor underflow near 1e-300
    let size = [b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y].iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let unit = if size > 0.0 && size.is_finite() { power_of_two(-(rounded_log2(size) as i32)) } else { 1.0 };
    let (bx, by, cx, cy) = ((b.x - a.x) * unit, (b.y - a.y) * unit, (c.x - a.x) * unit, (c.y - a.y) * unit);
    let d = 2.0 * (bx * cy - by * cx);
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    Point::new(a.x + (cy * b2 - by * c2) / d / unit, a.y + (bx * c2 - cx * b2) / d / unit)
}

/// The largest radius a minor arc may have as a builder's input, as a
/// multiple of its chord: 2^40 (a bulge of about 2^-42). A flatter arc is
/// straight to within the rounding of its centre, which lies that far
/// away: a bulge of 1e-17 over a chord of 10 puts it 2.5e17 away, rounded
/// by 32, and the distances taken from it are wrong by as much (its
/// offsets were refused, or, far from the origin, answered as a circle).
/// The builder refuses such an arc (`Builder::add_arc`), and a bulged
/// polyline or polygon takes that piece as a segment. The pieces that
/// splitting cuts are not held to it: a piece a pixel long of a circle is
/// as precise as that circle.
const FLATTEST: f64 = 1_099_511_627_776.0;

/// Whether the arc of `bulge` (finite, nonzero) over any chord is straight
/// to within the rounding of its centre (see [`FLATTEST`]): its radius,
/// chord (1 + β²) / (4 |β|), over 2^40 chords.
pub(crate) fn straight_within_rounding(bulge: f64) -> bool {
    bulge.abs() < 1.0 && 1.0 + bulge * bulge > 4.0 * FLATTEST * bulge.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn a_third_point_turns_the_same_way_at_every_magnitude() {
        // the products of the orientation underflowed near 1e-200 (the arc
        // came out clockwise, its complement) and overflowed near 1e200
        for scale in [1.0, 0.1, 1e-200, 3e-300, 1e200, 1e300] {
            let s = |x: f64, y: f64| p(x * scale, y * scale);
            let major = CircularArc::through(s(0.5, 0.3), s(0.1, 0.0), s(0.5, -0.3)).unwrap();
            assert!(major.is_counter_clockwise() && major.sweep() > std::f64::consts::PI, "{scale}: {major:?}");
            let minor = CircularArc::through(s(0.5, 0.3), s(0.6, 0.0), s(0.5, -0.3)).unwrap();
            assert!(!minor.is_counter_clockwise() && minor.sweep().abs() < std::f64::consts::PI, "{scale}: {minor:?}");
            assert!(CircularArc::through(s(0.5, 0.3), s(0.5, 0.0), s(0.5, -0.3)).is_err(), "{scale}: collinear");
        }
    }

    #[test]
    fn bulge_and_third_point_give_the_same_circle() {
        let quarter = CircularArc::from_bulge([1.0, 0.0], [0.0, 1.0], (std::f64::consts::PI / 8.0).tan()).unwrap();
        let by_point = CircularArc::through([1.0, 0.0], [0.5f64.sqrt(), 0.5f64.sqrt()], [0.0, 1.0]).unwrap();
        for arc in [quarter, by_point] {
            assert!(arc.centre().distance(p(0.0, 0.0)) < 1e-15, "{arc:?}");
            assert!((arc.radius() - 1.0).abs() < 1e-15);
            assert!(arc.is_counter_clockwise());
            assert!((arc.sweep() - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
        }
        assert!((by_point.bulge() - quarter.bulge()).abs() < 1e-15);
    }

    #[test]
    fn clockwise_three_quarters() {
        // from (0, 1) clockwise to (-1, 0): through (1, 0) and (0, -1)
        let arc = CircularArc::through([0.0, 1.0], [1.0, 0.0], [-1.0, 0.0]).unwrap();
        assert!(!arc.is_counter_clockwise());
        assert!((arc.sweep() + 1.5 * std::f64::consts::PI).abs() < 1e-14);
        assert!(arc.spans(p(0.0, -5.0)) && arc.spans(p(3.0, 0.1)));
        assert!(!arc.spans(p(-1.0, 1.0)), "the missing quarter");
        assert!((arc.distance(p(-1.0, 1.0)) - 1.0).abs() < 1e-15);
        assert!((arc.distance(p(0.0, -3.0)) - 2.0).abs() < 1e-15);
        assert_eq!(arc.nearest_point(p(-2.0, 2.0)), p(0.0, 1.0));
        let bulge = (arc.sweep() / 4.0).tan();
        let again = CircularArc::from_bulge(arc.start(), arc.end(), bulge).unwrap();
        assert!(again.centre().distance(arc.centre()) < 1e-15);
        assert_eq!(arc.reversed().reversed(), arc);
        assert!(arc.reversed().is_counter_clockwise());
    }

    #[test]
    fn tangents_point_into_the_arc() {
        let arc = CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        let t = arc.tangent_into(arc.start());
        assert!((t.x - 0.0).abs() < 1e-15 && (t.y - 1.0).abs() < 1e-15, "{t:?}");
        let t = arc.tangent_into(arc.end());
        assert!((t.x - 0.0).abs() < 1e-15 && (t.y - 1.0).abs() < 1e-15, "{t:?}");
        assert!(arc.left_of(p(0.0, 0.5)) > 0.0 && arc.reversed().left_of(p(0.0, 0.5)) < 0.0);
        assert_eq!(arc.midpoint(), p(0.0, 1.0));
    }

    #[test]
    fn bad_arcs_are_refused_with_their_reason() {
        let e = CircularArc::from_bulge([0.0, 0.0], [1.0, 0.0], 0.0).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidArc);
        assert!(e.message().contains("zero is a segment"), "{e}");
        assert!(CircularArc::from_bulge([0.0, 0.0], [0.0, 0.0], 1.0).is_err());
        assert!(CircularArc::from_bulge([0.0, f64::NAN], [0.0, 1.0], 1.0).is_err());
        assert!(CircularArc::through([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]).unwrap_err().message().contains("one line"));
        assert!(CircularArc::from_bulge([0.0, 0.0], [1.0, 0.0], 1e-310).is_err(), "a circle beyond f64");
        assert!(CircularArc::from_bulge([0.0, 0.0], [1.0, 0.0], 1e-300).is_ok(), "nearly straight, still a circle");
        let huge = CircularArc::through([1e300, 0.0], [0.0, 1e300], [-1e300, 0.0]).unwrap();
        assert!(huge.centre().distance(p(0.0, 0.0)) < 1e285 && (huge.radius() / 1e300 - 1.0).abs() < 1e-15);
        // (three points near 1e-300: their orientation underflows, and the
        // arc is refused as collinear; a known limit)
        let one_ulp = CircularArc::from_bulge([0.5, 0.0], [0.5, f64::EPSILON / 2.0], 1.0).unwrap();
        assert_eq!(one_ulp.sweep(), std::f64::consts::PI);
        let nearly_full = CircularArc::from_bulge([0.0, 0.0], [1e-3, 0.0], 1e6).unwrap();
        assert!(nearly_full.sweep() > 6.28);
    }
}
