#![allow(dead_code)] // used by segment insertion (issue 3), not wired yet
//! Voronoi-vertex solvers for every combination of point and segment sites.
//!
//! A Voronoi vertex of sites `a`, `b`, `c` is the centre of a circle that
//! touches the three sites: it passes through point sites and is tangent to
//! the supporting line of each segment site. Around the vertex the regions of
//! `a`, `b`, `c` appear counter-clockwise, which is the same as saying that the
//! *touching points* of `a`, `b`, `c` lie counter-clockwise on the circle.
//! That order is what the construction knows exactly (from the topology), so
//! [`vertex`] takes it as part of the question: of the up to four algebraic
//! solutions it returns the one with that order, and where possible decides
//! which one *before* computing, so the wrong root (which may be at infinity)
//! is never evaluated. When no circle with that order exists it returns
//! `None` and the topology decides what to do.
//!
//! Touching points that coincide: when a point site `p` is an endpoint of a
//! segment site `s`, a circle centred on the perpendicular to `s` at `p`
//! touches both at `p`. Their order is then the limit order: the segment's
//! touching point is `p` moved an infinitesimal step into the segment, so `s`
//! comes just after `p` counter-clockwise when that step turns
//! counter-clockwise around the centre, and just before it otherwise.
//!
//! The cases, named by the site types after rotating to a canonical order
//! (points first; any rotation of the arguments gives the same answer):
//! - `PPP`: circumcircle ([`crate::geometry::solvers::circumcircle`]).
//! - `PPS`: circle through two points tangent to a line (quadratic).
//! - `PPS`, one point an endpoint of the segment: bisector ∩ perpendicular.
//! - `PSS`: parabola ∩ angle bisector (quadratic).
//! - `PSS`, the point an endpoint of one segment: perpendicular ∩ parabola,
//!   which on that perpendicular is linear.
//! - `PSS`, the point the common endpoint of both: the point itself, radius 0.
//! - `SSS`: in- or excentre of the triangle of the three supporting lines.
//!
//! The solvers use the segments' supporting lines. They do not reject a
//! circle whose tangent point falls outside its open segment (except that the
//! `SSS` solver uses the segments' extent to choose among three excentres):
//! the topology has already decided that the vertex exists, and a tangent
//! point a rounding error beyond an endpoint must not erase it. A caller that
//! wants the check has [`Site::nearest_point`] and
//! [`crate::geometry::site::segment_parameter`].
//!
//! Precision (all cases): not exact. Every solver works relative to a local
//! origin (a point site or a segment endpoint of the triple), turns sides and
//! orders into exact orientation predicates where they decide a case, and
//! takes each quadratic root from whichever of the two algebraically equal
//! formulas has no cancellation. The error is a few ulps of the configuration's
//! extent (the radius plus the distance from the local origin), times the
//! condition of the problem: near a double root (two solutions about to merge)
//! a perturbation `δ` of the input moves the answer by up to `√δ`, which no
//! formula avoids. Non-finite intermediate results give `None`, never a panic.

use crate::geometry::arithmetic::real::Real;
use crate::geometry::point::Point;
use crate::geometry::predicates::{orientation, turn, Orientation};
use crate::geometry::site::{segment_parameter, Site};
use crate::geometry::solvers::circumcircle;

/// The centre and radius of the circle touching `a`, `b`, `c` with touching
/// points in counter-clockwise order (see the module documentation), or `None`
/// when there is no such circle or it cannot be determined. Any rotation of
/// the arguments gives the same answer (bit for bit); swapping two arguments
/// asks for the other orientation.
pub(crate) fn vertex(a: &Site, b: &Site, c: &Site) -> Option<(Point, f64)> {
    vertex_and_condition(a, b, c).map(|(centre, r, _)| (centre, r))
}

/// [`vertex`] and the condition of its computation (see [`Solved`]): the
/// relative error is about `f64::EPSILON` times it. Three points: 1 (the
/// circumcircle is accurate to a few ulps of its radius).
pub(crate) fn vertex_and_condition(a: &Site, b: &Site, c: &Site) -> Option<(Point, f64, f64)> {
    let sites = [*a, *b, *c];
    let result = if sites.iter().all(Site::is_point) {
        ppp(rotate_smallest_first(sites)).map(|(c, r)| (c, r, 1.0))
    } else {
        with_segments(sites, &|x| x).map(|(c, r, condition)| (Point::new(c.x, c.y), r, condition))
    };
    result.filter(|(centre, r, _)| centre.is_finite() && r.is_finite() && *r >= 0.0)
}

/// The same circle as [`vertex`] computed in the arithmetic `T` (`lift` brings a coordinate into
/// it exactly) as `[x, y, r]`: every case decided as in `f64` (the same
/// exact orientations, the same root), only the arithmetic finer. For
/// ill-conditioned configurations, where `f64` loses the circle (nearly
/// parallel lines whose unit normals differ in the tenth digit), and
/// whose `f64` answer is then no start for Newton's method.
pub(crate) fn vertex_in<T: Real>(sites: &[Site; 3], lift: &impl Fn(f64) -> T) -> Option<[T; 3]> {
    let [x, y, r] = vertex_in_any_range(sites, lift)?;
    let finite = x.to_f64().is_finite() && y.to_f64().is_finite() && r.to_f64().is_finite();
    finite.then_some([x, y, r])
}

/// [`vertex_in`] wherever the circle lies, also beyond the range of
/// `f64` (an arithmetic with a wider exponent holds it: big floats).
pub(crate) fn vertex_in_any_range<T: Real>(sites: &[Site; 3], lift: &impl Fn(f64) -> T) -> Option<[T; 3]> {
    let (c, r, _) = if sites.iter().all(Site::is_point) {
        ppp_in(rotate_smallest_first(*sites), lift)?
    } else {
        with_segments(*sites, lift)?
    };
    (r.signum() >= 0).then_some([c.x, c.y, r])
}

/// A circle in the arithmetic `T` (centre, radius) and the condition of
/// its computation in `f64`: about how many ulps of the configuration's
/// size its error is, from the cancellations the solver cannot avoid
/// (nearly parallel lines, a point nearly on a line, a double root). An
/// estimate, for deciding when to solve again in a finer arithmetic.
type Solved<T> = (Vector<T>, T, f64);

/// The dispatch of [`vertex`] when a segment is among the sites.
fn with_segments<T: Real>(sites: [Site; 3], lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    match sites.iter().filter(|s| s.is_point()).count() {
        2 => {
            // The rotation that puts the segment last: (p, q, S).
            let [p, q, s] = rotate_to(sites, |site| !site.is_point(), 2);
            pps_dispatch(point_of(p)?, point_of(q)?, segment_of(s)?, lift)
        }
        1 => {
            // The rotation that puts the point first: (p, S1, S2).
            let [p, s1, s2] = rotate_to(sites, Site::is_point, 0);
            pss_dispatch(point_of(p)?, segment_of(s1)?, segment_of(s2)?, lift)
        }
        0 => {
            let [s1, s2, s3] = rotate_smallest_first(sites);
            sss(segment_of(s1)?, segment_of(s2)?, segment_of(s3)?, lift)
        }
        _ => None,
    }
}

// ---------------------------------------------------------------------------
// Canonical order.

/// The rotation of `sites` that puts the first site that is `wanted` at
/// index `at` (the identity if none is, which the callers rule out by
/// counting site types). Indices only: on the solvers' hot path, building
/// the three rotations to search them cost more than some solves.
fn rotate_to(sites: [Site; 3], wanted: impl Fn(&Site) -> bool, at: usize) -> [Site; 3] {
    let Some(k) = sites.iter().position(wanted) else { return sites };
    let shift = (k + 3 - at) % 3;
    std::array::from_fn(|i| sites[(shift + i) % 3])
}

/// The rotation that starts with the site of smallest coordinates (lexicographic
/// over the coordinates, `total_cmp`), so that the three rotations of one
/// question are computed by identical arithmetic.
fn rotate_smallest_first(sites: [Site; 3]) -> [Site; 3] {
    let key = |s: &Site| -> [f64; 4] {
        match *s {
            Site::Point(p) => [p.x, p.y, 0.0, 0.0],
            Site::Segment { a, b } => [a.x, a.y, b.x, b.y],
            Site::Arc(arc) => [arc.start().x, arc.start().y, arc.end().x, arc.end().y],
        }
    };
    let less = |s: &Site, t: &Site| {
        key(s).iter().zip(key(t).iter()).map(|(x, y)| x.total_cmp(y)).find(|o| o.is_ne()).is_some_and(|o| o.is_lt())
    };
    let [a, b, c] = sites;
    if less(&b, &a) && !less(&c, &b) {
        [b, c, a]
    } else if less(&c, &a) && less(&c, &b) {
        [c, a, b]
    } else {
        sites
    }
}

fn point_of(s: Site) -> Option<Point> {
    match s {
        Site::Point(p) => Some(p),
        Site::Segment { .. } | Site::Arc(_) => None,
    }
}

fn segment_of(s: Site) -> Option<(Point, Point)> {
    match s {
        Site::Segment { a, b } => Some((a, b)),
        Site::Point(_) | Site::Arc(_) => None,
    }
}

// ---------------------------------------------------------------------------
// Vectors in the arithmetic `T`.

/// A point or vector whose coordinates are in the arithmetic `T`.
#[derive(Clone, Debug)]
struct Vector<T> {
    x: T,
    y: T,
}

