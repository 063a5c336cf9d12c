//! How a circular arc meets a point, a closed segment or another arc: the
//! contact rules of the input for arcs, decided exactly.
//!
//! # The arc as three exact points
//! Every `f64` is a dyadic rational `m · 2^e`, and so is the midpoint
//! `(s + e)/2 − (β/2) · perp(e − s)` of an arc given by its bulge `β`. So
//! every arc, however it was given, is the arc from `s` through `q` to `e`
//! for three dyadic points (`q` the midpoint, or the `via` point), and all
//! the arithmetic below is on dyadic rationals with big-integer mantissas
//! ([`Dyadic`]): sums, differences and products only, never rounded, so
//! no sign is ever wrong and no finite input overflows. The rounded
//! `centre()` and `radius()` of [`CircularArc`] are not used. An `f64`
//! circle of our own, with a proven bound on its error ([`Approx`]), sizes
//! the conservative bounding box ([`arc_box`]) and serves as a filter that
//! only ever claims the *absence* of a contact, and only when it is certain
//! (a point clearly off the circle, a segment clearly missing it, disjoint
//! circles); everything else is decided in big numbers. When two pieces
//! share an endpoint, their other common point is rational and no square
//! root is needed.
//!
//! The circle is `G(p) = A|p|² + B·x + C·y + F = 0` (`A > 0`), the
//! incircle determinant of `s, q, e, p`. The chord line `s e` meets the
//! circle only at `s` and `e` and cuts it into two open arcs, one on each
//! side; so a point `p` of the circle lies on the open arc exactly when
//! `orient(s, e, p)` has the (nonzero) sign of `orient(s, e, q)`. That one
//! linear sign replaces every angle comparison.
//!
//! # Intersection points
//! A line or a second circle meets the circle in the roots of a quadratic
//! with dyadic coefficients: points `(u ± v√Δ)/w`. Whether such a point is
//! inside the open segment or on the open arc is the sign of a linear
//! function of it, so the sign of `U + V√Δ`, decided exactly by
//! [`sign_with_root`] (squaring only when `U` and `V` have opposite signs).
//!
//! # The rules
//! - a point exactly on the open arc is a conflict; an endpoint is not;
//! - a segment or arc that shares an endpoint with the arc and meets it
//!   nowhere else is fine, tangent or not (tangent-continuous chains);
//! - any point of the open arc that also lies on the other closed piece
//!   is a conflict: a crossing, a tangency, an endpoint of the other
//!   piece inside the arc, or (same circle) an overlap;
//! - an endpoint of the arc strictly inside a segment is *not* a conflict
//!   here: the build splits the segment there. Contacts at the arc's
//!   endpoints are never conflicts of the arc.

use std::cell::OnceCell;
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::{BigInt, Sign};

use crate::geometry::arc::CircularArc;
use crate::geometry::arithmetic::bigfloat::dyadic;
use crate::geometry::point::Point;

/// An exact dyadic rational `m · 2^e`. Zero is `m = 0` (any `e`).
#[derive(Clone, Debug)]
struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    fn zero() -> Dyadic {
        Dyadic { m: BigInt::from(0), e: 0 }
    }

    /// `x` exactly (finite `x`; `-0.0` is zero).
    fn from_f64(x: f64) -> Dyadic {
        match dyadic(x) {
            None => Dyadic::zero(),
            Some((m, e)) => {
                let m = BigInt::from(m);
                Dyadic { m: if x < 0.0 { -m } else { m }, e }
            }
        }
    }

    fn sign(&self) -> i32 {
        match self.m.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }

    fn is_zero(&self) -> bool {
        self.sign() == 0
    }

    /// `self · 2^k`, exactly.
    fn times_pow2(&self, k: i64) -> Dyadic {
        Dyadic { m: self.m.clone(), e: self.e + k }
    }

    fn square(&self) -> Dyadic {
        self * self
    }
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, other: &Dyadic) -> Dyadic {
        // a zero's exponent means nothing: aligning to it could make the
        // other mantissa needlessly long
        if self.is_zero() {
            return other.clone();
        }
        if other.is_zero() {
            return self.clone();
        }
        let e = self.e.min(other.e);
        let m = (&self.m << (self.e - e) as u64) + (&other.m << (other.e - e) as u64);
        Dyadic { m, e }
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, other: &Dyadic) -> Dyadic {
        self + &(-other)
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, other: &Dyadic) -> Dyadic {
        if self.is_zero() || other.is_zero() {
            return Dyadic::zero();
        }
        Dyadic { m: &self.m * &other.m, e: self.e + other.e }
    }
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic { m: -&self.m, e: self.e }
    }
}

/// A point with dyadic coordinates.
#[derive(Clone, Debug)]
struct DPoint {
    x: Dyadic,
    y: Dyadic,
}

impl DPoint {
    fn from_point(p: Point) -> DPoint {
        DPoint { x: Dyadic::from_f64(p.x), y: Dyadic::from_f64(p.y) }
    }

    fn sub(&self, other: &DPoint) -> DPoint {
        DPoint { x: &self.x - &other.x, y: &self.y - &other.y }
    }

    fn norm2(&self) -> Dyadic {
        &self.x.square() + &self.y.square()
    }
}

/// `u.x·v.y − u.y·v.x`.
fn cross(u: &DPoint, v: &DPoint) -> Dyadic {
    &(&u.x * &v.y) - &(&u.y * &v.x)
}

/// `u·v`.
fn dot(u: &DPoint, v: &DPoint) -> Dyadic {
    &(&u.x * &v.x) + &(&u.y * &v.y)
}

/// The exact sign of `u + v·√d` (`d ≥ 0`): -1, 0 or 1. When `u` and `v·√d`
/// have opposite signs, the larger magnitude wins, found by comparing the
/// squares `u²` and `v²d` (both nonnegative, so squaring keeps the order).
fn sign_with_root(u: &Dyadic, v: &Dyadic, d: &Dyadic) -> i32 {
    let su = u.sign();
    let sv = if d.is_zero() { 0 } else { v.sign() };
    if sv == 0 || su == sv {
        return if su == 0 { sv } else { su };
    }
    if su == 0 {
        return sv;
    }
    match (&u.square() - &(&v.square() * d)).sign() {
        1 => su,
        -1 => sv,
        _ => 0,
    }
}

/// An arc prepared for the tests: the side of the chord on which the open
/// arc lies, its `f64` circle for the filters, and (made on demand) its
/// three dyadic points and exact circle `A|p|² + Bx + Cy + F = 0`, `A > 0`.
#[derive(Clone, Debug)]
pub(crate) struct ExactArc {
    arc: CircularArc,
    s: Point,
    e: Point,
    /// The sign of `orient(s, e, q)`: the side of the chord `s → e` the open
    /// arc lies on (never 0; -1 for a counter-clockwise arc).
    tau: i32,
    /// The circle in `f64` with its error bound, for the filters and the
    /// box; `None` where it is beyond `f64`'s range.
    approx: Option<Approx>,
    /// The exact circle, made when a test first needs it (the filters
    /// settle most pairs without it).
    circle: OnceCell<Circle>,
}

/// An arc's exact data: its points and its circle's equation
/// `A|p|² + Bx + Cy + F = 0`, `A > 0`.
#[derive(Clone, Debug)]
struct Circle {
    sd: DPoint,
    /// `e − s`.
    d: DPoint,
    /// A point strictly inside the arc (its midpoint or its `via`).
    q: DPoint,
    a: Dyadic,
    b: Dyadic,
    c: Dyadic,
    f: Dyadic,
}