impl<T: Real> Vector<T> {
    fn of(p: Point, lift: &impl Fn(f64) -> T) -> Vector<T> {
        Vector { x: lift(p.x), y: lift(p.y) }
    }

    /// `q - p` for input points, exact in every arithmetic but `f64`.
    fn between(p: Point, q: Point, lift: &impl Fn(f64) -> T) -> Vector<T> {
        Vector::of(q, lift).sub(&Vector::of(p, lift))
    }

    fn sub(&self, o: &Vector<T>) -> Vector<T> {
        Vector { x: self.x.sub(&o.x), y: self.y.sub(&o.y) }
    }

    fn add(&self, o: &Vector<T>) -> Vector<T> {
        Vector { x: self.x.add(&o.x), y: self.y.add(&o.y) }
    }

    fn scale(&self, s: &T) -> Vector<T> {
        Vector { x: s.mul(&self.x), y: s.mul(&self.y) }
    }

    fn neg(&self) -> Vector<T> {
        Vector { x: self.x.neg(), y: self.y.neg() }
    }

    fn dot(&self, o: &Vector<T>) -> T {
        self.x.mul(&o.x).add(&self.y.mul(&o.y))
    }

    fn cross(&self, o: &Vector<T>) -> T {
        self.x.mul(&o.y).sub(&self.y.mul(&o.x))
    }

    fn norm(&self) -> T {
        T::hypot(&self.x, &self.y)
    }

    /// The vector turned a quarter counter-clockwise.
    fn rot_ccw(&self) -> Vector<T> {
        Vector { x: self.y.neg(), y: self.x.clone() }
    }

    /// `v / |v|`, or `None` for a zero or non-finite vector.
    fn unit(&self) -> Option<Vector<T>> {
        let len = self.norm();
        (len.signum() > 0 && len.to_f64().is_finite()).then(|| self.scale(&len.recip()))
    }
}

/// The unit normal of the line `a → b` that points to the side of `p`, and
/// the distance of `p` from the line, and the condition of that distance
/// (its relative error in ulps). `None` when `p` is on the line (exact
/// test) or `a == b`.
///
/// Precision: the side is exact; the distance is computed from the endpoint
/// nearer to `p`, a few ulps of that distance.
fn normal_toward<T: Real>(a: Point, b: Point, p: Point, lift: &impl Fn(f64) -> T) -> Option<(Vector<T>, T, f64)> {
    let n = Vector::between(a, b, lift).unit()?.rot_ccw();
    let n = match orientation(a, b, p) {
        Orientation::CounterClockwise => n,
        Orientation::Clockwise => n.neg(),
        Orientation::Collinear => return None,
    };
    let near = if p.distance_squared(a) <= p.distance_squared(b) { a } else { b };
    let h = n.dot(&Vector::between(near, p, lift)).abs();
    if h.signum() == 0 {
        // `p` is off the line (exact test), so its distance is not zero: the
        // arithmetic lost it (a normal tilted below the least subnormal
        // rounds to an axis), and no circle is found in it
        return None;
    }
    // the rounded normal tilts by an ulp: an error of about |p - near| ulps
    let condition = p.distance(near) / h.to_f64();
    Some((n, h, condition))
}

/// Whether the two segments lie on one line (exact).
fn collinear_segments(s: (Point, Point), t: (Point, Point)) -> bool {
    orientation(s.0, s.1, t.0) == Orientation::Collinear && orientation(s.0, s.1, t.1) == Orientation::Collinear
}

// ---------------------------------------------------------------------------
// Point, point, point.

/// Three point sites: their circumcircle when they are counter-clockwise
/// (exact test), else `None` (clockwise: the other orientation was meant;
/// collinear: no circle).
///
/// Precision: that of [`circumcircle`] (a few ulps of the radius, also for
/// needle triangles).
fn ppp(sites: [Site; 3]) -> Option<(Point, f64)> {
    let [a, b, c] = sites.map(point_of);
    let (a, b, c) = (a?, b?, c?);
    if orientation(a, b, c) != Orientation::CounterClockwise {
        return None;
    }
    circumcircle(a, b, c)
}

/// [`ppp`] in the arithmetic `T`: the circumcentre relative to the first
/// point by Cramer's rule, the orientation decided exactly. (In `f64`
/// [`circumcircle`] is the accurate one; this is for finer arithmetics,
/// where the differences of the inputs are exact.)
fn ppp_in<T: Real>(sites: [Site; 3], lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let [a, b, c] = sites.map(point_of);
    let (a, b, c) = (a?, b?, c?);
    if orientation(a, b, c) != Orientation::CounterClockwise {
        return None;
    }
    let (u, v) = (Vector::between(a, b, lift), Vector::between(a, c, lift));
    let d = lift(2.0).mul(&u.cross(&v));
    if d.signum() == 0 {
        return None;
    }
    let (u2, v2) = (u.dot(&u), v.dot(&v));
    let w = Vector { x: v.y.mul(&u2).sub(&u.y.mul(&v2)).div(&d), y: u.x.mul(&v2).sub(&v.x.mul(&u2)).div(&d) };
    let r = w.norm();
    Some((Vector::of(a, lift).add(&w), r, 1.0))
}

// ---------------------------------------------------------------------------
// Point, point, segment.

/// `(p, q, S)`: chooses the endpoint case or the general one.
fn pps_dispatch<T: Real>(p: Point, q: Point, s: (Point, Point), lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let seg = Site::Segment { a: s.0, b: s.1 };
    match (seg.other_endpoint(p), seg.other_endpoint(q)) {
        // S = pq: the perpendiculars at p and q are parallel.
        (Some(_), Some(_)) => None,
        (Some(e), None) => pps_endpoint(p, q, p, e, lift),
        (None, Some(e)) => pps_endpoint(p, q, q, e, lift),
        (None, None) => pps(p, q, s.0, s.1, lift),
    }
}

/// `(p, q, S)` where `S` runs from `shared` (which is `p` or `q`) to `far`.
///
/// The segment touches the circle at `shared`, so the centre is on the
/// perpendicular to `S` at `shared`: `u = shared + λ n` (`n` a unit normal of
/// `S`). With `v = other - shared`, `|u - shared| = |u - other|` gives
/// `λ² = λ² - 2λ n·v + |v|²`, so `λ = |v|² / (2 n·v)`: linear, one solution.
///
/// Its order: if `shared = q`, `S` touches just after `q`, which is
/// counter-clockwise exactly when `orientation(p, q, far)` is; if
/// `shared = p`, `S` touches just before `p`, i.e. `(q, S⁺, p)` must be
/// clockwise, which is again `orientation(p, q, far)` counter-clockwise. So in
/// both cases the circle is wanted iff `p, q, far` are counter-clockwise (seed
/// 000 §5.2.1). Collinear: the bisector is parallel to the perpendicular.
///
/// Precision: relative to `shared`; a few ulps of `|λ|`, except that `λ` is
/// ill-conditioned when `other` is nearly on the line of `S` (the vertex runs
/// off to infinity).
fn pps_endpoint<T: Real>(p: Point, q: Point, shared: Point, far: Point, lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    if orientation(p, q, far) != Orientation::CounterClockwise {
        return None;
    }
    let other = if shared == p { q } else { p };
    let n = Vector::between(shared, far, lift).unit()?.rot_ccw();
    let v = Vector::between(shared, other, lift);
    let denominator = lift(2.0).mul(&n.dot(&v));
    if denominator.signum() == 0 {
        return None;
    }
    let lambda = v.dot(&v).div(&denominator);
    // n . v cancels when `other` is nearly on the line of S
    let condition = 4.0 + 2.0 * v.norm().to_f64() / denominator.to_f64().abs();
    Some((Vector::of(shared, lift).add(&n.scale(&lambda)), lambda.abs(), condition))
}

/// `(p, q, S)`, neither point an endpoint of `S`: the circle through `p` and
/// `q` tangent to the line `L` of `S`.
///
/// Frame: `x` along `L`, `y` the height above `L`, origin at the foot of `p`,
/// right-handed, oriented so that `p = (0, hp)` with `hp > 0`; then
/// `q = (a, hq)` with `hq = hp + dy`. A circle tangent to `L` at `(ξ, 0)`
/// has its centre at `(ξ, r)`; through `p` and `q`:
/// `r = (ξ² + hp²) / 2hp = ((a - ξ)² + hq²) / 2hq`, i.e.
/// `dy ξ² + 2 hp a ξ - hp (a² + hq dy) = 0`, with discriminant
/// `4 hp hq |pq|²`. Both points must be strictly on one side of `L`.
///
/// Root: the touching points `p, q, t = (ξ, 0)` are counter-clockwise iff
/// `cross(q - p, t - p) = -a hp - dy ξ > 0`, which for `dy > 0` is the smaller
/// root and for `dy < 0` the larger; both are
/// `ξ = -(hp a + D) / dy` with `D = √(hp hq) |pq|`. For `a < 0` that sum
/// cancels, and the rationalised form `ξ = hp (a² + hq dy) / (hp a - D)` is
/// used instead (its denominator is then a sum of two negatives). When
/// `dy = 0` (line `pq` parallel to `L`) only the second form is finite, and
/// only for `a < 0`; for `a ≥ 0` the circle has the other order, giving
/// `None`.
///
/// Precision: relative to `p`; `r` is taken from the point farther from `L`
/// (the smaller relative error of the division). A few ulps of the
/// configuration's extent, worse when `p` or `q` is very close to `L`
/// relative to `|pq|` (the circle is then nearly determined by one point).
fn pps<T: Real>(p: Point, q: Point, a: Point, b: Point, lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let (n, hp, hp_condition) = normal_toward(a, b, p, lift)?;
    // The side of q, exactly: both points must be strictly on p's side.
    if orientation(a, b, q) != orientation(a, b, p) {
        return None;
    }
    let d = Vector { x: n.y.clone(), y: n.x.neg() }; // n = rot_ccw(d): the frame is right-handed
    let v = Vector::between(p, q, lift);
    let (along, dy) = (d.dot(&v), n.dot(&v));
    let hq = hp.add(&dy);
    let disc_root = hp.sqrt().mul(&hq.sqrt()).mul(&v.norm());
    let xi = if along.signum() >= 0 {
        if dy.signum() == 0 {
            return None;
        }
        hp.mul(&along).add(&disc_root).neg().div(&dy)
    } else {
        hp.mul(&along.mul(&along).add(&hq.mul(&dy))).div(&hp.mul(&along).sub(&disc_root))
    };
    let two = lift(2.0);
    let r = if hq.sub(&hp).signum() > 0 {
        let ax = along.sub(&xi);
        ax.mul(&ax).add(&hq.mul(&hq)).div(&two.mul(&hq))
    } else {
        xi.mul(&xi).add(&hp.mul(&hp)).div(&two.mul(&hp))
    };
    // Centre = foot of p + ξ d + r n = p + ξ d + (r - hp) n.
    let centre = Vector::of(p, lift).add(&d.scale(&xi).add(&n.scale(&r.sub(&hp))));
    // hp and hq are known to their conditions; a point nearly on the line
    // (small h against |pq|) makes the circle sensitive to them
    let hq_condition = (hp_condition * hp.to_f64() + v.norm().to_f64()) / hq.to_f64();
    let condition = 4.0 + hp_condition.max(hq_condition);
    Some((centre, r, condition))
}

// ---------------------------------------------------------------------------
// Point, segment, segment.

/// `(p, S1, S2)`: chooses the endpoint cases or the general one.
fn pss_dispatch<T: Real>(p: Point, s1: (Point, Point), s2: (Point, Point), lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let e1 = Site::Segment { a: s1.0, b: s1.1 }.other_endpoint(p);
    let e2 = Site::Segment { a: s2.0, b: s2.1 }.other_endpoint(p);
    match (e1, e2) {
        (Some(f1), Some(f2)) => pss_common_endpoint(p, f1, f2).then(|| (Vector::of(p, lift), lift(0.0), 1.0)),
        (Some(f1), None) => pss_endpoint(p, f1, true, s2, lift),
        (None, Some(f2)) => pss_endpoint(p, f2, false, s1, lift),
        (None, None) => match shared_endpoint(s1, s2) {
            Some(q) => pss_joint(p, q, s1, s2, lift),
            None => pss(p, s1, s2, lift),
        },
    }
}

/// The endpoint two segments share, if any (exact comparison).
fn shared_endpoint(s1: (Point, Point), s2: (Point, Point)) -> Option<Point> {
    [s1.0, s1.1].into_iter().find(|&q| q == s2.0 || q == s2.1)
}

/// `(p, S1, S2)` where the segments meet at an endpoint `q` (a joint of a
/// chain) and `p` is an endpoint of neither: [`pss`] with the crossing of
/// the two lines known exactly.
///
/// The centre is on a bisector of the lines through `q`; the one on `p`'s
/// side runs along `v = (n1 + n2) / |n1 + n2|` (the normals toward `p`),
/// so `u = q + t v`, radius `t κ` with `κ = n1·v = |n1 + n2| / 2`, and
/// `|u - p| = t κ` reads `(1 - κ²) t² - 2 (v·d) t + |d|² = 0`, `d = p - q`.
/// This form has no difference of nearly equal normals: where the chain
/// is nearly straight (a kink far below `f64`'s resolution, as at a joint
/// moved by a subnormal), [`pss`]'s bisector, the difference `n1 - n2`,
/// is rounding noise, while `n1 + n2` is about `2 n1` and `1 - κ² =
/// |n1 - n2|² / 4` only scales the far root. The root is [`pss`]'s rule
/// (the circles tangent to both lines are homothetic from `q`): the
/// smaller circle when `cross(n1, n2) > 0`, else the larger; that sign is
/// exact, from the turn between the segments' directions and the sides of
/// `p`, where the rounded normals may not tell it.
///
/// Precision: relative to `d`; a few ulps of `t` for the smaller root,
/// away from a double root (`p` near a tangent point).
fn pss_joint<T: Real>(p: Point, q: Point, s1: (Point, Point), s2: (Point, Point), lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    if collinear_segments(s1, s2) {
        return None;
    }
    let (n1, _, h1_condition) = normal_toward(s1.0, s1.1, p, lift)?;
    let (n2, _, h2_condition) = normal_toward(s2.0, s2.1, p, lift)?;
    let sum = n1.add(&n2);
    let v = sum.unit()?;
    let kappa = sum.norm().mul(&lift(0.5));
    let m = n1.sub(&n2);
    let a = m.dot(&m).mul(&lift(0.25)); // 1 - κ², without cancellation
    let d = Vector::between(q, p, lift);
    let b = v.dot(&d);
    let dd = d.dot(&d);
    if b.signum() <= 0 {
        return None;
    }
    let disc = b.mul(&b).sub(&a.mul(&dd));
    if disc.signum() < 0 {
        return None;
    }
    let root = disc.sqrt();
    // cross(n1, n2) = σ1 σ2 cross(u1, u2) for the directions u of the
    // segments as given and σ the side of p: exact signs
    let side = orientation(s1.0, s1.1, p).sign() * orientation(s2.0, s2.1, p).sign();
    let smaller = side * turn(s1.0, s1.1, s2.0, s2.1).sign() > 0;
    let t = if smaller {
        dd.div(&b.add(&root))
    } else {
        if a.signum() == 0 {
            return None; // the larger circle is at infinity
        }
        b.add(&root).div(&a)
    };
    let centre = Vector::of(q, lift).add(&v.scale(&t));
    let r = t.mul(&kappa);
    let disc_condition = if disc.signum() > 0 { b.mul(&b).to_f64() / disc.to_f64() } else { f64::INFINITY };
    // the larger root divides by 1 - κ², known only to ε / |n1 - n2|
    let far_condition = if smaller { 0.0 } else { 4.0 / m.dot(&m).sqrt().to_f64() };
    let condition = 4.0 + h1_condition + h2_condition + disc_condition + far_condition;
    Some((centre, r, condition))
}

/// `(p, S1, S2)` with `p` an endpoint of both: `S1 = p f1`, `S2 = p f2`.
///
/// The centre is on the perpendiculars at `p` to both segments, which meet at
/// `p` itself: the vertex is `p` with radius 0. The three regions meet there
/// in the order `(p, S1, S2)` exactly when `f1, f2` turn counter-clockwise
/// around `p` by less than a half turn (`orientation(p, f1, f2)`
/// counter-clockwise, exact): then, counter-clockwise around `p`, come the
/// strip of `S1`, the wedge between the segments where `S1` and `S2` share
/// the angle bisector, the strip of `S2`, and the region of `p` behind both
/// perpendiculars. (E.g. `S1` along +x and `S2` along +y: `S1` owns angles
/// -90°..45°, `S2` 45°..180°, `p` 180°..270°.) Otherwise no vertex: at a
/// reflex angle the order is `(p, S2, S1)`.
///
/// Collinear consecutive segments (a straight angle): the two perpendiculars
/// coincide and the region of `p` shrinks to that line, so a vertex of these
/// three sites is anywhere on it — undetermined: no vertex, and the topology
/// decides. The same for `f1`, `f2` on one side (overlapping segments, which
/// the input rules exclude).
///
/// Precision: exact (the answer is an input point).
fn pss_common_endpoint(p: Point, f1: Point, f2: Point) -> bool {
    orientation(p, f1, f2) == Orientation::CounterClockwise
}

/// `(p, S1, S2)` where `p` is an endpoint of exactly one of the segments: the
/// segment `p → far` (which is `S1` when `incident_first`, else `S2`), and
/// `other`, the segment not incident to `p`.
///
/// The centre lies on the perpendicular at `p`: `u = p + λ m` with `λ > 0`,
/// where the unit normal `m` is chosen by the order. The circle touches the
/// incident segment at `p`, and its touching point moves from `p` along the
/// segment, which is counter-clockwise around `u` iff `u` is to the left of
/// `p → far`. `S1` must come just after `p`, so for `incident_first`
/// `m` = left normal of `p → far`; `S2` must come just before `p`, so
/// otherwise `m` = right normal.
///
/// With `n` the unit normal of `other`'s line toward `p` and `h > 0` the
/// distance of `p` from it, `u` must be on `p`'s side of that line (a point
/// on the other side is nearer to the line than to `p`), at height
/// `h + λ c`, `c = m·n`. `|u - p| = λ = h + λ c` gives `λ = h / (1 - c)`,
/// valid when `c < 1`; `1 - c` is computed as `|m - n|² / 2` to keep it
/// accurate when the lines are nearly parallel (`λ` then runs off to
/// infinity, as it should). `p` on `other`'s line (exact test): `None` — it
/// would touch at `p` itself, outside the open segment `other`.
///
/// Precision: relative to `p`; a few ulps of `λ`.
fn pss_endpoint<T: Real>(
    p: Point,
    far: Point,
    incident_first: bool,
    other: (Point, Point),
    lift: &impl Fn(f64) -> T,
) -> Option<Solved<T>> {
    let d = Vector::between(p, far, lift).unit()?;
    let m = if incident_first { d.rot_ccw() } else { d.rot_ccw().neg() };
    let (n, h, h_condition) = normal_toward(other.0, other.1, p, lift)?;
    let gap = m.sub(&n);
    let one_minus_c = lift(0.5).mul(&gap.dot(&gap));
    if one_minus_c.signum() == 0 {
        return None;
    }
    let lambda = h.div(&one_minus_c);
    // m - n, a difference of rounded unit normals, is known to a few ulps
    // absolutely: nearly parallel lines lose its digits
    let condition = 4.0 + h_condition + 4.0 / gap.norm().to_f64();
    Some((Vector::of(p, lift).add(&m.scale(&lambda)), lambda, condition))
}