/// An arc's circle in `f64`: `centre = (s + e)/2 + k·perp(e − s)`,
/// `radius = |e − s|·h` with `h = √(1/4 + k²)`, from `k` within `3·2^-53·h`
/// ([`Approx::of`]). The true centre lies within `err` of `centre` in each
/// coordinate and the true radius within `err` of `radius`: the rounding
/// errors are a few units of `2^-53` of the magnitudes (and `2^-1074`
/// where subnormal), `err` is `2^-40` of them (and `2^-1060`), a
/// thousandfold margin.
#[derive(Clone, Copy, Debug)]
struct Approx {
    k: f64,
    len: f64,
    h: f64,
    centre: Point,
    radius: f64,
    err: f64,
}

/// The relative slack of the filters: far above the few `2^-53` that
/// rounded distances and cross products lose.
const SLACK: f64 = 1.0 / (1u64 << 40) as f64;

/// The absolute slack (for subnormal values): far above `2^-1074`.
const TINY: f64 = f64::MIN_POSITIVE / (1u64 << 38) as f64;

fn magnitude(p: Point) -> f64 {
    p.x.abs() + p.y.abs()
}

impl Approx {
    /// The circle of `arc` in `f64`, and the exact side `tau` of the chord
    /// the open arc lies on (as in [`ExactArc`]). `k` is rounded once from
    /// an exact value: for a bulge β, `(1 − β²)/4β` in `f64` is within
    /// `3·2^-53·h` of it (`h = (1 + β²)/4|β|`), which moves the centre by at
    /// most `3·2^-53` of the radius; for a third point `q`, with `Q = q − s`
    /// and `E = e − s`, `k = Q·(E − Q) / 2 cross(Q, E)`, computed exactly
    /// and rounded once (a few products: far cheaper than the circle's
    /// equation).
    fn of(arc: &CircularArc) -> (Option<Approx>, i32) {
        let (s, e) = (arc.start(), arc.end());
        let (k, tau) = match arc.datum() {
            // for |β| > 1e150, 1/4β is below 2^-53 of β/4 (and β² would
            // overflow); the side of the midpoint is −(β/2)|e − s|²
            (Some(b), _) => (if b.abs() > 1e150 { -b / 4.0 } else { (1.0 - b * b) / (4.0 * b) }, if b > 0.0 { -1 } else { 1 }),
            (_, Some(via)) => {
                let (sd, ed, qd) = (DPoint::from_point(s), DPoint::from_point(e), DPoint::from_point(via));
                let (q, e_rel) = (qd.sub(&sd), ed.sub(&sd));
                let den = cross(&q, &e_rel).times_pow2(1);
                let k = ratio_to_f64(&dot(&q, &e_rel.sub(&q)), &den);
                (k, -den.sign())
            }
            (None, None) => (f64::NAN, 1),
        };
        (Approx::new(s, e, k), tau)
    }

    fn new(s: Point, e: Point, k: f64) -> Option<Approx> {
        let (dx, dy) = (e.x - s.x, e.y - s.y);
        let len = dx.hypot(dy);
        let h = 0.5f64.hypot(k);
        let centre = Point::new(0.5 * s.x + 0.5 * e.x - k * dy, 0.5 * s.y + 0.5 * e.y + k * dx);
        let radius = len * h;
        let err = SLACK * (magnitude(centre) + radius + magnitude(s) + magnitude(e)) + TINY;
        let finite = [k, len, h, centre.x, centre.y, radius, err].iter().all(|v| v.is_finite());
        (finite && len > 0.0).then_some(Approx { k, len, h, centre, radius, err })
    }

    /// The bound on the error of `|p − centre| − radius` computed in `f64`,
    /// against the exact `|p − c| − r`.
    fn tolerance(&self, p: Point) -> f64 {
        3.0 * self.err + SLACK * magnitude(p)
    }

    /// `|p − centre| − radius` in `f64` (non-finite when out of range).
    fn offset(&self, p: Point) -> f64 {
        (p.x - self.centre.x).hypot(p.y - self.centre.y) - self.radius
    }

    /// Whether `p` is certainly not on the circle.
    fn clearly_off(&self, p: Point) -> bool {
        let offset = self.offset(p);
        offset.is_finite() && offset.abs() > self.tolerance(p)
    }

    /// Whether the closed segment `ab` certainly misses the circle: both
    /// ends inside the disc, or the whole line outside it, or both ends
    /// outside and the foot of the centre beyond an end.
    fn misses_segment(&self, a: Point, b: Point) -> bool {
        let (oa, ob) = (self.offset(a), self.offset(b));
        let (ta, tb) = (self.tolerance(a), self.tolerance(b));
        if !(oa.is_finite() && ob.is_finite()) {
            return false;
        }
        if oa < -ta && ob < -tb {
            return true; // the disc is convex
        }
        let (wx, wy) = (b.x - a.x, b.y - a.y);
        let (ux, uy) = (self.centre.x - a.x, self.centre.y - a.y);
        let lw = wx.hypot(wy);
        // rounded cross and dot products of rounded vectors: within a few
        // 2^-53 of |w|·|c − a|, and the centre's own error times |w|
        let size = magnitude(a) + magnitude(b) + magnitude(self.centre) + self.radius;
        let scale = lw * size;
        if scale.is_nan() || scale <= f64::MIN_POSITIVE * (1u64 << 60) as f64 {
            // products near the subnormal range lose their relative
            // precision (and the slack underflows): no claim
            return false;
        }
        let tol = (3.0 * self.err + SLACK * size) * lw;
        let (cross, dot) = (wx * uy - wy * ux, wx * ux + wy * uy);
        if !(lw.is_finite() && lw > 0.0 && cross.is_finite() && dot.is_finite() && (lw * lw).is_finite()) {
            return false;
        }
        if cross.abs() > (self.radius * lw + tol) {
            return true;
        }
        oa > ta && ob > tb && (dot < -tol || dot > lw * lw + tol)
    }

    /// Whether the two circles certainly have no common point: apart, or
    /// one strictly inside the other.
    fn misses_circle(&self, other: &Approx) -> bool {
        let dc = (self.centre.x - other.centre.x).hypot(self.centre.y - other.centre.y);
        let tol = 3.0 * (self.err + other.err) + SLACK * (magnitude(self.centre) + magnitude(other.centre));
        dc.is_finite() && (dc > self.radius + other.radius + tol || dc < (self.radius - other.radius).abs() - tol)
    }
}

impl Circle {
    fn new(arc: &CircularArc) -> Circle {
        let (sd, ed) = (DPoint::from_point(arc.start()), DPoint::from_point(arc.end()));
        let d = ed.sub(&sd);
        let q = match arc.datum() {
            (_, Some(via)) => DPoint::from_point(via),
            // the midpoint (s + e)/2 − (β/2)·perp(e − s), perp(x, y) = (−y, x):
            // dyadic, since halving and products of dyadics are
            (Some(bulge), None) => {
                let half_bulge = Dyadic::from_f64(bulge).times_pow2(-1);
                DPoint {
                    x: &(&sd.x + &ed.x).times_pow2(-1) + &(&half_bulge * &d.y),
                    y: &(&sd.y + &ed.y).times_pow2(-1) - &(&half_bulge * &d.x),
                }
            }
            (None, None) => sd.clone(), // no arc: every arc has a datum
        };
        // The incircle determinant of (s, q, e, p) relative to s, expanded
        // along p's row: A|P|² + B_rel·P.x + C_rel·P.y with P = p − s.
        let (qr, er) = (q.sub(&sd), d.clone());
        let (q2, e2) = (qr.norm2(), er.norm2());
        let mut a = cross(&qr, &er);
        let mut b_rel = &(&qr.y * &e2) - &(&er.y * &q2);
        let mut c_rel = &(&er.x * &q2) - &(&qr.x * &e2);
        if a.sign() < 0 {
            a = -&a;
            b_rel = -&b_rel;
            c_rel = -&c_rel;
        }
        // absolute: A|p|² + (B_rel − 2A·s.x)x + (C_rel − 2A·s.y)y
        //           + A|s|² − B_rel·s.x − C_rel·s.y
        let two_a = a.times_pow2(1);
        let b = &b_rel - &(&two_a * &sd.x);
        let c = &c_rel - &(&two_a * &sd.y);
        let f = &(&(&a * &sd.norm2()) - &(&b_rel * &sd.x)) - &(&c_rel * &sd.y);
        // A > 0 for every arc the constructors accept (the third point is
        // off the chord). A degenerate one (only `scaled` into underflow
        // could make it) gets some answer, never a panic: nothing divides.
        Circle { sd, d, q, a, b, c, f }
    }
}

impl ExactArc {
    /// The exact form of `arc` (any arc [`CircularArc`]'s constructors
    /// accept): cheap, the circle in big numbers comes when needed.
    pub(crate) fn new(arc: &CircularArc) -> ExactArc {
        let (approx, tau) = Approx::of(arc);
        ExactArc { arc: *arc, s: arc.start(), e: arc.end(), tau, approx, circle: OnceCell::new() }
    }

    /// The exact circle.
    fn circle(&self) -> &Circle {
        self.circle.get_or_init(|| Circle::new(&self.arc))
    }

    /// `G(p)`: zero on the circle (its sign: outside positive).
    fn power(&self, p: &DPoint) -> Dyadic {
        let quad = &self.circle().a * &p.norm2();
        let lin = &(&self.circle().b * &p.x) + &(&self.circle().c * &p.y);
        &(&quad + &lin) + &self.circle().f
    }

    /// The sign of `orient(s, e, p)`.
    fn side(&self, p: &DPoint) -> i32 {
        cross(&self.circle().d, &p.sub(&self.circle().sd)).sign()
    }

    /// Whether the two arcs lie on one circle (proportional equations).
    fn same_circle(&self, other: &ExactArc) -> bool {
        let prop = |x: &Dyadic, y: &Dyadic| (&(&other.circle().a * x) - &(&self.circle().a * y)).is_zero();
        prop(&self.circle().b, &other.circle().b)
            && prop(&self.circle().c, &other.circle().c)
            && prop(&self.circle().f, &other.circle().f)
    }

    /// Whether the input point `p` lies on the open arc.
    pub(crate) fn contains_point(&self, p: Point) -> bool {
        self.contains_point_by::<true>(p)
    }

    /// [`ExactArc::contains_point`], with (`FAST`) or without the filter.
    fn contains_point_by<const FAST: bool>(&self, p: Point) -> bool {
        if p == self.s || p == self.e {
            return false;
        }
        self.on_circle::<FAST>(p) && self.side(&DPoint::from_point(p)) == self.tau
    }

    /// Whether the input point `p` lies on the circle: filtered, then exact.
    fn on_circle<const FAST: bool>(&self, p: Point) -> bool {
        if FAST && self.approx.is_some_and(|ap| ap.clearly_off(p)) {
            return false;
        }
        self.power(&DPoint::from_point(p)).is_zero()
    }

    /// [`ExactArc::contains_point`] for a point known to be on the circle.
    fn on_circle_inside(&self, p: &DPoint) -> bool {
        self.side(p) == self.tau
    }
}

/// `num / den` rounded to `f64` (relative error below `2^-52`, plus at
/// most `2^-1074` absolute where the result is subnormal; ±∞ beyond the
/// range); `den ≠ 0`.
fn ratio_to_f64(num: &Dyadic, den: &Dyadic) -> f64 {
    if num.is_zero() {
        return 0.0;
    }
    if den.is_zero() {
        return f64::INFINITY; // no arc makes it; a box over everything is safe
    }
    let negative = (num.sign() < 0) != (den.sign() < 0);
    let (n, d) = (num.m.magnitude(), den.m.magnitude());
    // a quotient of at least 64 bits, truncated, then its top 64 bits
    let shift = (d.bits() + 64).saturating_sub(n.bits());
    let quotient = (n << shift) / d;
    let drop = quotient.bits().saturating_sub(64);
    let top: u64 = (quotient >> drop).iter_u64_digits().next().unwrap_or(0);
    let exponent = num.e - den.e - shift as i64 + drop as i64;
    let value = scale_by_pow2(top as f64, exponent);
    if negative {
        -value
    } else {
        value
    }
}

/// `x · 2^k` in steps that stay in range until the last (so a subnormal
/// result is rounded once).
fn scale_by_pow2(mut x: f64, k: i64) -> f64 {
    let mut k = k.clamp(-4000, 4000);
    while k != 0 {
        let step = k.clamp(-1000, 1000);
        x *= f64::from_bits(((1023 + step) as u64) << 52);
        k -= step;
    }
    x
}

/// How a closed segment meets an arc's open part (`None`: not at all, or
/// only at the arc's endpoints).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SegmentArcContact {
    /// The open segment crosses the open arc.
    Cross,
    /// The open segment is tangent to the open arc.
    Tangent,
    /// An endpoint of the segment (or the whole of a zero-length one) lies
    /// on the open arc.
    EndOnArc,
}

/// Exact classification of the contact of the closed segment `seg` with
/// the open arc. See the module documentation for the rules.
pub(crate) fn segment_arc_contact(arc: &ExactArc, seg: [Point; 2]) -> Option<SegmentArcContact> {
    segment_arc_contact_by::<true>(arc, seg)
}