/// `(p, S1, S2)`, `p` an endpoint of neither: parabola ∩ angle bisector.
///
/// With `n_i` the unit normal of line `i` toward `p` and `h_i > 0` the
/// distance of `p` from it, a point `p + w` is at height `h_i + n_i·w` above
/// line `i`. The centre is on `p`'s side of both lines (a point on the far
/// side of a line is nearer to it than to `p`), so the angle bisector is
/// `(n1 - n2)·w = h2 - h1`: the line through `w0 = (h2 - h1) m / |m|²`
/// (`m = n1 - n2`) with direction `e = rot_ccw(m) / |m|`. (Parallel lines:
/// `m = 2 n1`, the mid-line of the strip; same-side parallel or coincident:
/// `m = 0`, no vertex.) On it, `w = w0 + t e`, the parabola `|w| = h1 + n1·w`
/// reads `(1 - k²) t² - 2 g k t + |w0|² - g² = 0` with `k = n1·e`,
/// `g = h1 + n1·w0`, discriminant `Δ = g² - (1 - k²) |w0|²`.
///
/// Root: the lines meet at `O`; the circles tangent to both form a
/// homothetic family from `O`, and `p` is the far point (from `O`) of the
/// smaller solution circle and the near point of the larger. The near arc is
/// the one between the tangent points, so there `p` sits between the
/// touching directions `-n1`, `-n2`; those turn counter-clockwise iff
/// `cross(n1, n2) > 0`. Working it through, `(p, S1, S2)` is the smaller
/// circle when `cross(n1, n2) > 0` and the larger otherwise — and
/// `e·(n1 + n2) = 2 cross(n1, n2)`, so `e` points away from `O` exactly in
/// the first case: either way the wanted root is the smaller `t`,
/// `t = (g k - √Δ) / (1 - k²) = (|w0|² - g²) / (g k + √Δ)`, the first form
/// for `g k ≤ 0` and the second for `g k > 0` (no cancellation; the second
/// never divides by zero, so the far root of nearly parallel lines is not
/// computed when it is not wanted). In the strip, `k = 0` and
/// `t = -√Δ`, the same rule. `Δ < 0`: the bisector misses the parabola.
///
/// `p` on a supporting line (exact test): `None`, it would be touched at `p`,
/// outside that open segment. Collinear segments (exact test): `None`.
///
/// Precision: relative to `p`. `1 - k² = cross(n1, e)²` and
/// `Δ = (g - s|w0|)(g + s|w0|)`, `s = |cross(n1, e)|`, avoid needless
/// cancellation; the error is a few ulps of the extent times the condition,
/// which grows like `1/√Δ` near a double root (`p` near a tangent point).
/// For nearly parallel lines `m` is the difference of two rounded unit
/// normals, so its direction is known only to `ε / |m|`: a kink of 1e-10
/// rad keeps six digits in `f64` (the oracle then solves again in a finer
/// arithmetic, `vertex_in`).
fn pss<T: Real>(p: Point, s1: (Point, Point), s2: (Point, Point), lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    if collinear_segments(s1, s2) {
        return None;
    }
    let (n1, h1, h1_condition) = normal_toward(s1.0, s1.1, p, lift)?;
    let (n2, h2, h2_condition) = normal_toward(s2.0, s2.1, p, lift)?;
    let m = n1.sub(&n2);
    let mm = m.dot(&m);
    if mm.signum() == 0 {
        return None;
    }
    let w0 = m.scale(&h2.sub(&h1).div(&mm));
    let e = m.rot_ccw().scale(&mm.sqrt().recip());
    let k = n1.dot(&e);
    let s = n1.cross(&e).abs();
    let g = h1.add(&n1.dot(&w0));
    let w0_len = w0.norm();
    let disc = g.sub(&s.mul(&w0_len)).mul(&g.add(&s.mul(&w0_len)));
    if disc.signum() < 0 {
        return None;
    }
    let root = disc.sqrt();
    let gk = g.mul(&k);
    let t = if gk.signum() > 0 {
        w0_len.sub(&g).mul(&w0_len.add(&g)).div(&gk.add(&root))
    } else {
        let ss = s.mul(&s);
        if ss.signum() == 0 {
            return None;
        }
        gk.sub(&root).div(&ss)
    };
    let w = w0.add(&e.scale(&t));
    let r = w.norm();
    // m, a difference of rounded unit normals, loses its direction for
    // nearly parallel lines; a small discriminant (near a double root)
    // amplifies the error of its terms
    let disc_condition = if disc.signum() > 0 { g.mul(&g).to_f64() / disc.to_f64() } else { f64::INFINITY };
    let condition = 4.0 + h1_condition + h2_condition + 4.0 / mm.sqrt().to_f64() + disc_condition;
    Some((Vector::of(p, lift).add(&w), r, condition))
}

// ---------------------------------------------------------------------------
// Segment, segment, segment.

/// `(S1, S2, S3)`: a circle tangent to the three supporting lines.
///
/// With unit normals `n_i` (left of `a_i → b_i`) and `c_i = n_i·(a_i - o)`
/// relative to the origin `o = a_1`, a circle with centre `o + w`, radius
/// `r` and centre on side `σ_i = ±1` of line `i` solves the linear system
/// `n_i·w - σ_i r = c_i` (Cramer's rule). Up to a common sign flip (which
/// only flips `r`) there are four sign patterns: the in- and the three
/// excentres of the triangle of the lines. The touching point on line `i` is
/// in direction `-σ_i n_i` from the centre, so a pattern has the wanted order
/// iff `σ_1 n_1, σ_2 n_2, σ_3 n_3` are counter-clockwise — known before
/// solving, exactly, from the turns between the segments' directions (not
/// from the orientation of the rounded normals as points, which for lines
/// 1e-10 rad apart is noise: the three points are 1e-10 apart and their
/// triangle's area 1e-31), so every arithmetic makes the same choice. For a proper triangle one pattern (the incentre: the
/// seed's "q_i, q_j, q_k positively oriented") or three (the excentres)
/// pass; the seed leaves the choice among excentres to "the relative
/// position of the segments", which is made precise here as: the candidate
/// whose tangent points lie inside the open segments, or when none does,
/// the one whose tangent points stray least beyond the segments' ends (sum
/// of distances). For segments that do not cross, at most one excentre
/// touches all three.
///
/// Two parallel lines (a strip) make two patterns singular (a zero
/// determinant, skipped) and leave the two circles on the mid-line, one per
/// order. Three parallel lines, or two segments on one line (exact test):
/// `None` (no circle, or a whole family). Three lines through one point: the
/// answer is that point with radius about 0.
///
/// Two of the segments meeting at a joint `q` (an endpoint of both): each
/// pattern's centre is solved on the bisector through `q`, as
/// [`pss_joint`] does, not by Cramer's rule. The two lines cross at `q`
/// exactly, while from their equations alone the crossing of nearly
/// parallel lines is lost: at a joint that is straight up to rounding the
/// system of the circle across the joint (centre on the perpendicular
/// there) is singular, and the only pattern left is the circle of radius
/// about 0 at the far end of one segment, tangent to the other's line
/// beyond its end (a vertex 0.05 off its sites on a chain cut at a point
/// moved by an ulp). Three segments in a chain (two joints): the crossing
/// of the two joints' bisectors ([`solve_at_two_joints`]). The choice among
/// the patterns is made by the strays of all of them, so the condition
/// returned is the worst of theirs: an imprecise rival makes the choice
/// uncertain, and the caller solves again finer.
///
/// Precision: relative to `a_1`; each solution costs a 3×3 determinant of
/// unit-normal entries, a few ulps of the extent divided by the sine of the
/// smallest angle between the lines that matter; at a joint, a few ulps
/// divided by the angle between the third line and the bisector.
fn sss<T: Real>(s1: (Point, Point), s2: (Point, Point), s3: (Point, Point), lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let segs = [s1, s2, s3];
    if collinear_segments(s1, s2) || collinear_segments(s2, s3) || collinear_segments(s3, s1) {
        return None;
    }
    let o = s1.0;
    let mut normals = Vec::with_capacity(3);
    let mut c = Vec::with_capacity(3);
    for &(a, b) in &segs {
        let n = Vector::between(a, b, lift).unit()?.rot_ccw();
        c.push(n.dot(&Vector::between(o, a, lift)));
        normals.push(n);
    }
    let n: [Vector<T>; 3] = normals.try_into().ok()?;
    let c: [T; 3] = c.try_into().ok()?;
    let joint = sss_joints(&segs);
    // The turns between the segments' directions, exactly: the touching
    // directions `σ_i n_i` are the directions turned a quarter and
    // flipped by `σ_i`, so their order comes from these and the signs.
    let turn_of = |i: usize, j: usize| f64::from(turn(segs[i].0, segs[i].1, segs[j].0, segs[j].1).sign());
    let turns = [turn_of(0, 1), turn_of(1, 2), turn_of(2, 0)];
    const PATTERNS: [[f64; 3]; 4] = [[1.0, 1.0, 1.0], [-1.0, 1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, -1.0]];
    let mut best: Option<(f64, Vector<T>, T, f64)> = None;
    // The choice among the patterns is only as good as the worst of their
    // solutions: a candidate solved imprecisely (nearly parallel lines) has
    // a stray that means nothing, and the one chosen over it may be the
    // wrong circle however well it is conditioned itself.
    let mut worst = 0.0f64;
    for sigma in PATTERNS {
        // Three directions are counter-clockwise in this order when at
        // least two of the three consecutive turns are (none parallel).
        let left_turns = (0..3).filter(|&i| sigma[i] * sigma[(i + 1) % 3] * turns[i] > 0.0).count();
        if left_turns < 2 {
            continue;
        }
        let solved = match joint {
            Joints::Two(order, q1, q2) => {
                solve_at_two_joints(&n, sigma, order, Vector::between(o, q1, lift), Vector::between(o, q2, lift))
            }
            Joints::One(pair, q) => solve_at_joint(&n, &c, sigma, pair, Vector::between(o, q, lift), lift),
            Joints::None => solve_tangent_system(&n, &c, sigma, lift),
        };
        let Some((w, r, condition)) = solved else { continue };
        worst = worst.max(condition);
        let centre = Vector::of(o, lift).add(&w);
        let stray = stray_distance(&segs, Point::new(centre.x.to_f64(), centre.y.to_f64()));
        if best.as_ref().map_or(true, |(b, _, _, _)| stray < *b) {
            best = Some((stray, centre, r.abs(), condition));
        }
    }
    best.map(|(_, centre, r, condition)| (centre, r, condition.max(worst)))
}