/// [`segment_arc_contact`] with (`FAST`) or without the `f64` filter and
/// the rational shortcut for a point of the segment on the circle (the
/// tests compare both).
fn segment_arc_contact_by<const FAST: bool>(arc: &ExactArc, seg: [Point; 2]) -> Option<SegmentArcContact> {
    let [mut a, mut b] = seg;
    if a == b {
        return arc.contains_point_by::<FAST>(a).then_some(SegmentArcContact::EndOnArc);
    }
    if FAST && arc.approx.is_some_and(|ap| ap.misses_segment(a, b)) {
        return None;
    }
    if FAST && (b == arc.s || b == arc.e) {
        // a common endpoint first: then it is the root t = 0 (below)
        std::mem::swap(&mut a, &mut b);
    }
    // The line a + t·w against the circle: α t² + β t + γ = 0, with
    // α = A|w|² > 0, β = 2A(a·w) + B w.x + C w.y, γ = G(a).
    let (ad, bd) = (DPoint::from_point(a), DPoint::from_point(b));
    let w = bd.sub(&ad);
    let alpha = &arc.circle().a * &w.norm2();
    let beta = &(&(&arc.circle().a * &dot(&ad, &w)).times_pow2(1) + &(&arc.circle().b * &w.x)) + &(&arc.circle().c * &w.y);
    let gamma = arc.power(&ad);
    let kappa = cross(&arc.circle().d, &w);
    let sigma_a = cross(&arc.circle().d, &ad.sub(&arc.circle().sd));
    if FAST && gamma.is_zero() {
        // `a` on the circle (a common endpoint, most often): the roots are
        // 0 and t' = −β/α, rational. t' is inside the open segment when
        // −β > 0 and α + β > 0; on the open arc when σ(a) + t'κ, times α,
        // α σ(a) − κβ, has the arc's sign. (β = 0: tangent at `a` only.)
        let inside = beta.sign() < 0 && (&alpha + &beta).sign() > 0;
        if inside && (&(&alpha * &sigma_a) - &(&kappa * &beta)).sign() == arc.tau {
            return Some(SegmentArcContact::Cross);
        }
        return (arc.contains_point_by::<FAST>(a) || arc.contains_point_by::<FAST>(b)).then_some(SegmentArcContact::EndOnArc);
    }
    let disc = &beta.square() - &(&alpha * &gamma).times_pow2(2);
    if disc.sign() >= 0 {
        // t = (−β ± √Δ)/2α. Inside the open segment: t > 0 and 1 − t > 0,
        // the signs of −β ± √Δ and 2α + β ∓ √Δ. On the open arc: the side
        // σ(a + t w) = σ(a) + t·κ (κ = cross(d, w)), times 2α: the sign of
        // 2α σ(a) − κβ ± κ√Δ must be the arc's.
        let side_u = &(&alpha * &sigma_a).times_pow2(1) - &(&kappa * &beta);
        let one = Dyadic { m: BigInt::from(1), e: 0 };
        let roots: &[i32] = if disc.is_zero() { &[1] } else { &[1, -1] };
        for &pm in roots {
            let sign_root = if pm > 0 { one.clone() } else { -&one };
            let after_a = sign_with_root(&-&beta, &sign_root, &disc) > 0;
            let before_b = after_a && sign_with_root(&(&alpha.times_pow2(1) + &beta), &-&sign_root, &disc) > 0;
            let on_arc = before_b && sign_with_root(&side_u, &(if pm > 0 { kappa.clone() } else { -&kappa }), &disc) == arc.tau;
            if on_arc {
                return Some(if disc.is_zero() { SegmentArcContact::Tangent } else { SegmentArcContact::Cross });
            }
        }
    }
    (arc.contains_point_by::<FAST>(a) || arc.contains_point_by::<FAST>(b)).then_some(SegmentArcContact::EndOnArc)
}

/// How two arcs meet in the open part of either (`None`: not at all, or
/// only at endpoints of both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ArcArcContact {
    /// The open arcs cross (two distinct circles meeting at a point inside
    /// both arcs).
    Cross,
    /// The circles are tangent at a point inside both open arcs.
    Tangent,
    /// An endpoint of the second arc lies on the open first arc.
    EndOfSecondOnFirst,
    /// An endpoint of the first arc lies on the open second arc.
    EndOfFirstOnSecond,
    /// The arcs lie on one circle and share more than a point (identical
    /// arcs included).
    Overlap,
}

/// Exact classification of the contact of two arcs. See the module
/// documentation for the rules.
pub(crate) fn arc_arc_contact(first: &ExactArc, second: &ExactArc) -> Option<ArcArcContact> {
    arc_arc_contact_by::<true>(first, second)
}

/// [`arc_arc_contact`] with (`FAST`) or without the `f64` filters and the
/// rational shortcut for arcs with a common endpoint (the tests compare
/// both).
fn arc_arc_contact_by<const FAST: bool>(first: &ExactArc, second: &ExactArc) -> Option<ArcArcContact> {
    if let (true, Some(x), Some(y)) = (FAST, first.approx, second.approx) {
        if x.misses_circle(&y) {
            return None;
        }
    }
    let ends = |arc: &ExactArc| [DPoint::from_point(arc.s), DPoint::from_point(arc.e)];
    if first.same_circle(second) {
        // Open arcs of one circle share a point exactly when an endpoint of
        // one lies inside the other, or when they have the same two
        // endpoints and lie on the same side of that chord.
        let [s2, e2] = ends(second);
        let [s1, e1] = ends(first);
        let inside = first.on_circle_inside(&s2)
            || first.on_circle_inside(&e2)
            || second.on_circle_inside(&s1)
            || second.on_circle_inside(&e1);
        let same_ends = (first.s == second.s && first.e == second.e) || (first.s == second.e && first.e == second.s);
        let same_side = same_ends && first.on_circle_inside(&second.circle().q);
        return (inside || same_side).then_some(ArcArcContact::Overlap);
    }
    if let Some(contact) = crossing_of_circles::<FAST>(first, second) {
        return Some(contact);
    }
    // an endpoint of one inside the other (common endpoints are on the
    // chord, never inside: no exact test for them, as `contains_point`)
    let own_end = |arc: &ExactArc, p: Point| FAST && (p == arc.s || p == arc.e);
    let inside =
        |arc: &ExactArc, p: Point| !own_end(arc, p) && arc.on_circle::<FAST>(p) && arc.on_circle_inside(&DPoint::from_point(p));
    if inside(first, second.s) || inside(first, second.e) {
        return Some(ArcArcContact::EndOfSecondOnFirst);
    }
    if inside(second, first.s) || inside(second, first.e) {
        return Some(ArcArcContact::EndOfFirstOnSecond);
    }
    None
}

/// A point of two distinct circles inside both open arcs: a crossing, or
/// a tangency.
fn crossing_of_circles<const FAST: bool>(first: &ExactArc, second: &ExactArc) -> Option<ArcArcContact> {
    // The radical line A₂G₁ − A₁G₂ = 0: Lx·x + Ly·y + L0 = 0.
    let lx = &(&second.circle().a * &first.circle().b) - &(&first.circle().a * &second.circle().b);
    let ly = &(&second.circle().a * &first.circle().c) - &(&first.circle().a * &second.circle().c);
    if lx.is_zero() && ly.is_zero() {
        return None; // concentric, distinct: disjoint
    }
    // On the line, p = (P0 + t·W)/N with N = Lx² + Ly², P0 = −L0·(Lx, Ly),
    // W = (−Ly, Lx) (so P0·W = 0 and |W|² = N). Then N·G₁(p) = α t² + β t + γ:
    // α = A₁, β = B₁W.x + C₁W.y, γ = A₁L0² − L0(B₁Lx + C₁Ly) + N·F₁.
    let w = DPoint { x: -&ly, y: lx.clone() };
    let common = [first.s, first.e].into_iter().find(|&p| FAST && (p == second.s || p == second.e));
    if let Some(p) = common {
        // Both circles pass through p, so the radical line does: on it,
        // p + t·W, N·G₁ = A₁N t² + β t with β = 2A₁(p·W) + B₁W.x + C₁W.y. The
        // other common point is t' = −β/A₁N, rational (β = 0: tangent at p,
        // an endpoint of both). Its side for arc i, times A₁N > 0:
        // A₁N·cross(dᵢ, p − sᵢ) − β·cross(dᵢ, W).
        let pd = DPoint::from_point(p);
        let beta =
            &(&(&first.circle().a * &dot(&pd, &w)).times_pow2(1) + &(&first.circle().b * &w.x)) + &(&first.circle().c * &w.y);
        if beta.is_zero() {
            return None;
        }
        let an = &first.circle().a * &(&lx.square() + &ly.square());
        let side = |arc: &ExactArc| {
            (&(&an * &cross(&arc.circle().d, &pd.sub(&arc.circle().sd))) - &(&beta * &cross(&arc.circle().d, &w))).sign()
        };
        return (side(first) == first.tau && side(second) == second.tau).then_some(ArcArcContact::Cross);
    }
    // (L0 only here: a common endpoint above needs none)
    let l0 = &(&second.circle().a * &first.circle().f) - &(&first.circle().a * &second.circle().f);
    let n = &lx.square() + &ly.square();
    let p0 = DPoint { x: -&(&l0 * &lx), y: -&(&l0 * &ly) };
    let alpha = &first.circle().a;
    let beta = &(&first.circle().b * &w.x) + &(&first.circle().c * &w.y);
    let gamma = &(&(alpha * &l0.square()) - &(&l0 * &(&(&first.circle().b * &lx) + &(&first.circle().c * &ly))))
        + &(&n * &first.circle().f);
    let disc = &beta.square() - &(alpha * &gamma).times_pow2(2);
    if disc.sign() < 0 {
        return None;
    }
    // With t = (−β ± √Δ)/2α: 2α·N·σᵢ(p) = U + V(−β ± √Δ)... for arc i,
    // U = 2α(cross(dᵢ, P0) − N·cross(dᵢ, sᵢ)), V = cross(dᵢ, W).
    let side_terms = |arc: &ExactArc| {
        let v = cross(&arc.circle().d, &w);
        let u = &(&(&cross(&arc.circle().d, &p0) - &(&n * &cross(&arc.circle().d, &arc.circle().sd))) * alpha).times_pow2(1);
        (u - &(&v * &beta), v)
    };
    let (u1, v1) = side_terms(first);
    let (u2, v2) = side_terms(second);
    let roots: &[bool] = if disc.is_zero() { &[true] } else { &[true, false] };
    for &plus in roots {
        let signed = |v: &Dyadic| if plus { v.clone() } else { -v };
        if sign_with_root(&u1, &signed(&v1), &disc) == first.tau && sign_with_root(&u2, &signed(&v2), &disc) == second.tau {
            return Some(if disc.is_zero() { ArcArcContact::Tangent } else { ArcArcContact::Cross });
        }
    }
    None
}

/// A box `[x_min, x_max, y_min, y_max]` that contains the closed arc:
/// its endpoints, and each extreme point of the circle (leftmost,
/// rightmost, lowest, highest) unless it is clearly outside the arc's span,
/// each widened by far more than the rounding of the centre and radius.
/// Infinite where the circle is beyond `f64`'s range.
pub(crate) fn arc_box(arc: &CircularArc) -> [f64; 4] {
    let (s, e) = (arc.start(), arc.end());
    let mut bx = [s.x.min(e.x), s.x.max(e.x), s.y.min(e.y), s.y.max(e.y)];
    let (approx, tau) = Approx::of(arc);
    let Some(Approx { k, len, h, centre, radius: r, err }) = approx else {
        return [f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY];
    };
    let (cx, cy) = (centre.x, centre.y);
    let margin = 16.0 * err;
    let (dx, dy) = (e.x - s.x, e.y - s.y);
    // The side of the chord of the extreme point c + r·u (u a unit axis
    // vector) is the sign of k|d|² + r·cross(d, u) = |d|²(k + h·cross(d̂, u)).
    let in_span = |cross_du: f64| {
        let value = k + h * (cross_du / len);
        let tolerance = 1e-9 * (k.abs() + h);
        value * tau as f64 > -tolerance
    };
    if in_span(-dy) {
        bx[1] = bx[1].max(cx + r + margin); // u = (1, 0)
    }
    if in_span(dy) {
        bx[0] = bx[0].min(cx - r - margin); // u = (−1, 0)
    }
    if in_span(dx) {
        bx[3] = bx[3].max(cy + r + margin); // u = (0, 1)
    }
    if in_span(-dx) {
        bx[2] = bx[2].min(cy - r - margin); // u = (0, −1)
    }
    bx
}