/// Solves `n_i·w - σ_i r = c_i` (i = 0, 1, 2) by Cramer's rule; `None` when
/// the determinant is 0 or the result is not finite.
fn solve_tangent_system<T: Real>(n: &[Vector<T>; 3], c: &[T; 3], sigma: [f64; 3], lift: &impl Fn(f64) -> T) -> Option<Solved<T>> {
    let col_s = sigma.map(|s| lift(-s));
    let col_x = [n[0].x.clone(), n[1].x.clone(), n[2].x.clone()];
    let col_y = [n[0].y.clone(), n[1].y.clone(), n[2].y.clone()];
    let det = det3(&col_x, &col_y, &col_s);
    if det.signum() == 0 {
        return None;
    }
    let x = det3(c, &col_y, &col_s).div(&det);
    let y = det3(&col_x, c, &col_s).div(&det);
    let r = det3(&col_x, &col_y, c).div(&det);
    let finite = x.to_f64().is_finite() && y.to_f64().is_finite() && r.to_f64().is_finite();
    // Cramer's rule: the determinant of unit normals is about the product
    // of the sines of the angles between the lines
    let condition = 8.0 + 6.0 / det.to_f64().abs();
    finite.then_some((Vector { x, y }, r, condition))
}

/// Where three segments meet each other at endpoints (joints), as
/// [`sss`] uses them.
enum Joints {
    /// A chain: `[i, j, k]` with `i, j` meeting at the first point and
    /// `j, k` at the second (a triangle gives its first two joints).
    Two([usize; 3], Point, Point),
    /// `[i, j, k]` with `i, j` meeting at the point.
    One([usize; 3], Point),
    None,
}

/// The joints among three segments (exact comparisons of endpoints).
fn sss_joints(segs: &[(Point, Point); 3]) -> Joints {
    let pairs = [[0, 1, 2], [1, 2, 0], [2, 0, 1]];
    let mut meeting = pairs.iter().filter_map(|&[i, j, k]| shared_endpoint(segs[i], segs[j]).map(|q| ([i, j, k], q)));
    match (meeting.next(), meeting.next()) {
        (None, _) => Joints::None,
        (Some((pair, q)), None) => Joints::One(pair, q),
        (Some(([a, b, _], q1)), Some(([c, d, _], q2))) => {
            // the segment both joints hold is the middle of the chain
            let middle = if a == c || a == d { a } else { b };
            let other = |x: usize, y: usize| if x == middle { y } else { x };
            Joints::Two([other(a, b), middle, other(c, d)], q1, q2)
        }
    }
}

/// The circle of sign pattern `sigma` (as [`solve_tangent_system`]) when
/// lines `i` and `j` of `pair = [i, j, k]` cross at `q` (`qo`: `q` from
/// the origin of `c`): the centre is `q + t v` on the bisector
/// `v ∥ σ_i n_i + σ_j n_j` (a sum: no cancellation where the touching
/// directions nearly agree), radius `t κ` with `κ = |σ_i n_i + σ_j n_j| / 2`,
/// and line `k` fixes `t`: `n_k·(q + t v) - σ_k t κ = c_k`.
fn solve_at_joint<T: Real>(
    n: &[Vector<T>; 3],
    c: &[T; 3],
    sigma: [f64; 3],
    [i, j, k]: [usize; 3],
    qo: Vector<T>,
    lift: &impl Fn(f64) -> T,
) -> Option<Solved<T>> {
    let w = n[i].scale(&lift(sigma[i])).add(&n[j].scale(&lift(sigma[j])));
    let norm = w.norm();
    let v = w.unit()?;
    let kappa = norm.mul(&lift(0.5));
    let denominator = n[k].dot(&v).sub(&kappa.mul(&lift(sigma[k])));
    if denominator.signum() == 0 {
        return None;
    }
    let t = c[k].sub(&n[k].dot(&qo)).div(&denominator);
    let centre = qo.add(&v.scale(&t));
    let r = t.mul(&kappa);
    let finite = centre.x.to_f64().is_finite() && centre.y.to_f64().is_finite() && r.to_f64().is_finite();
    // the bisector's direction is known to ε / |w|, and line k meets it at
    // an angle whose sine is about the denominator
    let condition = 8.0 + 4.0 / norm.to_f64() + 4.0 / denominator.to_f64().abs();
    finite.then_some((centre, r, condition))
}

/// The circle of sign pattern `sigma` (as [`solve_tangent_system`]) of a
/// chain `order = [i, j, k]` whose lines `i, j` cross at `q1` and `j, k`
/// at `q2` (from the origin): the crossing of the two bisectors
/// `q1 + t v1`, `v1 ∥ σ_i n_i + σ_j n_j`, and `q2 + s v2`,
/// `v2 ∥ σ_j n_j + σ_k n_k`, radius `t κ1`, `κ1 = |σ_i n_i + σ_j n_j| / 2`.
/// Where both joints are nearly straight the circle is far away and the
/// bisectors nearly parallel: their crossing divides by the sine of the
/// angle between them, first order in the joints' turns, where the
/// equation of one joint's bisector against the third line divides by a
/// second-order difference of normals that no fixed precision holds.
fn solve_at_two_joints<T: Real>(
    n: &[Vector<T>; 3],
    sigma: [f64; 3],
    [i, j, k]: [usize; 3],
    q1: Vector<T>,
    q2: Vector<T>,
) -> Option<Solved<T>> {
    let signed = |m: usize| if sigma[m] > 0.0 { n[m].clone() } else { n[m].neg() };
    let w1 = signed(i).add(&signed(j));
    let w2 = signed(j).add(&signed(k));
    let (norm1, norm2) = (w1.norm(), w2.norm());
    let (v1, v2) = (w1.unit()?, w2.unit()?);
    let sine = v1.cross(&v2);
    if sine.signum() == 0 {
        return None;
    }
    let t = q2.sub(&q1).cross(&v2).div(&sine);
    let centre = q1.add(&v1.scale(&t));
    let r = t.mul(&signed(i).dot(&v1));
    let finite = centre.x.to_f64().is_finite() && centre.y.to_f64().is_finite() && r.to_f64().is_finite();
    let condition = 8.0 + 4.0 / norm1.to_f64() + 4.0 / norm2.to_f64() + 4.0 / sine.to_f64().abs();
    finite.then_some((centre, r, condition))
}

/// The determinant of the 3×3 matrix with columns `a`, `b`, `c`.
fn det3<T: Real>(a: &[T; 3], b: &[T; 3], c: &[T; 3]) -> T {
    let minor = |i: usize, j: usize| b[i].mul(&c[j]).sub(&b[j].mul(&c[i]));
    a[0].mul(&minor(1, 2)).sub(&a[1].mul(&minor(0, 2))).add(&a[2].mul(&minor(0, 1)))
}