/// The order of two `f64` without NaN (`-0.0` equals `+0.0`).
pub(crate) fn cmp_f64(a: f64, b: f64) -> Ordering {
    a.partial_cmp(&b).unwrap_or(Ordering::Equal)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn through(s: [f64; 2], via: [f64; 2], e: [f64; 2]) -> CircularArc {
        CircularArc::through(s, via, e).unwrap()
    }

    fn bulged(s: [f64; 2], e: [f64; 2], bulge: f64) -> CircularArc {
        CircularArc::from_bulge(s, e, bulge).unwrap()
    }

    fn up(x: f64) -> f64 {
        f64::from_bits(if x >= 0.0 { x.to_bits() + 1 } else { x.to_bits() - 1 })
    }

    fn down(x: f64) -> f64 {
        -up(-x)
    }

    /// A named map of the plane and a power-of-two factor.
    type Transform = (&'static str, fn(Point) -> Point, f64);

    /// The transforms that keep every contact: power-of-two scalings, the
    /// mirror in the y axis, and with it the swap of the axes.
    fn transforms() -> Vec<Transform> {
        vec![
            ("identity", |q| q, 1.0),
            ("mirror", |q| p(-q.x, q.y), 1.0),
            ("swap axes", |q| p(q.y, q.x), 1.0),
            ("times 2^-1000", |q| q, f64::from_bits(74 << 52)),
            ("times 2^996", |q| q, 2f64.powi(996)),
            ("times -2^-1070", |q| q, -f64::from_bits(1 << 4)),
        ]
    }

    /// Whether scaling by `scale` keeps the points exact (no rounding in
    /// the subnormal range).
    fn exact_scaling(points: &[Point], scale: f64) -> bool {
        points.iter().all(|q| (q.x * scale) / scale == q.x && (q.y * scale) / scale == q.y)
    }

    fn arc_points(arc: &CircularArc) -> Vec<Point> {
        let mut v = vec![arc.start(), arc.end()];
        v.extend(arc.via());
        v
    }

    fn transform_arc(arc: &CircularArc, f: fn(Point) -> Point, scale: f64) -> CircularArc {
        let map = |q: Point| f(q).scaled(scale);
        // mirrors reverse the turn: rebuild from the exact points
        let moved = match arc.datum() {
            (_, Some(via)) => CircularArc::through(map(arc.start()), map(via), map(arc.end())),
            (Some(b), None) => {
                let flips = {
                    let (o, x, y) = (f(p(0.0, 0.0)), f(p(1.0, 0.0)), f(p(0.0, 1.0)));
                    (x.x - o.x) * (y.y - o.y) - (x.y - o.y) * (y.x - o.x) < 0.0
                };
                CircularArc::from_bulge(map(arc.start()), map(arc.end()), if flips { -b } else { b })
            }
            _ => unreachable!(),
        };
        // constructors refuse circles whose rounded centre overflows: the
        // crate's own scaling keeps the exact data anyway
        moved.unwrap_or_else(|_| {
            let base = match arc.datum() {
                (_, Some(via)) => CircularArc::through(f(arc.start()), f(via), f(arc.end())).unwrap(),
                (Some(b), None) => {
                    let (o, x, y) = (f(p(0.0, 0.0)), f(p(1.0, 0.0)), f(p(0.0, 1.0)));
                    let flips = (x.x - o.x) * (y.y - o.y) - (x.y - o.y) * (y.x - o.x) < 0.0;
                    CircularArc::from_bulge(f(arc.start()), f(arc.end()), if flips { -b } else { b }).unwrap()
                }
                _ => unreachable!(),
            };
            base.scaled(scale)
        })
    }

    fn point_case(arc: &CircularArc, q: Point) -> bool {
        ExactArc::new(arc).contains_point(q)
    }

    /// `segment_arc_contact` under every transform and with the arc and the
    /// segment reversed: always `expected`.
    fn check_segment(arc: &CircularArc, seg: [Point; 2], expected: Option<SegmentArcContact>) {
        for (name, f, scale) in transforms() {
            if !exact_scaling(&[arc_points(arc), seg.to_vec()].concat(), scale) {
                continue;
            }
            let arc = transform_arc(arc, f, scale);
            let seg = [f(seg[0]).scaled(scale), f(seg[1]).scaled(scale)];
            for arc in [arc, arc.reversed()] {
                let exact = ExactArc::new(&arc);
                for seg in [seg, [seg[1], seg[0]]] {
                    assert_eq!(segment_arc_contact(&exact, seg), expected, "{name}: {arc:?} and {seg:?}");
                }
                let bx = arc_box(&arc);
                if expected.is_some() {
                    let meets = |q: Point| q.x >= bx[0] && q.x <= bx[1] && q.y >= bx[2] && q.y <= bx[3];
                    let sb = [seg[0].x.min(seg[1].x), seg[0].x.max(seg[1].x), seg[0].y.min(seg[1].y), seg[0].y.max(seg[1].y)];
                    let overlap = sb[0] <= bx[1] && bx[0] <= sb[1] && sb[2] <= bx[3] && bx[2] <= sb[3];
                    assert!(overlap || meets(seg[0]), "{name}: box {bx:?} misses {seg:?}");
                }
            }
        }
    }

    fn swapped(c: Option<ArcArcContact>) -> Option<ArcArcContact> {
        c.map(|c| match c {
            ArcArcContact::EndOfFirstOnSecond => ArcArcContact::EndOfSecondOnFirst,
            ArcArcContact::EndOfSecondOnFirst => ArcArcContact::EndOfFirstOnSecond,
            other => other,
        })
    }

    /// `arc_arc_contact` under every transform, with either arc reversed,
    /// in both orders: always `expected` (the end cases swapped with the
    /// order).
    fn check_arcs(first: &CircularArc, second: &CircularArc, expected: Option<ArcArcContact>) {
        for (name, f, scale) in transforms() {
            if !exact_scaling(&[arc_points(first), arc_points(second)].concat(), scale) {
                continue;
            }
            let (a, b) = (transform_arc(first, f, scale), transform_arc(second, f, scale));
            for a in [a, a.reversed()] {
                for b in [b, b.reversed()] {
                    let (x, y) = (ExactArc::new(&a), ExactArc::new(&b));
                    assert_eq!(arc_arc_contact(&x, &y), expected, "{name}: {a:?} and {b:?}");
                    assert_eq!(arc_arc_contact(&y, &x), swapped(expected), "{name}: {b:?} and {a:?}");
                    if expected.is_some() {
                        let (p, q) = (arc_box(&a), arc_box(&b));
                        assert!(p[0] <= q[1] && q[0] <= p[1] && p[2] <= q[3] && q[2] <= p[3], "{name}: boxes {p:?} {q:?}");
                    }
                }
            }
        }
    }

    // The circle of radius 5 about the origin, through the Pythagorean
    // points (±3, ±4) and (±4, ±3): its right half, given two ways.
    fn right_half() -> [CircularArc; 2] {
        [through([0.0, -5.0], [4.0, 3.0], [0.0, 5.0]), bulged([0.0, -5.0], [0.0, 5.0], 1.0)]
    }

    #[test]
    fn a_bulge_and_a_via_arc_of_one_circle_are_the_same_arc() {
        let [v, b] = right_half();
        let (x, y) = (ExactArc::new(&v), ExactArc::new(&b));
        assert!(x.same_circle(&y));
        assert_eq!(x.tau, y.tau);
        assert_eq!(x.tau, -1, "counter-clockwise: the arc lies right of its chord");
        assert_eq!(arc_arc_contact(&x, &y), Some(ArcArcContact::Overlap), "identical arcs overlap");
        assert!(x.approx.unwrap().k == 0.0 && y.approx.unwrap().k == 0.0);
    }

    #[test]
    fn points_exactly_on_the_open_arc_and_one_ulp_off() {
        for arc in right_half() {
            for (x, y) in [(3.0, 4.0), (4.0, 3.0), (5.0, 0.0), (3.0, -4.0), (4.0, -3.0)] {
                for (name, f, scale) in transforms() {
                    if !exact_scaling(&[arc_points(&arc), vec![p(x, y)]].concat(), scale) {
                        continue;
                    }
                    let moved = transform_arc(&arc, f, scale);
                    let q = f(p(x, y)).scaled(scale);
                    assert!(point_case(&moved, q), "{name}: ({x}, {y}) on {moved:?}");
                    assert!(point_case(&moved.reversed(), q));
                    // one ulp off, each way and on each axis: not on the circle
                    for off in [p(up(q.x), q.y), p(down(q.x), q.y), p(q.x, up(q.y)), p(q.x, down(q.y))] {
                        assert!(!point_case(&moved, off), "{name}: {off:?} one ulp off");
                    }
                }
            }
            // the endpoints, the other half, the centre: no
            for q in [p(0.0, 5.0), p(0.0, -5.0), p(-3.0, 4.0), p(-5.0, 0.0), p(0.0, 0.0), p(1e308, -1e308)] {
                assert!(!point_case(&arc, q), "{q:?}");
            }
        }
    }

    #[test]
    fn segments_against_the_right_half() {
        use SegmentArcContact::*;
        let cases: Vec<([f64; 4], Option<SegmentArcContact>, &str)> = vec![
            ([5.0, -2.0, 5.0, 2.0], Some(Tangent), "the tangent x = 5 through (5, 0) inside the arc"),
            ([up(5.0), -2.0, up(5.0), 2.0], None, "one ulp outside the tangent"),
            ([down(5.0), -2.0, down(5.0), 2.0], Some(Cross), "one ulp inside the tangent: two crossings"),
            ([5.0, 0.0, 5.0, 3.0], Some(EndOnArc), "ending at the tangent point"),
            ([0.0, 0.0, 10.0, 0.0], Some(Cross), "through (5, 0)"),
            ([0.0, 0.0, 5.0, 0.0], Some(EndOnArc), "from the centre to the arc"),
            ([0.0, 0.0, up(5.0), 0.0], Some(Cross), "one ulp past the arc"),
            ([0.0, 0.0, down(5.0), 0.0], None, "one ulp short of the arc"),
            ([3.0, 4.0, 10.0, 4.0], Some(EndOnArc), "an end at (3, 4)"),
            ([-3.0, 4.0, 3.0, 4.0], Some(EndOnArc), "the chord y = 4 ends on the arc"),
            ([-3.0, 4.0, 4.0, 4.0], Some(Cross), "y = 4 crossing at (3, 4)"),
            ([0.0, 5.0, -7.0, 5.0], None, "leaving the endpoint (0, 5) along the tangent"),
            ([0.0, 5.0, 7.0, 5.0], None, "leaving the endpoint (0, 5) along the tangent, back over the arc"),
            ([-1.0, 5.0, 1.0, 5.0], None, "the arc's endpoint inside the segment, tangent (the build splits)"),
            ([0.0, -6.0, 0.0, 6.0], None, "through both endpoints of the arc"),
            ([0.0, 5.0, 0.0, -5.0], None, "the chord"),
            ([0.0, 5.0, 8.0, 0.0], Some(Cross), "from an endpoint, through the disc, out across the arc"),
            ([0.0, 5.0, 4.0, 2.5], None, "from an endpoint into the disc"),
            ([0.0, 5.0, 4.0, -3.0], Some(EndOnArc), "a chord from the endpoint to (4, -3)"),
            ([-5.0, 0.0, -10.0, 3.0], None, "on the other half's side"),
            ([-5.0, 0.0, 5.0, 0.0], Some(EndOnArc), "the diameter: (5, 0) is its end"),
            ([6.0, 6.0, 6.0, 6.0], None, "a zero-length segment off the arc"),
            ([4.0, 3.0, 4.0, 3.0], Some(EndOnArc), "a zero-length segment on the arc"),
        ];
        for arc in right_half() {
            for &([ax, ay, bx, by], expected, why) in &cases {
                let seg = [p(ax, ay), p(bx, by)];
                let got = segment_arc_contact(&ExactArc::new(&arc), seg);
                assert_eq!(got, expected, "{why}");
                check_segment(&arc, seg, expected);
            }
        }
    }

    #[test]
    fn arcs_against_arcs() {
        use ArcArcContact::*;
        let [right, right_bulged] = right_half();
        let left = bulged([0.0, 5.0], [0.0, -5.0], 1.0);
        let left_via = through([0.0, 5.0], [-4.0, -3.0], [0.0, -5.0]);
        let quarter = through([5.0, 0.0], [4.0, 3.0], [0.0, 5.0]);
        let upper_left = through([3.0, 4.0], [0.0, 5.0], [-5.0, 0.0]);
        // the circle of radius 5 about (10, 0), and about (6, 0)
        let beside = through([10.0, 5.0], [5.0, 0.0], [10.0, -5.0]);
        let beside_out = through([10.0 + 2f64.powi(-49), 5.0], [5.0 + 2f64.powi(-49), 0.0], [10.0 + 2f64.powi(-49), -5.0]);
        let beside_in = through([10.0 - 2f64.powi(-49), 5.0], [5.0 - 2f64.powi(-49), 0.0], [10.0 - 2f64.powi(-49), -5.0]);
        let crossing = through([6.0, 5.0], [1.0, 0.0], [6.0, -5.0]);
        let from_crossing = through([3.0, 4.0], [6.0, 5.0], [11.0, 0.0]);
        // radius 2.5 about (2.5, 0): inside, tangent at (5, 0)
        let inner = through([2.5, 2.5], [5.0, 0.0], [2.5, -2.5]);
        let inner_from_tangent = through([5.0, 0.0], [4.0, 2.0], [2.5, 2.5]);
        let lower_quarter = through([0.0, -5.0], [3.0, -4.0], [5.0, 0.0]);
        let s_curve = through([5.0, 0.0], [6.0, 3.0], [10.0, 5.0]);
        let lens = through([0.0, -5.0], [-1.0, 0.0], [0.0, 5.0]);
        let crescent = through([0.0, 5.0], [8.0, 0.0], [0.0, -5.0]);
        let wide = through([0.0, 5.0], [8.0, 0.0], [3.0, -4.0]);
        let right_reversed = right.reversed();
        let cases: Vec<(&CircularArc, &CircularArc, Option<ArcArcContact>, &str)> = vec![
            (&right, &left, None, "a full circle as two arcs"),
            (&right_bulged, &left_via, None, "a full circle as two arcs, given otherwise"),
            (&right, &right_bulged, Some(Overlap), "identical"),
            (&right, &right_reversed, Some(Overlap), "identical, reversed"),
            (&right, &quarter, Some(Overlap), "a quarter inside the half"),
            (&quarter, &left, None, "sharing the end (0, 5) and running on"),
            (&quarter, &upper_left, Some(Overlap), "sharing the stretch from (3, 4) to (0, 5)"),
            (&lower_quarter, &quarter, None, "one circle, one common endpoint"),
            (&right, &beside, Some(Tangent), "tangent outside at (5, 0)"),
            (&right, &beside_out, None, "one ulp apart"),
            (&right, &beside_in, Some(Cross), "one ulp overlapping"),
            (&right, &crossing, Some(Cross), "crossing at (3, ±4)"),
            (&left, &crossing, None, "the crossings are on the other half"),
            (&right, &from_crossing, Some(EndOfSecondOnFirst), "starting on the arc"),
            (&right, &inner, Some(Tangent), "tangent inside at (5, 0)"),
            (&right, &inner_from_tangent, Some(EndOfSecondOnFirst), "starting inside the arc, tangent"),
            (&lower_quarter, &inner_from_tangent, None, "a tangent-continuous join inside"),
            (&lower_quarter, &s_curve, None, "a tangent-continuous S"),
            (&quarter, &s_curve, None, "meeting at an endpoint of both, not tangent"),
            (&right, &lens, None, "a lens: two circles through both endpoints"),
            (&right, &crescent, None, "a crescent: both bulging right from one chord"),
            (&left, &lens, None, "a lens the other way"),
            (&right, &wide, Some(EndOfSecondOnFirst), "through both circle points, one inside the arc"),
        ];
        for (a, b, expected, why) in cases {
            assert_eq!(arc_arc_contact(&ExactArc::new(a), &ExactArc::new(b)), expected, "{why}");
            check_arcs(a, b, expected);
        }
    }

    #[test]
    fn roots_are_signed_exactly() {
        let d = |x: f64| Dyadic::from_f64(x);
        assert_eq!(sign_with_root(&d(-3.0), &d(1.0), &d(9.0)), 0);
        assert_eq!(sign_with_root(&d(-3.0), &d(1.0), &d(up(9.0))), 1);
        assert_eq!(sign_with_root(&d(-3.0), &d(1.0), &d(down(9.0))), -1);
        assert_eq!(sign_with_root(&d(3.0), &d(-1.0), &d(9.0)), 0);
        assert_eq!(sign_with_root(&d(0.0), &d(-1.0), &d(2.0)), -1);
        assert_eq!(sign_with_root(&d(-1.0), &d(5.0), &d(0.0)), -1);
        assert_eq!(ratio_to_f64(&d(1.0), &d(3.0)), 1.0 / 3.0);
        assert_eq!(ratio_to_f64(&d(-1e300), &d(1e-300)), f64::NEG_INFINITY);
        assert_eq!(ratio_to_f64(&d(f64::MIN_POSITIVE), &d(4.0)), f64::MIN_POSITIVE / 4.0);
    }

    /// What dense sampling can tell about a closed piece `samples` (in
    /// order along it) against an arc: a clear crossing of the open arc at
    /// a clearly interior stretch of the piece, clearly apart, or unclear.
    #[derive(Debug, PartialEq)]
    enum Sampled {
        Crosses,
        Apart,
        Unclear,
    }

    fn sample_against(arc: &CircularArc, samples: &[Point], spacing: f64) -> Sampled {
        let (c, r) = (arc.centre(), arc.radius());
        let (s, e) = (arc.start(), arc.end());
        let tau = if arc.is_counter_clockwise() { -1.0 } else { 1.0 };
        let tol = 1e-7 * r.max(spacing);
        let side = |q: Point| tau * ((e.x - s.x) * (q.y - s.y) - (e.y - s.y) * (q.x - s.x)) / s.distance(e);
        let power = |q: Point| q.distance(c) - r;
        let inner = &samples[2..samples.len() - 2];
        for w in inner.windows(2) {
            let (h0, h1) = (power(w[0]), power(w[1]));
            if h0.abs() > tol && h1.abs() > tol && (h0 < 0.0) != (h1 < 0.0) && side(w[0]) > tol && side(w[1]) > tol {
                return Sampled::Crosses;
            }
        }
        let nearest = samples.iter().map(|&q| arc.distance(q)).fold(f64::INFINITY, f64::min);
        if nearest > spacing + tol {
            Sampled::Apart
        } else {
            Sampled::Unclear
        }
    }

    /// Random small arcs and segments, on a coarse grid (many exact
    /// contacts) or anywhere: wherever dense sampling is clear, the exact
    /// answer agrees (a clear crossing is a conflict, clearly apart is
    /// none). Sampling decides nothing near tangencies or endpoints.
    #[test]
    fn sampling_confirms_the_clear_cases() {
        let mut rng = crate::splitmix::SplitMix64(99);
        let (mut crosses, mut apart) = (0, 0);
        for round in 0..3000 {
            let coarse = round % 2 == 0;
            let mut value = || {
                let v = rng.unit() * 8.0 - 4.0;
                if coarse {
                    (v * 2.0).round() / 2.0
                } else {
                    v
                }
            };
            let mut pt = || p(value(), value());
            let (a, b, m) = (pt(), pt(), pt());
            let Ok(arc) = (if round % 3 == 0 {
                CircularArc::from_bulge(a, b, (m.x / 2.0).clamp(-3.0, 3.0) + 0.01)
            } else {
                CircularArc::through(a, m, b)
            }) else {
                continue;
            };
            let (c, d, n) = (pt(), pt(), pt());
            let exact = ExactArc::new(&arc);
            const M: usize = 4000;
            if round % 2 == 0 {
                let spacing = c.distance(d) / M as f64;
                let samples: Vec<Point> = (0..=M)
                    .map(|i| {
                        let t = i as f64 / M as f64;
                        p(c.x + t * (d.x - c.x), c.y + t * (d.y - c.y))
                    })
                    .collect();
                let got = segment_arc_contact(&exact, [c, d]);
                match sample_against(&arc, &samples, spacing) {
                    Sampled::Crosses => {
                        crosses += 1;
                        assert!(got.is_some(), "{arc:?} {c:?} {d:?}")
                    }
                    Sampled::Apart => {
                        apart += 1;
                        assert_eq!(got, None, "{arc:?} {c:?} {d:?}")
                    }
                    Sampled::Unclear => {}
                }
            } else {
                let Ok(other) = CircularArc::through(c, n, d) else { continue };
                let spacing = other.radius() * other.sweep().abs() / M as f64;
                let samples: Vec<Point> = (0..=M).map(|i| other.point_at(i as f64 / M as f64)).collect();
                let got = arc_arc_contact(&exact, &ExactArc::new(&other));
                match sample_against(&arc, &samples, spacing) {
                    Sampled::Crosses => {
                        crosses += 1;
                        assert!(got.is_some(), "{arc:?} {other:?}")
                    }
                    Sampled::Apart => {
                        apart += 1;
                        assert_eq!(got, None, "{arc:?} {other:?}")
                    }
                    Sampled::Unclear => {}
                }
            }
        }
        assert!(crosses > 300 && apart > 300, "{crosses} crossings and {apart} apart confirmed");
    }

    /// The filters and the rational shortcuts change no answer: on inputs
    /// made of points of a few circles with Pythagorean points (shared
    /// endpoints, points on circles, tangencies and common circles
    /// everywhere), at two scales, the fast and the plain exact paths agree.
    #[test]
    fn the_filters_and_shortcuts_change_no_answer() {
        let mut pool = vec![];
        for (cx, cy) in [(0.0, 0.0), (10.0, 0.0), (6.0, 0.0), (0.0, 8.0), (3.0, 4.0)] {
            for (x, y) in [(3.0, 4.0), (4.0, 3.0), (5.0, 0.0), (0.0, 5.0)] {
                for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
                    pool.push(p(cx + sx * x, cy + sy * y));
                }
            }
            pool.push(p(cx, cy));
        }
        pool.extend([p(2.5, 2.5), p(4.0, 2.0), p(2.5, -2.5), p(up(5.0), 0.0), p(down(5.0), 0.0)]);
        let mut rng = crate::splitmix::SplitMix64(8);
        let (mut arcs_seen, mut contacts) = (0, 0);
        for round in 0..9000 {
            // 1, 2^-943, 2^1000, 2^-1070 (subnormal: points may merge), and
            // 2^-530 and 2^-510, where products of coordinates are subnormal
            let scale = [
                1.0,
                f64::from_bits(80 << 52),
                f64::from_bits(2023 << 52),
                f64::from_bits(1 << 4),
                f64::from_bits(493 << 52),
                f64::from_bits(513 << 52),
            ][(round / 2) % 6];
            let mut pick = || pool[(rng.next_u64() % pool.len() as u64) as usize];
            let (a, m, b, mut c, n, mut d) = (pick(), pick(), pick(), pick(), pick(), pick());
            // common endpoints in half the rounds
            match round % 4 {
                1 => c = a,
                3 => d = b,
                _ => {}
            }
            if !exact_scaling(&[a, m, b, c, n, d], scale) {
                continue; // subnormal: the scaled points would not be the same figure
            }
            let Ok(arc) = CircularArc::through(a, m, b) else { continue };
            let arc = if round % 3 == 0 { CircularArc::from_bulge(a, b, arc.bulge()).unwrap_or(arc) } else { arc };
            // scaled after construction: the constructors refuse circles
            // whose rounded centre leaves f64's range, the crate's scaling not
            let arc = arc.scaled(scale);
            let (c0, d0) = (c, d);
            let (c, d) = (c.scaled(scale), d.scaled(scale));
            arcs_seen += 1;
            let x = ExactArc::new(&arc);
            let seg = [c, d];
            let fast = segment_arc_contact_by::<true>(&x, seg);
            assert_eq!(fast, segment_arc_contact_by::<false>(&x, seg), "{arc:?} {seg:?}");
            assert_eq!(x.contains_point_by::<true>(c), x.contains_point_by::<false>(c));
            if let Ok(other) = CircularArc::through(c0, n, d0) {
                let other = other.scaled(scale);
                let y = ExactArc::new(&other);
                let fast = arc_arc_contact_by::<true>(&x, &y);
                assert_eq!(fast, arc_arc_contact_by::<false>(&x, &y), "{arc:?} {other:?}");
                contacts += usize::from(fast.is_some());
            }
            contacts += usize::from(fast.is_some());
        }
        assert!(arcs_seen > 2000 && contacts > 1000, "{arcs_seen} arcs, {contacts} contacts");
    }
}