/// How far, in all, the feet of `centre` on the three supporting lines lie
/// beyond the ends of their segments (0 when all are inside).
fn stray_distance(segs: &[(Point, Point); 3], centre: Point) -> f64 {
    segs.iter()
        .map(|&(a, b)| {
            let t = segment_parameter(a, b, centre);
            let beyond = if t < 0.0 { -t } else { (t - 1.0).max(0.0) };
            beyond * a.distance(b)
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::TAU;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn sub(a: Point, b: Point) -> Point {
        Point::new(a.x - b.x, a.y - b.y)
    }

    fn add(a: Point, b: Point) -> Point {
        Point::new(a.x + b.x, a.y + b.y)
    }

    fn scale(s: f64, v: Point) -> Point {
        Point::new(s * v.x, s * v.y)
    }

    fn cross(a: Point, b: Point) -> f64 {
        a.x * b.y - a.y * b.x
    }

    fn pt(x: f64, y: f64) -> Site {
        Site::Point(p(x, y))
    }

    fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Site {
        Site::Segment { a: p(ax, ay), b: p(bx, by) }
    }

    /// `vertex` of the three rotations, which must agree bit for bit.
    fn solve(a: Site, b: Site, c: Site) -> Option<(Point, f64)> {
        let first = vertex(&a, &b, &c);
        let bits = |v: Option<(Point, f64)>| v.map(|(q, r)| [q.x, q.y, r].map(f64::to_bits));
        assert_eq!(bits(first), bits(vertex(&b, &c, &a)), "rotation (b, c, a)");
        assert_eq!(bits(first), bits(vertex(&c, &a, &b)), "rotation (c, a, b)");
        first
    }

    #[track_caller]
    fn assert_circle(got: Option<(Point, f64)>, cx: f64, cy: f64, r: f64) {
        let (c, radius) = got.expect("a circle");
        let tol = 1e-12 * (r + cx.abs().max(cy.abs()));
        assert!(
            (c.x - cx).abs() <= tol && (c.y - cy).abs() <= tol && (radius - r).abs() <= tol,
            "got {c:?} r={radius}, want ({cx}, {cy}) r={r}"
        );
    }

    /// The angle around `centre` at which `site` touches the circle. A
    /// segment whose endpoint is a point site of the triple touches at that
    /// endpoint, moved a hair along the segment (the limit order of the
    /// module documentation).
    fn touching_angle(site: &Site, others: &[Site], centre: Point) -> f64 {
        let angle = |q: Point| (q.y - centre.y).atan2(q.x - centre.x);
        match *site {
            Site::Point(q) => angle(q),
            Site::Segment { a, b } => {
                for o in others {
                    if let Site::Point(q) = *o {
                        if let Some(far) = site.other_endpoint(q) {
                            let turn = cross(sub(q, centre), sub(far, q)).signum();
                            return angle(q) + 1e-7 * turn;
                        }
                    }
                }
                let t = segment_parameter(a, b, centre);
                angle(Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)))
            }
            Site::Arc(_) => angle(site.nearest_point(centre)),
        }
    }

    /// Whether the touching points of `sites` are counter-clockwise around
    /// `centre`.
    fn touching_order_is_ccw(sites: [Site; 3], centre: Point) -> bool {
        let th = sites.map(|s| touching_angle(&s, &sites, centre));
        let a1 = (th[1] - th[0]).rem_euclid(TAU);
        let a2 = (th[2] - th[0]).rem_euclid(TAU);
        0.0 < a1 && a1 < a2
    }

    // --- point, point, point ----------------------------------------------

    #[test]
    fn ppp_is_the_circumcircle_of_a_ccw_triple_only() {
        // Right angle at the origin: centre the hypotenuse's midpoint (2, 1.5),
        // radius half the hypotenuse, 5 / 2.
        let (a, b, c) = (pt(0., 0.), pt(4., 0.), pt(0., 3.));
        assert_circle(solve(a, b, c), 2.0, 1.5, 2.5);
        assert_eq!(solve(b, a, c), None, "clockwise");
        assert_eq!(solve(pt(0., 0.), pt(1., 1.), pt(2., 2.)), None, "collinear");
    }

    // --- point, point, segment --------------------------------------------

    #[test]
    fn pps_two_roots_are_told_apart_by_the_order() {
        // Line y = 0. (3,1) and (-4,2) both lie on the circle centred (0,5)
        // of radius 5 (9 + 16 = 16 + 9 = 25), tangent at (0,0). Angles seen
        // from (0,5): (-4,2) at 217°, the tangent point at 270°, (3,1) at
        // 307°: counter-clockwise order ((-4,2), S, (3,1)) = ((3,1), (-4,2), S).
        // The other circle tangent at (x,0): (3-x)^2 + 1 = 2R and
        // (4+x)^2 + 4 = 4R give x^2 - 20x = 0, so x = 20, R = (17^2 + 1)/2 = 145.
        let s = seg(-30., 0., 30., 0.);
        let (q1, q2) = (pt(3., 1.), pt(-4., 2.));
        assert_circle(solve(q1, q2, s), 0.0, 5.0, 5.0);
        assert_circle(solve(q2, q1, s), 20.0, 145.0, 145.0);
        // The segment's direction does not matter.
        assert_circle(solve(q1, q2, seg(30., 0., -30., 0.)), 0.0, 5.0, 5.0);
        assert_circle(solve(q2, q1, seg(30., 0., -30., 0.)), 20.0, 145.0, 145.0);
    }

    #[test]
    fn pps_points_parallel_to_the_line_have_one_circle() {
        // (1,1), (-1,1) over y = 0: only the circle centred (0,1), radius 1
        // (r^2 = 1 + (1-r)^2). From (0,1): (1,1) at 0°, (-1,1) at 180°, the
        // tangent point at 270°: order ((1,1), (-1,1), S).
        let s = seg(-5., 0., 5., 0.);
        assert_circle(solve(pt(1., 1.), pt(-1., 1.), s), 0.0, 1.0, 1.0);
        // The other order would need the second root, which is at infinity.
        assert_eq!(solve(pt(-1., 1.), pt(1., 1.), s), None);
    }

    #[test]
    fn pps_nearly_parallel_takes_the_rationalised_root() {
        // (1,0.7) and (-1,0.7+1e-12) over y = 0 (as doubles). Exact, from
        // 60-digit arithmetic on those doubles: tangent point
        // x = 1.8213882782917e-13, radius 1.064285714285454. The textbook
        // form -(hp a + D) / dy divides a cancelled difference, rounded to
        // about 1e-16, by dy = 1e-12, and is off by about 1e-4.
        let s = seg(-5., 0., 5., 0.);
        let (c, r) = solve(pt(1., 0.7), pt(-1., 0.7 + 1e-12), s).expect("a circle");
        assert!((c.x - 1.8213882782917e-13).abs() < 1e-14, "{c:?}");
        assert!((r - 1.064285714285454).abs() < 1e-14 && (c.y - r).abs() < 1e-14, "{c:?} {r}");
    }

    #[test]
    fn pps_degenerate_sides() {
        let s = seg(-5., 0., 5., 0.);
        // The line separates the points: no circle touches it and both.
        assert_eq!(solve(pt(1., 1.), pt(-1., -1.), s), None);
        assert_eq!(solve(pt(-1., -1.), pt(1., 1.), s), None);
        // A point on the supporting line (outside the segment) is touched at
        // itself, never inside the open segment.
        assert_eq!(solve(pt(7., 0.), pt(-1., 1.), s), None);
        assert_eq!(solve(pt(-1., 1.), pt(7., 0.), s), None);
    }

    #[test]
    fn pps_with_an_endpoint_is_perpendicular_meets_bisector() {
        // S from p = (0,0) to (1,0); the centre is on x = 0. With q = (1,-1):
        // y^2 = 1 + (y+1)^2 gives y = -1, centre (0,-1), radius 1. From it q
        // is at 0°, p at 90°, and S touches just clockwise of p (moving +x at
        // the top of the circle): order (q, S, p) = (p, q, S).
        let s = seg(0., 0., 1., 0.);
        assert_circle(solve(pt(0., 0.), pt(1., -1.), s), 0.0, -1.0, 1.0);
        assert_eq!(solve(pt(1., -1.), pt(0., 0.), s), None, "wrong order");
        // The endpoint second: q' = (0,0) with S just after it. Centre (0,1)
        // (x^2... y^2 = 1 + (y-1)^2 for p' = (-1,1) gives y = 1); from it p'
        // is at 180°, q' at 270°, S at 270° + (moving +x at the bottom).
        assert_circle(solve(pt(-1., 1.), pt(0., 0.), s), 0.0, 1.0, 1.0);
        assert_eq!(solve(pt(0., 0.), pt(-1., 1.), s), None, "wrong order");
        // The other point on the supporting line: bisector parallel to the
        // perpendicular.
        assert_eq!(solve(pt(0., 0.), pt(3., 0.), s), None);
        assert_eq!(solve(pt(3., 0.), pt(0., 0.), s), None);
        // Both points are endpoints: perpendiculars parallel.
        assert_eq!(solve(pt(0., 0.), pt(1., 0.), s), None);
        assert_eq!(solve(pt(1., 0.), pt(0., 0.), s), None);
    }

    // --- point, segment, segment ------------------------------------------

    #[test]
    fn pss_parabola_meets_angle_bisector() {
        // Lines y = 0 and x = 0, p = (1,2): centres (s,s) with
        // (s-1)^2 + (s-2)^2 = s^2, i.e. s^2 - 6s + 5 = 0, s = 1 or 5.
        // From (5,5): S2 touches at 180°, p at 217°, S1 at 270°: (p, S1, S2).
        // From (1,1): p at 90°, S2 at 180°, S1 at 270°: (p, S2, S1).
        let (s1, s2) = (seg(0.5, 0., 10., 0.), seg(0., 0.5, 0., 10.));
        let q = pt(1., 2.);
        assert_circle(solve(q, s1, s2), 5.0, 5.0, 5.0);
        assert_circle(solve(q, s2, s1), 1.0, 1.0, 1.0);
        // Reversing a segment's direction changes nothing.
        assert_circle(solve(q, seg(10., 0., 0.5, 0.), s2), 5.0, 5.0, 5.0);
    }

    #[test]
    fn pss_strip_of_parallel_segments() {
        // y = 0 and y = 2, p = (0, 1.5): centre (x, 1), radius 1, with
        // x^2 + 0.25 = 1, x = ±√0.75. From (+√0.75, 1): S2 at 90°, p at about
        // 150°, S1 at 270°: (p, S1, S2). The other root has the other order.
        let (s1, s2) = (seg(-10., 0., 10., 0.), seg(10., 2., -10., 2.));
        let q = pt(0., 1.5);
        let x = 0.75f64.sqrt();
        assert_circle(solve(q, s1, s2), x, 1.0, 1.0);
        assert_circle(solve(q, s2, s1), -x, 1.0, 1.0);
    }

    #[test]
    fn pss_degenerate_lines() {
        let q = pt(0., 1.);
        // Parallel, both below p: no point is equidistant from the two lines
        // on p's side.
        assert_eq!(solve(q, seg(-5., 0., 5., 0.), seg(-5., -2., 5., -2.)), None);
        // Collinear segments: every circle touching the line does.
        let (s1, s2) = (seg(-5., 0., -1., 0.), seg(1., 0., 5., 0.));
        assert_eq!(solve(q, s1, s2), None);
        assert_eq!(solve(q, s2, s1), None);
        // p on the supporting line of S2, outside it.
        assert_eq!(solve(pt(3., 0.), seg(0., 1., 0., 5.), seg(-5., 0., -1., 0.)), None);
        assert_eq!(solve(pt(3., 0.), seg(-5., 0., -1., 0.), seg(0., 1., 0., 5.)), None);
    }

    #[test]
    fn pss_with_p_an_endpoint_of_one_segment() {
        // S1 from p = (0,0) along +x; the centre is on x = 0.
        // Other line x = 4: from (0,λ), |λ| = 4 - 0 gives (0,4) or (0,-4),
        // radius 4. From (0,4): p at 270°, S1 just after (moving +x at the
        // bottom), S2 at 0°: (p, S1, S2). From (0,-4): S2 at 0°, S1 just
        // before p (moving +x at the top is clockwise), p at 90°: (p, S2, S1).
        let q = pt(0., 0.);
        let s1 = seg(0., 0., 3., 0.);
        let s2 = seg(4., -10., 4., 10.);
        assert_circle(solve(q, s1, s2), 0.0, 4.0, 4.0);
        assert_circle(solve(q, s2, s1), 0.0, -4.0, 4.0);
        // Other line y = 4: only (0,2), radius 2 (|λ| = 4 - λ); below p the
        // circle would have to reach y = 4 with centre below 0.
        let s3 = seg(-5., 4., 5., 4.);
        assert_circle(solve(q, s1, s3), 0.0, 2.0, 2.0);
        assert_eq!(solve(q, s3, s1), None);
        // Other line y = -4 lies on the other side: mirror image.
        let s4 = seg(-5., -4., 5., -4.);
        assert_circle(solve(q, s4, s1), 0.0, -2.0, 2.0);
        assert_eq!(solve(q, s1, s4), None);
        // p on the other segment's supporting line.
        assert_eq!(solve(q, s1, seg(-1., 0., -5., 0.)), None);
    }

    #[test]
    fn pss_at_a_joint_straight_to_far_below_an_ulp() {
        // The chain (4,12) - (1,15) - (-e,16) with e = 4 x 2^-1074 turns by
        // about 2^-1076 rad at (1,15) (c_tests/fixtures/
        // search_denormal_nudged_junction_5seg.txt); the point (1,10). The
        // circle through the point tangent to both pieces: centre on the
        // perpendicular at the joint, (-1.5, 12.5), radius √12.5, to far
        // below an ulp. The normals' difference is rounding noise there;
        // solved on the bisector through the joint it is not.
        let e = -4.0 * f64::from_bits(1);
        let (s12, s13) = (seg(4., 12., 1., 15.), seg(e, 16., 1., 15.));
        let q = pt(1., 10.);
        assert_circle(solve(q, s12, s13), -1.5, 12.5, 12.5f64.sqrt());
        // the other order is the far circle of the homothety, beyond f64:
        // whatever f64 makes of it is flagged for solving again
        if let Some((_, _, condition)) = vertex_and_condition(&q, &s13, &s12) {
            assert!(condition > 1e10, "condition {condition}");
        }
        // a joint at a right angle: the same circle as without the shared
        // end (pss_parabola_meets_angle_bisector), from (5,5) radius 5
        let (s1, s2) = (seg(0., 0., 10., 0.), seg(0., 0., 0., 10.));
        assert_circle(solve(pt(1., 2.), s1, s2), 5.0, 5.0, 5.0);
        assert_circle(solve(pt(1., 2.), s2, s1), 1.0, 1.0, 1.0);
    }

    #[test]
    fn pss_at_a_common_endpoint() {
        let q = pt(0., 0.);
        let east = seg(0., 0., 2., 0.);
        let north = seg(0., 0., 0., 2.);
        let south = seg(0., -2., 0., 0.);
        let west = seg(-2., 0., 0., 0.);
        // 90°: around p, S_east owns -90°..45°, S_north 45°..180°, p the rest.
        assert_eq!(solve(q, east, north), Some((p(0., 0.), 0.0)));
        assert_eq!(solve(q, north, east), None);
        // 270° (east to south counter-clockwise): the order is reversed.
        assert_eq!(solve(q, east, south), None);
        assert_eq!(solve(q, south, east), Some((p(0., 0.), 0.0)));
        // 180°: collinear neighbours, the vertex is undetermined.
        assert_eq!(solve(q, east, west), None);
        assert_eq!(solve(q, west, east), None);
    }

    // --- segment, segment, segment ----------------------------------------

    #[test]
    fn sss_incentre_of_a_triangle() {
        // The 3-4-5 triangle (0,0), (4,0), (0,3) as a closed polygon: incircle
        // radius (3 + 4 - 5) / 2 = 1, centre (1,1), touching (1,0) at 270°,
        // (1.6,1.8) at 53° and (0,1) at 180°: order (bottom, hypotenuse, left).
        let bottom = seg(0., 0., 4., 0.);
        let hyp = seg(4., 0., 0., 3.);
        let left = seg(0., 3., 0., 0.);
        assert_circle(solve(bottom, hyp, left), 1.0, 1.0, 1.0);
        // The opposite order is an excentre; every excentre of a closed
        // triangle touches two extensions, so the answer is a fallback, but it
        // must have the asked order.
        let (c, _) = solve(bottom, left, hyp).expect("an excentre");
        assert!(touching_order_is_ccw([bottom, left, hyp], c));
    }

    #[test]
    fn sss_excentre_is_chosen_by_the_segments() {
        // Same lines; segments placed so that the excircle opposite (0,0)
        // touches all three: radius area / (s - a) = 6 / (6 - 5) = 6, centre
        // (6,6), touching (6,0) (on 5..8), (0,6) (on 5..8) and
        // (6,6) - 6 (3,4)/5 = (2.4,1.2) (on the hypotenuse). Angles from
        // (6,6): left 180°, hypotenuse 233°, bottom 270°. The other two
        // excentres, (-2,2) r 2 and (3,-3) r 3, touch the x-axis at -2 and 3,
        // outside 5..8.
        let bottom = seg(5., 0., 8., 0.);
        let hyp = seg(4., 0., 0., 3.);
        let left = seg(0., 8., 0., 5.);
        assert_circle(solve(bottom, left, hyp), 6.0, 6.0, 6.0);
        // The incircle is the only circle of the other order (its feet miss
        // these segments, which is not checked: see the module docs).
        assert_circle(solve(bottom, hyp, left), 1.0, 1.0, 1.0);
    }

    #[test]
    fn sss_strip_and_transversal() {
        // y = 0, y = 2 and x = 3: centres (2,1) and (4,1), radius 1.
        // From (4,1): S2 at 90°, S3 at 180°, S1 at 270°: (S1, S2, S3).
        let (s1, s2, s3) = (seg(-10., 0., 10., 0.), seg(-10., 2., 10., 2.), seg(3., 0.5, 3., 1.5));
        assert_circle(solve(s1, s2, s3), 4.0, 1.0, 1.0);
        assert_circle(solve(s1, s3, s2), 2.0, 1.0, 1.0);
    }

    #[test]
    fn sss_degenerate_lines() {
        // Three parallel lines.
        let (s1, s2, s3) = (seg(0., 0., 1., 0.), seg(0., 1., 1., 1.), seg(0., 3., 1., 3.));
        assert_eq!(solve(s1, s2, s3), None);
        assert_eq!(solve(s1, s3, s2), None);
        // Two collinear segments and a third.
        let (s1, s2, s3) = (seg(-5., 0., -1., 0.), seg(1., 0., 5., 0.), seg(0., 1., 0., 5.));
        assert_eq!(solve(s1, s2, s3), None);
        assert_eq!(solve(s2, s1, s3), None);
    }

    // --- robustness ---------------------------------------------------------

    #[test]
    fn far_from_the_origin_the_error_stays_relative_to_the_configuration() {
        // The PPS and PSS examples above, moved by (1e9, -1e9): the answers
        // move with them to within a few ulps of 1e9.
        let (ox, oy) = (1e9, -1e9);
        let s = seg(ox - 30., oy, ox + 30., oy);
        let got = solve(pt(ox + 3., oy + 1.), pt(ox - 4., oy + 2.), s);
        assert_circle(got, ox, oy + 5.0, 5.0);
        let (s1, s2) = (seg(ox + 0.5, oy, ox + 10., oy), seg(ox, oy + 0.5, ox, oy + 10.));
        assert_circle(solve(pt(ox + 1., oy + 2.), s1, s2), ox + 5., oy + 5., 5.0);
        assert_circle(solve(pt(ox + 1., oy + 2.), s2, s1), ox + 1., oy + 1., 1.0);
    }

    #[test]
    fn degenerate_and_non_finite_inputs_do_not_panic() {
        let zero = seg(1., 1., 1., 1.);
        let nan = pt(f64::NAN, 0.);
        let inf = seg(0., 0., f64::INFINITY, 0.);
        let ordinary = [pt(0., 0.), pt(5., 1.), seg(-3., -2., 3., -2.), seg(-3., 4., 3., 4.)];
        for odd in [zero, nan, inf] {
            for x in ordinary {
                for y in ordinary {
                    for (a, b, c) in [(odd, x, y), (x, odd, y), (x, y, odd)] {
                        if let Some((c, r)) = vertex(&a, &b, &c) {
                            assert!(c.is_finite() && r.is_finite() && r >= 0.0);
                        }
                    }
                }
            }
        }
    }

    // --- property test --------------------------------------------------------

    /// What a slot of a generated configuration holds.
    #[derive(Clone, Copy, Debug, PartialEq)]
    enum Slot {
        Point,
        /// A segment tangent to the circle at the slot's angle.
        Free,
        /// A segment starting at the previous slot's point, along the
        /// circle's counter-clockwise tangent (so it touches just after it).
        After,
        /// A segment ending at the next slot's point, along the clockwise
        /// tangent (so it touches just before it).
        Before,
    }

    /// Builds the three sites touching the circle `(centre, r)`
    /// counter-clockwise at `angles`, with segments short enough not to meet
    /// each other (a tangent at angle `θ` meets the one at `φ` at distance
    /// `r |tan((θ - φ)/2)|` from its tangent point).
    fn configuration(centre: Point, r: f64, angles: [f64; 3], slots: [Slot; 3], lengths: [(f64, f64); 3]) -> [Site; 3] {
        let on_circle = |th: f64| p(centre.x + r * th.cos(), centre.y + r * th.sin());
        let tangent = |th: f64| p(-th.sin(), th.cos());
        let reach = |th: f64| {
            angles
                .iter()
                .filter(|&&o| (o - th).abs() > 1e-12)
                .map(|&o| r * ((o - th) / 2.0).tan().abs())
                .fold(f64::INFINITY, f64::min)
        };
        let mut sites = [Site::Point(centre); 3];
        for i in 0..3 {
            let (l0, l1) = lengths[i];
            sites[i] = match slots[i] {
                Slot::Point => Site::Point(on_circle(angles[i])),
                Slot::Free => {
                    let (t, d, k) = (on_circle(angles[i]), tangent(angles[i]), reach(angles[i]));
                    Site::Segment { a: add(t, scale(-l0 * k, d)), b: add(t, scale(l1 * k, d)) }
                }
                Slot::After => {
                    let th = angles[(i + 2) % 3];
                    let q = on_circle(th);
                    Site::Segment { a: q, b: add(q, scale(l1 * reach(th), tangent(th))) }
                }
                Slot::Before => {
                    let th = angles[(i + 1) % 3];
                    let q = on_circle(th);
                    Site::Segment { a: add(q, scale(-l0 * reach(th), tangent(th))), b: q }
                }
            };
        }
        sites
    }

    fn slot_kinds() -> impl Strategy<Value = [Slot; 3]> {
        let free = prop_oneof![Just(Slot::Point), Just(Slot::Free)];
        ([free.clone(), free.clone(), free], 0usize..7).prop_map(|(mut slots, attach)| {
            // attach 1..=3: slot attach-1 follows the point before it;
            // 4..=6: slot attach-4 precedes the point after it.
            match attach {
                1..=3 => {
                    let i = attach - 1;
                    slots[i] = Slot::After;
                    slots[(i + 2) % 3] = Slot::Point;
                }
                4..=6 => {
                    let i = attach - 4;
                    slots[i] = Slot::Before;
                    slots[(i + 1) % 3] = Slot::Point;
                }
                _ => {}
            }
            slots
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        #[test]
        fn touching_circle_is_found_with_its_order(
            cx in -1e3f64..1e3, cy in -1e3f64..1e3, r in 1e-2f64..1e3,
            start in 0.0f64..TAU,
            weights in [0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0],
            slots in slot_kinds(),
            lengths in [(0.05f64..0.9, 0.05f64..0.9), (0.05f64..0.9, 0.05f64..0.9),
                        (0.05f64..0.9, 0.05f64..0.9)],
        ) {
            // Three angles at least 0.3 apart (also across 2π).
            let total: f64 = weights.iter().sum::<f64>() + 1e-9;
            let gap = |w: f64| 0.3 + (TAU - 0.9) * w / total;
            let angles = [start, start + gap(weights[0]), start + gap(weights[0]) + gap(weights[1])];
            let centre = p(cx, cy);
            let sites = configuration(centre, r, angles, slots, lengths);
            let [a, b, c] = sites;

            let (got, radius) = solve(a, b, c).expect("the generating circle");
            let scale = r + cx.abs().max(cy.abs());
            let tol = 1e-9 * scale;
            prop_assert!(got.distance(centre) <= tol && (radius - r).abs() <= tol,
                "got {:?} r={} want {:?} r={}", got, radius, centre, r);
            for s in &sites {
                let d = s.distance(got);
                prop_assert!((d - radius).abs() <= tol, "site {:?}: distance {} radius {}", s, d, radius);
            }
            prop_assert!(touching_order_is_ccw(sites, got));

            // The other order: another circle of that order, or none — never
            // the generating one.
            if let Some((other, other_r)) = solve(b, a, c) {
                prop_assert!(touching_order_is_ccw([b, a, c], other),
                    "swapped order answered {:?} r={}", other, other_r);
            }
        }
    }

    /// A chain of three nearly vertical segments whose joints turn by about
    /// 7e-11 rad (c_tests/fixtures/near_vertical_chain3.txt).
    #[allow(clippy::excessive_precision)] // the doubles of the input file, digit for digit
    fn kinked_chain() -> [Point; 4] {
        [
            p(0.93524989551077042, 0.085386995976182073),
            p(0.93524989548178594, 0.18407541281776227),
            p(0.93524989545530357, 0.30131729768741955),
            p(0.93524989543751025, 0.41729566017222008),
        ]
    }

    #[test]
    fn the_far_circle_of_a_kinked_chain_is_found_in_double_double() {
        // The circle tangent to the first two pieces and through the far
        // end: about 1.8e9 away on the concave side. In f64 the angle
        // bisector of the two lines is lost (their unit normals agree to
        // ten digits) and no circle is found; double-double finds it, and
        // 400-bit floats agree to 1e-15.
        use crate::geometry::arithmetic::bigfloat::BigFloat;
        use crate::geometry::arithmetic::double_double::DoubleDouble;
        let q = kinked_chain();
        let sites = [Site::Segment { a: q[0], b: q[1] }, Site::Point(q[3]), Site::Segment { a: q[1], b: q[2] }];
        let dd = vertex_in(&sites, &DoubleDouble::from_f64).expect("a circle").map(|v| v.to_f64());
        let big = vertex_in(&sites, &|x| BigFloat::from_f64(x, 400)).expect("a circle").map(|v| v.to_f64());
        assert!(big[0] > 1e9 && big[2] > 1e9, "{big:?}");
        for k in 0..3 {
            assert!((dd[k] - big[k]).abs() <= 1e-14 * big[2], "{dd:?} {big:?}");
        }
        // and the circle touches its three sites
        let centre = p(big[0], big[1]);
        for site in &sites {
            assert!((site.distance(centre) - big[2]).abs() <= 1e-12 * big[2], "{site:?}");
        }
    }

    #[test]
    fn the_order_of_three_nearly_parallel_lines_is_decided_exactly() {
        // Three pieces of the kinked chain: the circle tangent to all three
        // is the far one on the concave side, about 1.7e9 away, with
        // touching points counter-clockwise in the order (S1, S0, S2) seen
        // from there; the rounded unit normals, 7e-11 apart, have no
        // reliable orientation as points, so the order comes from the
        // exact turns between the pieces' directions.
        use crate::geometry::arithmetic::double_double::DoubleDouble;
        let q = kinked_chain();
        let s = [0, 1, 2].map(|i| Site::Segment { a: q[i], b: q[i + 1] });
        let far = vertex_in(&[s[1], s[0], s[2]], &DoubleDouble::from_f64).expect("a circle").map(|v| v.to_f64());
        assert!(far[0] > 1e9 && far[2] > 1e9, "{far:?}");
        let centre = p(far[0], far[1]);
        for site in &s {
            assert!((site.distance(centre) - far[2]).abs() <= 1e-12 * far[2], "{site:?}");
        }
        // the other order is not the far circle
        let near = vertex_in(&[s[0], s[1], s[2]], &DoubleDouble::from_f64).map(|v| v.map(|x| x.to_f64()));
        assert!(near.map_or(true, |v| v[2] < 1.0), "{near:?}");
    }
}
