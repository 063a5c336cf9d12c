//! Exact signs where pieces meet: the direction in which a segment or an
//! arc leaves one of its endpoints, as exact polynomials of the input
//! (endpoints and bulge or third point), and the turns between such
//! directions. At a join of a chain these decide what the floating-point
//! tangents cannot: a vertex an ulp off straight is a corner, not a
//! tangent join, and where the pieces meet at that corner is then fixed
//! by the sign, not by rounding noise. Only an exactly tangent join (the
//! cross product exactly zero) is left to the curvature rules.
//!
//! The directions are exact up to a positive factor; every sign here is
//! exact unless a product leaves `f64`'s range (`None` then, and the
//! caller keeps its floating-point answer).

use crate::geometry::arc::CircularArc;
use crate::geometry::arithmetic::bigfloat::BigFloat;
use crate::geometry::arithmetic::expansion::Expansion;
use crate::geometry::arithmetic::radical_tower::{exact_evaluation, Algebraic};
use crate::geometry::arithmetic::real::Real;
use crate::geometry::point::Point;
use crate::geometry::predicates::exact_orientation;
use crate::geometry::site::Site;

fn coord(p: Point) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

/// A direction held exactly, up to a positive factor.
#[derive(Clone)]
pub(crate) struct Direction {
    x: Expansion,
    y: Expansion,
}

impl Direction {
    fn new(x: Expansion, y: Expansion) -> Option<Direction> {
        (x.is_finite() && y.is_finite() && (x.sign() != 0 || y.sign() != 0)).then_some(Direction { x, y })
    }

    /// The direction rounded to floating point (its scale arbitrary).
    pub(crate) fn approximate(&self) -> Point {
        Point::new(self.x.approximate(), self.y.approximate())
    }

    /// `to − from`.
    fn between(from: Point, to: Point) -> Option<Direction> {
        Direction::new(Expansion::difference(to.x, from.x), Expansion::difference(to.y, from.y))
    }
}

/// The sign of `u × v` (positive: `v` turns counter-clockwise from `u`);
/// `None` out of range.
pub(crate) fn cross_sign(u: &Direction, v: &Direction) -> Option<i8> {
    let value = u.x.times(&v.y).minus(&u.y.times(&v.x));
    value.is_finite().then(|| value.sign())
}

/// The sign of `u · v`; `None` out of range.
pub(crate) fn dot_sign(u: &Direction, v: &Direction) -> Option<i8> {
    let value = u.x.times(&v.x).plus(&u.y.times(&v.y));
    value.is_finite().then(|| value.sign())
}

/// The direction in which the segment or arc `site` leaves its endpoint
/// `end` (an arc: its tangent there, pointing into the arc). `None` when
/// `end` is not an endpoint of `site`, or out of range.
pub(crate) fn leaving(site: &Site, end: Point) -> Option<Direction> {
    match *site {
        Site::Segment { a, b } if a == end => Direction::between(a, b),
        Site::Segment { a, b } if b == end => Direction::between(b, a),
        Site::Arc(arc) if arc.start() == end || arc.end() == end => arc_leaving(&arc, end),
        _ => None,
    }
}

/// The tangent of `arc` pointing into it from its endpoint `end`.
///
/// With a bulge `β` and chord `D = end − start`, the tangent turns from
/// the chord by half the sweep, whose cosine and sine are
/// `(1 − β², 2β)/(1 + β²)`: it leaves the start along
/// `(1 − β²) D − 2β D⊥` and arrives at the end along `(1 − β²) D + 2β D⊥`
/// (`D⊥` is `D` turned a quarter counter-clockwise). Through a third point
/// `V`, inverting about the start `A` maps the circle to the line through
/// the images of `V` and the end `E`, which is parallel to the tangent at
/// `A`: it leaves along `|AE|² (V − A) − |AV|² (E − A)`.
fn arc_leaving(arc: &CircularArc, end: Point) -> Option<Direction> {
    let (s, e) = (arc.start(), arc.end());
    let at_start = end == s;
    match arc.datum() {
        (Some(beta), _) => {
            // β² must not underflow for the polynomial to be exact
            if beta != 0.0 && beta.abs() < 1e-150 {
                return None;
            }
            let (dx, dy) = (Expansion::difference(e.x, s.x), Expansion::difference(e.y, s.y));
            let mut cosine = Expansion::of(1.0);
            cosine.add_product(-beta, beta);
            let sine = Expansion::of(2.0 * beta);
            // D⊥ = (−dy, dx); at the start −2β D⊥ = (2β dy, −2β dx)
            let (along_x, along_y) = (cosine.times(&dx), cosine.times(&dy));
            let (turn_x, turn_y) = (sine.times(&dy), sine.times(&dx).negated());
            if at_start {
                Direction::new(along_x.plus(&turn_x), along_y.plus(&turn_y))
            } else {
                // arriving along (1 − β²) D + 2β D⊥; leaving the end backward
                Direction::new(turn_x.minus(&along_x), turn_y.minus(&along_y))
            }
        }
        (None, Some(via)) => {
            let (a, far) = if at_start { (s, e) } else { (e, s) };
            let squared = |p: Point| {
                let mut out = Expansion::default();
                out.add_squared_difference(p.x, a.x);
                out.add_squared_difference(p.y, a.y);
                out
            };
            let (to_far, to_via) = (squared(far), squared(via));
            let component = |v: f64, f: f64, a: f64| {
                let mut out = Expansion::default();
                out.add_product_with_difference(&to_far, (v, a));
                let mut minus = Expansion::default();
                minus.add_product_with_difference(&to_via, (f, a));
                out.minus(&minus)
            };
            Direction::new(component(via.x, far.x, a.x), component(via.y, far.y, a.y))
        }
        _ => None,
    }
}

/// Whether `arc`, leaving its endpoint `end`, curves to the left of its
/// direction there (its centre on that side): a counter-clockwise arc
/// from its start, a clockwise one from its end.
pub(crate) fn curves_left(arc: &CircularArc, end: Point) -> bool {
    arc.is_counter_clockwise() == (end == arc.start())
}

/// The signed curvature of a piece leaving `end` (positive curving left):
/// zero for a segment. Floating point: it only breaks exact ties of
/// direction.
pub(crate) fn curvature_leaving(site: &Site, end: Point) -> f64 {
    match *site {
        Site::Arc(arc) => {
            let k = 1.0 / arc.radius();
            if curves_left(&arc, end) {
                k
            } else {
                -k
            }
        }
        _ => 0.0,
    }
}

/// The sign of the turn from the tangent of the piece `u` to that of `v`,
/// both leaving their common endpoint `end`: 0 where they are exactly
/// parallel (a tangent join, a cusp). `None` out of range.
pub(crate) fn tangent_turn(u: &Site, v: &Site, end: Point) -> Option<i8> {
    cross_sign(&leaving(u, end)?, &leaving(v, end)?)
}

/// Whether the pieces `u` and `v`, both leaving their common endpoint
/// `end`, leave it on the same side of its normal (exactly; a cusp when
/// their tangents are also parallel). `None` out of range.
pub(crate) fn leave_the_same_way(u: &Site, v: &Site, end: Point) -> Option<bool> {
    Some(dot_sign(&leaving(u, end)?, &leaving(v, end)?)? > 0)
}

/// The sign of the turn from the piece `u` to the piece `v`, both leaving
/// their common endpoint `end`, as their directions a hair away from it
/// see it: by the exact tangents, and where those are exactly parallel by
/// the curvatures (the one curving more to the left lies counter-clockwise
/// of the other when both leave the same way, clockwise when they leave
/// opposite ways). `None` out of range.
pub(crate) fn turn_between(u: &Site, v: &Site, end: Point) -> Option<i8> {
    turn_between_leaving(u, &leaving(u, end)?, v, &leaving(v, end)?, end)
}

/// [`turn_between`] with the pieces' exact leaving directions `tu` and
/// `tv` known already.
fn turn_between_leaving(u: &Site, tu: &Direction, v: &Site, tv: &Direction, end: Point) -> Option<i8> {
    let sign = cross_sign(tu, tv)?;
    if sign != 0 {
        return Some(sign);
    }
    let same_way = dot_sign(tu, tv)?;
    let bend = curvature_leaving(v, end) - curvature_leaving(u, end);
    let bend = if bend > 0.0 {
        1
    } else if bend < 0.0 {
        -1
    } else {
        0
    };
    Some(same_way * bend)
}

/// The order of the pieces `u` and `v` leaving their common endpoint `end`
/// counter-clockwise from the direction of the positive x axis, as their
/// directions a hair away from it see it: by the half-plane of their exact
/// tangents, then by [`turn_between`] (the turn, and where the tangents
/// coincide the curvatures: the one curving more to the left comes
/// later). A piece that
/// leaves along the x axis curving right belongs at the end of the turn
/// rather than at its start; ordered first, it only rotates the cyclic
/// order by one, which the callers (pairing pieces around a point) accept.
/// `None` out of range.
pub(crate) fn compare_leaving(u: &Site, v: &Site, end: Point) -> Option<std::cmp::Ordering> {
    use std::cmp::Ordering;
    let (tu, tv) = (leaving(u, end)?, leaving(v, end)?);
    let lower = |d: &Direction| {
        let y = d.y.sign();
        y < 0 || (y == 0 && d.x.sign() < 0)
    };
    match (lower(&tu), lower(&tv)) {
        (false, true) => return Some(Ordering::Less),
        (true, false) => return Some(Ordering::Greater),
        _ => {}
    }
    // (in one half-plane, parallel tangents leave the same way)
    Some(match turn_between_leaving(u, &tu, v, &tv, end)? {
        1 => Ordering::Less,
        -1 => Ordering::Greater,
        _ => Ordering::Equal,
    })
}

/// Whether a vertex of both endpoints of `arc` and of `third` lies beyond
/// the arc's centre on the side of the arc's middle (1), before it (-1) or
/// at it (0), for the `third` sites where that is exact: a segment or arc
/// sharing one of the arc's endpoints (the vertex is where its normal at
/// that endpoint meets the bisector of the arc's endpoints, the arc's
/// centre where the arc's own normal does), and a point (the circle
/// through the two endpoints and it, against the arc's circle); a segment
/// or an arc apart from the arc's ends, touching the arc's circle near a
/// point clear of its own ends (`beyond_centre_touching`). `None` for any
/// other site or out of range.
pub(crate) fn beyond_centre(arc: &CircularArc, third: &Site) -> Option<i8> {
    let (s, e) = (arc.start(), arc.end());
    // positive for a counter-clockwise arc (its middle right of s → e)
    let ccw: i8 = if arc.is_counter_clockwise() { 1 } else { -1 };
    match *third {
        Site::Point(q) => beyond_centre_point(arc, q, ccw),
        _ => {
            let shared = if third.has_endpoint(s) {
                s
            } else if third.has_endpoint(e) {
                e
            } else {
                return beyond_centre_touching(arc, third, ccw);
            };
            let other = if shared == s { e } else { s };
            let d = Direction::between(shared, other)?;
            // Along the bisector, the point where a line through `shared`
            // in direction w (turned toward `other`) meets it moves toward
            // the arc's middle as w turns the way d × u says (u toward the
            // middle: for the start, d × u = −ccw).
            let toward_middle = if shared == s { -ccw } else { ccw };
            let (t_arc, t_third) = (leaving(&Site::Arc(*arc), shared)?, leaving(third, shared)?);
            // the normals (t turned a quarter) toward `other`
            let (n_arc, n_third) = (cross_sign(&t_arc, &d)?, cross_sign(&t_third, &d)?);
            if n_arc == 0 || n_third == 0 {
                return None;
            }
            let turn = cross_sign(&t_arc, &t_third)?;
            if turn == 0 && dot_sign(&t_arc, &t_third)? > 0 {
                // A cusp: the third piece leaves the shared end along the
                // arc and curves the other way. The normal from the cusp
                // to the centre ties the cusp, both pieces and the arc's
                // other end, but beside it the arc is nearer than the
                // third piece (which bends away): the vertex is the
                // arc's, in conflict with it, as beyond the centre.
                let arc_curve = curvature_leaving(&Site::Arc(*arc), shared);
                let third_curve = curvature_leaving(third, shared);
                return Some(if (arc_curve - third_curve) * arc_curve.signum() > 0.0 { 1 } else { 0 });
            }
            Some(n_arc * n_third * turn * toward_middle)
        }
    }
}

/// Whether `arc`, leaving its endpoint `end`, points into the circle
/// through `end` and the points `b` and `c` (1), out of it (-1) or along
/// it (0), exactly: the sign of its tangent there against the direction
/// to the circle's centre. With `B = b − end`, `C = c − end`, the centre
/// is `end + (C.y|B|² − B.y|C|², B.x|C|² − C.x|B|²) / 2(B × C)`. `None`
/// where the three points are collinear, or out of range.
pub(crate) fn leaves_into_circle(arc: &CircularArc, end: Point, b: Point, c: Point) -> Option<i8> {
    let tangent = leaving(&Site::Arc(*arc), end)?;
    let denominator = exact_orientation(end, b, c).sign();
    if denominator == 0 {
        return None;
    }
    let lift = |q: Point| {
        let mut out = Expansion::default();
        out.add_squared_difference(q.x, end.x);
        out.add_squared_difference(q.y, end.y);
        out
    };
    let (lift_b, lift_c) = (lift(b), lift(c));
    let along = |lift_1: &Expansion, q1: f64, lift_2: &Expansion, q2: f64, e: f64| {
        // lift_1 (q2 − e) − lift_2 (q1 − e)
        let mut out = Expansion::default();
        out.add_product_with_difference(lift_1, (q2, e));
        let mut minus = Expansion::default();
        minus.add_product_with_difference(lift_2, (q1, e));
        out.minus(&minus)
    };
    let ux = along(&lift_b, b.y, &lift_c, c.y, end.y);
    let uy = along(&lift_c, c.x, &lift_b, b.x, end.x);
    let toward = Direction::new(ux, uy)?;
    Some(dot_sign(&tangent, &toward)? * denominator)
}

/// Whether `arc`, leaving its endpoint `end`, points into the circle
/// through `end` that touches the segment or arc `piece` at its endpoint
/// `q` (1), out of it (-1) or along it (0), exactly. With `w = q − end`
/// and `n` the normal of `piece` at `q`, that circle's centre is
/// `q + λ n` with `λ = −|w|² / 2 n·w`, so the direction from `end` to it
/// is `(2 (n·w) w − |w|² n) / 2 n·w`. `None` where `end` is on the
/// tangent at `q`, or out of range.
pub(crate) fn leaves_into_tangent_circle(arc: &CircularArc, end: Point, q: Point, piece: &Site) -> Option<i8> {
    let tangent = leaving(&Site::Arc(*arc), end)?;
    let along = leaving(piece, q)?;
    let normal = Direction { x: along.y.negated(), y: along.x.clone() };
    let w = Direction::between(end, q)?;
    let nw = normal.x.times(&w.x).plus(&normal.y.times(&w.y));
    let denominator = nw.sign();
    if !nw.is_finite() || denominator == 0 {
        return None;
    }
    let ww = w.x.times(&w.x).plus(&w.y.times(&w.y));
    let two_nw = nw.plus(&nw);
    let toward = Direction::new(two_nw.times(&w.x).minus(&ww.times(&normal.x)), two_nw.times(&w.y).minus(&ww.times(&normal.y)))?;
    Some(dot_sign(&tangent, &toward)? * denominator)
}

/// Whether `arc`, leaving its endpoint `end`, points into the circle
/// through `end` and the point `q` that touches the circle of the arc
/// `other` (1), out of it (-1) or along it (0), exactly; of the up to two
/// such circles, the one whose centre is nearer `near` (the vertex as
/// floating point placed it). `None` where the two are not told apart
/// clearly, where either arc's datum leaves the range, or where the exact
/// evaluation gives up.
///
/// The centre is `end + w/2 + s·w⊥` (`w = q − end`, on the bisector of
/// `end` and `q`). With `c` the other arc's centre less `end` and `r²` its
/// squared radius, touching (`|centre − c| = R ± r`, `R² = |w|²(1/4 + s²)`)
/// is `(a + b·s)² = r²|w|²(1 + 4s²)` with `a = |c|² − r² − w·c` and
/// `b = −2 w⊥·c`: a quadratic in `s` with rational coefficients, whose
/// root is one square root. The arc's tangent `t` points into the circle
/// when `t·(w/2 + s·w⊥) > 0`. Its sign is decided in the radical tower
/// (`arithmetic::radical_tower`), and the root is chosen in 512-bit
/// floats: near a tie the circle can be 1e16 across, its centre a
/// rounding of the bisector's direction off the floating-point one.
pub(crate) fn leaves_into_circle_touching(
    arc: &CircularArc,
    end: Point,
    q: Point,
    other: &CircularArc,
    near: Point,
) -> Option<i8> {
    if end == q || !near.is_finite() {
        return None;
    }
    // the quadratic's coefficients (a·s² + 2b·s + c) and discriminant
    // (b² − ac) in any arithmetic
    fn quadratic<R: Real>(other: &CircularArc, end: Point, q: Point, lift: &impl Fn(f64) -> R) -> Option<[R; 4]> {
        let (cx, cy, _) = other.circle_in(lift)?;
        let (sx, sy) = (lift(other.start().x), lift(other.start().y));
        let squared_radius = cx.sub(&sx).mul(&cx.sub(&sx)).add(&cy.sub(&sy).mul(&cy.sub(&sy)));
        let (cx, cy) = (cx.sub(&lift(end.x)), cy.sub(&lift(end.y)));
        let (wx, wy) = (lift(q.x).sub(&lift(end.x)), lift(q.y).sub(&lift(end.y)));
        let ww = wx.mul(&wx).add(&wy.mul(&wy));
        let a = cx.mul(&cx).add(&cy.mul(&cy)).sub(&squared_radius).sub(&wx.mul(&cx).add(&wy.mul(&cy)));
        // w⊥ = (−wy, wx)
        let b = wy.mul(&cx).sub(&wx.mul(&cy)).mul(&lift(2.0));
        let g = squared_radius.mul(&ww);
        let four_g = g.mul(&lift(4.0));
        let discriminant = g.mul(&b.mul(&b).add(&a.mul(&a).mul(&lift(4.0))).sub(&four_g));
        Some([b.mul(&b).sub(&four_g), a.mul(&b), a.mul(&a).sub(&g), discriminant])
    }
    // the two roots, and which sign of the square root each takes
    let big = |x: f64| BigFloat::from_f64(x, 512);
    let [qa, qb, _, discriminant] = quadratic(other, end, q, &big)?;
    if qa.signum() == 0 || discriminant.signum() < 0 {
        return None;
    }
    let root = discriminant.sqrt();
    let roots = [-1.0, 1.0].map(|sign: f64| qb.neg().add(&root.mul(&big(sign))).div(&qa).to_f64());
    let (wx, wy) = (q.x - end.x, q.y - end.y);
    let s_near = ((near.x - end.x) * -wy + (near.y - end.y) * wx) / (wx * wx + wy * wy);
    let [d0, d1] = roots.map(|s| (s - s_near).abs());
    let sign_of_root = match () {
        _ if !(d0.is_finite() && d1.is_finite()) => return None,
        _ if 4.0 * d0 < d1 => -1.0,
        _ if 4.0 * d1 < d0 => 1.0,
        _ => return None,
    };
    exact_evaluation(|| {
        let lift = |x: f64| Algebraic::from_f64(x);
        let [qa, qb, _, discriminant] = quadratic(other, end, q, &lift)?;
        let s = qb.neg().add(&discriminant.sqrt().mul(&lift(sign_of_root))).div(&qa);
        // the tangent: the radius at `end` turned a quarter, toward the
        // side the arc curves away from
        let (cx, cy, _) = arc.circle_in(&lift)?;
        let (rx, ry) = (lift(end.x).sub(&cx), lift(end.y).sub(&cy));
        let (tx, ty) = if curves_left(arc, end) { (ry.neg(), rx) } else { (ry, rx.neg()) };
        let (wx, wy) = (lift(q.x).sub(&lift(end.x)), lift(q.y).sub(&lift(end.y)));
        // t·(w/2 + s·w⊥), doubled
        let along = tx.mul(&wx).add(&ty.mul(&wy));
        let across = tx.mul(&wy.neg()).add(&ty.mul(&wx));
        Some(along.add(&across.mul(&s).mul(&lift(2.0))).signum() as i8)
    })
    .flatten()
}

/// [`beyond_centre`] for a segment or an arc `third` apart from the arc's
/// ends that comes within a rounding of the arc's circle: as for a point
/// (`beyond_centre_point`), at the point `q` where it comes nearest the
/// arc's centre. The vertex's circle passes through the arc's ends and
/// touches `third` near `q`; it reaches beyond the arc's circle on the side
/// of the arc's middle exactly when `third` stays outside the arc's circle
/// there (`stays_outside_circle`). (Two arcs touching at a point of both,
/// their circles a rounding apart: the floating-point vertex sits at the
/// centre, and the rounding decided which arc's cell kept it.)
///
/// `None` where the nearest point is near the arc's ends, or where
/// `stays_outside_circle` has no answer.
fn beyond_centre_touching(arc: &CircularArc, third: &Site, ccw: i8) -> Option<i8> {
    let (q, outside) = stays_outside_circle(arc, third)?;
    let (s, e) = (arc.start(), arc.end());
    if s.distance(q).min(e.distance(q)) < CLEAR * arc.radius() {
        return None;
    }
    let side = exact_orientation(s, e, q).sign();
    if side == 0 {
        return None;
    }
    let middle_side = side == -ccw;
    Some(match outside {
        0 => 0,
        o if (o > 0) == middle_side => 1,
        _ => -1,
    })
}

/// Whether the segment or arc `other`, which comes within a rounding of
/// the circle of `arc`, stays outside that circle (1), touches it (0) or
/// enters it (-1) where it comes nearest the circle's centre, exactly,
/// with that nearest point (in floating point). A comparison of exact
/// numbers of the input: the distance from the centre to the segment's
/// line, or to the other arc's circle (`|d − ρ|` for centres `d` apart and
/// the other radius `ρ`), against the radius, all from the arcs' ends and
/// bulges (`exact_circle`).
///
/// `None` where the nearest point is near an end of `other` (the end is a
/// point site of its own, nearer there), where `other` does not come near
/// the circle, for an arc given by three points, or out of range.
fn stays_outside_circle(arc: &CircularArc, other: &Site) -> Option<(Point, i8)> {
    let (c, r) = (arc.centre(), arc.radius());
    // where `other` comes nearest the centre, in floating point, and the
    // cases that are not answered here, before any exact arithmetic
    let q = match *other {
        Site::Segment { a, b } => {
            let t = crate::geometry::site::segment_parameter(a, b, c);
            if !(CLEAR..=1.0 - CLEAR).contains(&t) {
                return None;
            }
            Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
        }
        Site::Arc(o) => {
            let (oc, rho) = (o.centre(), o.radius());
            let d = oc.distance(c);
            // the centre clearly off the other circle (else the arcs are
            // of nearly one circle, or the arc's radius is nearly zero)
            if !(d > CLEAR * r) || (d - rho).abs() < CLEAR * r {
                return None;
            }
            let q = Point::new(oc.x + rho * (c.x - oc.x) / d, oc.y + rho * (c.y - oc.y) / d);
            if !o.spans(q) || o.start().distance(q).min(o.end().distance(q)) < CLEAR * rho {
                return None;
            }
            q
        }
        Site::Point(_) => return None,
    };
    if !((q.distance(c) - r).abs() <= CLEAR * r) {
        return None;
    }
    let (x, y, k, rk2) = exact_circle(arc)?;
    let outside = match *other {
        Site::Segment { a, b } => {
            // the distance to the line times |b − a| times k: (b − a) × (kC − ka)
            let (ux, uy) = (Expansion::difference(b.x, a.x), Expansion::difference(b.y, a.y));
            let xa = x.minus(&k.times(&Expansion::of(a.x)));
            let ya = y.minus(&k.times(&Expansion::of(a.y)));
            let cross = ux.times(&ya).minus(&uy.times(&xa));
            let length2 = ux.times(&ux).plus(&uy.times(&uy));
            let excess = cross.times(&cross).minus(&rk2.times(&length2));
            if !excess.is_finite() {
                return None;
            }
            excess.sign()
        }
        Site::Arc(o) => {
            let (ox, oy, ok, ork2) = exact_circle(&o)?;
            // with both scaled by k·k': d² → n, ρ² → u, r² → v
            let px = ox.times(&k).minus(&x.times(&ok));
            let py = oy.times(&k).minus(&y.times(&ok));
            let n = px.times(&px).plus(&py.times(&py));
            let (u, v) = (ork2.times(&k.times(&k)), rk2.times(&ok.times(&ok)));
            // |d − ρ| against r: d against ρ + r with the centre outside
            // the other circle, against ρ − r inside it; with
            // l = d² − ρ² − r², that is l against 2ρr, or against −2ρr
            let l = n.minus(&u).minus(&v);
            let beyond = l.times(&l).minus(&Expansion::of(4.0).times(&u).times(&v));
            if !beyond.is_finite() {
                return None;
            }
            match (o.centre().distance(c) > o.radius(), l.sign(), beyond.sign()) {
                (_, _, 0) => 0,
                (true, -1 | 0, _) | (false, 1 | 0, _) => -1,
                (_, _, b) => b,
            }
        }
        Site::Point(_) => return None,
    };
    Some((q, outside))
}

/// How clear of an end (a share of the length or radius) the nearest point
/// of a third site must be for `beyond_centre_touching`.
const CLEAR: f64 = 1e-6;

/// The arc's circle exactly, from its ends and bulge: the centre
/// `(x / k, y / k)` and the radius squared `rk2 / k²`, with `k = 4β`
/// (`4β (C − s) = 2β D + (1 − β²) D⊥`, `|2β D + (1 − β²) D⊥| = |D| (1 + β²)`).
/// `None` for an arc given by three points or a bulge near zero.
fn exact_circle(arc: &CircularArc) -> Option<(Expansion, Expansion, Expansion, Expansion)> {
    let beta = arc.datum().0?;
    if beta.abs() < 1e-150 || beta.abs() > 1e150 {
        return None;
    }
    let s = arc.start();
    let (wx, wy) = from_start_to_centre(s, arc.end(), beta);
    let k = Expansion::of(4.0 * beta);
    let x = k.times(&Expansion::of(s.x)).plus(&wx);
    let y = k.times(&Expansion::of(s.y)).plus(&wy);
    let rk2 = wx.times(&wx).plus(&wy.times(&wy));
    (x.is_finite() && y.is_finite() && rk2.is_finite()).then_some((x, y, k, rk2))
}

/// `4β (C − s) = 2β D + (1 − β²) D⊥` exactly, for the arc from `s` to `e`
/// of bulge `β` with centre `C` (`D = e − s`, `D⊥` turned a quarter
/// counter-clockwise).
fn from_start_to_centre(s: Point, e: Point, beta: f64) -> (Expansion, Expansion) {
    let (dx, dy) = (Expansion::difference(e.x, s.x), Expansion::difference(e.y, s.y));
    let mut cosine = Expansion::of(1.0);
    cosine.add_product(-beta, beta);
    let two_beta = Expansion::of(2.0 * beta);
    (two_beta.times(&dx).minus(&cosine.times(&dy)), two_beta.times(&dy).plus(&cosine.times(&dx)))
}

/// [`beyond_centre`] for a point `q`: the circle through the arc's ends and
/// `q` has its centre beyond the arc's when `q` lies outside the arc's
/// circle on the side of the arc's middle, or inside it on the other side.
fn beyond_centre_point(arc: &CircularArc, q: Point, ccw: i8) -> Option<i8> {
    let (s, e) = (arc.start(), arc.end());
    // the side of the chord s → e: the middle is right of it when ccw
    let side = exact_orientation(s, e, q).sign();
    let middle_side = side == -ccw;
    if side == 0 {
        return None;
    }
    let outside = match arc.datum() {
        (Some(beta), _) => {
            if beta.abs() < 1e-150 {
                return None;
            }
            // 4β (C − s) = 2β D + (1 − β²) D⊥; the power of q is
            // |q − s|² − 2 (q − s)·(C − s), of the sign of
            // β (2β |q − s|² − (q − s)·4β (C − s))
            let two_beta = Expansion::of(2.0 * beta);
            let (wx, wy) = from_start_to_centre(s, e, beta);
            let mut lift = Expansion::default();
            lift.add_squared_difference(q.x, s.x);
            lift.add_squared_difference(q.y, s.y);
            let mut power = two_beta.times(&lift);
            let mut along = Expansion::default();
            along.add_product_with_difference(&wx, (q.x, s.x));
            along.add_product_with_difference(&wy, (q.y, s.y));
            power.subtract(&along);
            if !power.is_finite() {
                return None;
            }
            let sign = power.sign() * if beta > 0.0 { 1 } else { -1 };
            if sign == 0 {
                return Some(0);
            }
            sign > 0
        }
        (None, Some(via)) => {
            // the circle through s, via, e, its points counter-clockwise
            let (a, c) = if exact_orientation(s, via, e).sign() > 0 { (s, e) } else { (e, s) };
            let det = robust::incircle(coord(a), coord(via), coord(c), coord(q));
            if det == 0.0 {
                return Some(0);
            }
            det < 0.0
        }
        _ => return None,
    };
    Some(if outside == middle_side { 1 } else { -1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// Uniform numbers in [0, 1) from `seed` (a linear congruential step).
    fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// The direction rounded to a unit vector.
    fn approx(d: &Direction) -> Point {
        let (x, y) = (d.x.approximate(), d.y.approximate());
        let n = x.hypot(y);
        p(x / n, y / n)
    }

    #[test]
    fn tangents_of_arcs_by_bulge_and_by_third_point_agree_with_the_centre() {
        let mut unit = uniform(0x1234_5678_9abc_def0);
        for _ in 0..500 {
            let (s, e) = (p(unit() * 10.0 - 5.0, unit() * 10.0 - 5.0), p(unit() * 10.0 - 5.0, unit() * 10.0 - 5.0));
            let bulge = (unit() * 4.0 - 2.0).clamp(-1.9, 1.9);
            if bulge.abs() < 0.01 {
                continue;
            }
            let by_bulge = CircularArc::from_bulge(s, e, bulge).unwrap();
            let via = by_bulge.midpoint();
            let by_via = CircularArc::through(s, via, e).unwrap();
            for arc in [by_bulge, by_via] {
                for end in [s, e] {
                    let t = approx(&leaving(&Site::Arc(arc), end).unwrap());
                    let want = arc.tangent_into(end);
                    assert!((t.x - want.x).abs() < 1e-6 && (t.y - want.y).abs() < 1e-6, "{arc:?} at {end:?}: {t:?} {want:?}");
                }
            }
        }
    }

    #[test]
    fn a_join_one_ulp_off_straight_is_a_corner() {
        // a segment into a half circle's start, its far end an ulp above or
        // below the tangent line
        let arc = CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap();
        let tiny = f64::MIN_POSITIVE * 1e10;
        for (y, want) in [(0.0, 0), (tiny, 1), (-tiny, -1), (1e-16, 1), (-1e-16, -1)] {
            let segment = Site::Segment { a: p(3.0, y), b: p(4.0, 0.0) };
            // arriving along the segment, leaving along the arc: the turn
            // is the turn from the segment's way back to the arc, reversed
            let turn = turn_between(&segment, &Site::Arc(arc), p(4.0, 0.0)).unwrap();
            assert_eq!(turn, if want == 0 { -1 } else { -want }, "y = {y}");
            assert_eq!(beyond_centre(&arc, &segment), Some(want), "y = {y}");
        }
    }

    #[test]
    fn beyond_the_centre_agrees_with_the_vertex_in_every_orientation() {
        let mut unit = uniform(0x9e37_79b9_7f4a_7c15);
        for case in 0..2000 {
            let (s, e) = (p(unit() * 2.0 - 1.0, unit() * 2.0 - 1.0), p(unit() * 2.0 - 1.0, unit() * 2.0 - 1.0));
            let bulge = (0.1 + 1.5 * unit()) * if case % 2 == 0 { 1.0 } else { -1.0 };
            let arc = CircularArc::from_bulge(s, e, bulge).unwrap();
            let shared = if case % 4 < 2 { s } else { e };
            let other = if shared == s { e } else { s };
            // a segment leaving `shared` along the arc's tangent turned by a
            // small angle either way (away from the arc: a join)
            let t = arc.tangent_into(shared);
            let angle = (unit() - 0.5) * 1e-3;
            let (c, si) = (angle.cos(), angle.sin());
            let back = p(-(t.x * c - t.y * si), -(t.x * si + t.y * c));
            let segment = Site::Segment { a: shared, b: p(shared.x + back.x, shared.y + back.y) };
            // the vertex: on the bisector of the ends and the segment's
            // normal at `shared`
            let n = p(-back.y, back.x);
            let m = p(0.5 * (s.x + e.x), 0.5 * (s.y + e.y));
            let d = p(other.x - shared.x, other.y - shared.y);
            // shared + k n on the bisector: (shared + k n − m)·d = 0
            let k = ((m.x - shared.x) * d.x + (m.y - shared.y) * d.y) / (n.x * d.x + n.y * d.y);
            let v = p(shared.x + k * n.x, shared.y + k * n.y);
            let (centre, middle) = (arc.centre(), arc.midpoint());
            let along = (v.x - centre.x) * (middle.x - centre.x) + (v.y - centre.y) * (middle.y - centre.y);
            if along.abs() < 1e-9 {
                continue;
            }
            let want = if along > 0.0 { 1 } else { -1 };
            assert_eq!(beyond_centre(&arc, &segment), Some(want), "case {case}: {arc:?} at {shared:?}, turned {angle}");
        }
    }

    #[test]
    fn a_cusp_puts_the_vertex_in_the_arcs_conflict() {
        // half circles in a row meeting at (4, 3), both leaving it upward
        let right = CircularArc::from_bulge(p(8.0, 3.0), p(4.0, 3.0), 1.0).unwrap();
        let left = CircularArc::from_bulge(p(4.0, 3.0), p(0.0, 3.0), 1.0).unwrap();
        assert_eq!(beyond_centre(&right, &Site::Arc(left)), Some(1));
        assert_eq!(turn_between(&Site::Arc(left), &Site::Arc(right), p(4.0, 3.0)), Some(-1));
        // the same half circle continued by a segment along its tangent:
        // the vertex is the centre
        let segment = Site::Segment { a: p(4.0, 3.0), b: p(4.0, 0.0) };
        assert_eq!(beyond_centre(&right, &segment), Some(0));
        // a segment leaving the cusp upward too (LibreCAD's c14): it bends
        // away from the arc as much as the other half circle does
        let up = Site::Segment { a: p(4.0, 3.0), b: p(4.0, 6.0) };
        assert_eq!(leave_the_same_way(&up, &Site::Arc(right), p(4.0, 3.0)), Some(true));
        assert_eq!(beyond_centre(&right, &up), Some(1));
    }

    #[test]
    fn leaving_into_the_circle_of_points_agrees_with_floating_point_where_it_is_clear() {
        let mut unit = uniform(0x5851_f42d_4c95_7f2d);
        let mut clear = 0;
        for _ in 0..2000 {
            let (s, e) = (p(unit() * 4.0, unit() * 4.0), p(unit() * 4.0, unit() * 4.0));
            let arc = CircularArc::from_bulge(s, e, unit() * 4.0 - 2.0).unwrap();
            let (b, c) = (p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0), p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0));
            for end in [s, e] {
                let Some((centre, _)) = crate::geometry::solvers::circumcircle(end, b, c) else { continue };
                let t = arc.tangent_into(end);
                let (nx, ny) = (centre.x - end.x, centre.y - end.y);
                let along = (t.x * nx + t.y * ny) / nx.hypot(ny);
                if along.abs() > 1e-6 && centre.is_finite() {
                    clear += 1;
                    assert_eq!(
                        leaves_into_circle(&arc, end, b, c),
                        Some(if along > 0.0 { 1 } else { -1 }),
                        "{arc:?} {end:?} {b:?} {c:?}"
                    );
                }
            }
        }
        assert!(clear > 3500, "{clear}");
    }

    #[test]
    fn a_circle_1e16_across_is_entered_at_3e_16() {
        // LibreCAD's t2.dxf: a half circle's top end 1.8e-15 below the
        // line of two points beside it (their circle's centre 1.2e16 up);
        // the arc leaves its top end level, so it points into that circle
        let end = p(4.0, -1.7763568394002505e-15);
        let arc = CircularArc::from_bulge(p(4.0, -4.000000000000002), end, 1.0).unwrap();
        assert_eq!(leaves_into_circle(&arc, end, p(0.0, 0.0), p(15.0, 0.0)), Some(1));
        // (it leaves toward the circle's centre, at x = 7.5; the half
        // circle the other way round leaves away from it)
        let other_way = CircularArc::from_bulge(end, p(4.0, -4.000000000000002), 1.0).unwrap();
        assert_eq!(leaves_into_circle(&other_way, end, p(0.0, 0.0), p(15.0, 0.0)), Some(-1));
        // the end an ulp above the line instead: the circle's centre is
        // 1.2e16 below, still at x = 7.5
        let up = p(4.0, 1.7763568394002505e-15);
        let arc = CircularArc::from_bulge(p(4.0, -4.0), up, 1.0).unwrap();
        assert_eq!(leaves_into_circle(&arc, up, p(0.0, 0.0), p(15.0, 0.0)), Some(1));
        // exactly level: along the circle's tangent (a line: collinear)
        let level = CircularArc::from_bulge(p(4.0, -4.0), p(4.0, 0.0), 1.0).unwrap();
        assert_eq!(leaves_into_circle(&level, p(4.0, 0.0), p(0.0, 0.0), p(15.0, 0.0)), None);
        // the circle through the end touching a segment at its end (t2's
        // line into the neighbouring coil's top)
        let segment = Site::Segment { a: p(11.0, -1.7763568394002505e-15), b: p(15.0, 0.0) };
        let other = CircularArc::from_bulge(p(4.0, -4.000000000000002), end, 1.0).unwrap();
        assert_eq!(leaves_into_tangent_circle(&other, end, p(11.0, -1.7763568394002505e-15), &segment), Some(1));
    }

    #[test]
    fn leaving_into_a_tangent_circle_agrees_with_floating_point_where_it_is_clear() {
        let mut unit = uniform(0x2545_f491_4f6c_dd1d);
        let mut clear = 0;
        for _ in 0..2000 {
            let (s, e) = (p(unit() * 4.0, unit() * 4.0), p(unit() * 4.0, unit() * 4.0));
            let arc = CircularArc::from_bulge(s, e, unit() * 4.0 - 2.0).unwrap();
            let (q, far) = (p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0), p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0));
            let piece = Site::Segment { a: q, b: far };
            for end in [s, e] {
                // the centre q + λ n, n the segment's normal at q
                let (dx, dy) = (far.x - q.x, far.y - q.y);
                let (nx, ny) = (-dy, dx);
                let (wx, wy) = (q.x - end.x, q.y - end.y);
                let lambda = -(wx * wx + wy * wy) / (2.0 * (nx * wx + ny * wy));
                let centre = p(q.x + lambda * nx, q.y + lambda * ny);
                assert!(
                    (centre.distance(end) - centre.distance(q)).abs() <= 1e-6 * (1.0 + centre.distance(q)) || !centre.is_finite()
                );
                let t = arc.tangent_into(end);
                let (vx, vy) = (centre.x - end.x, centre.y - end.y);
                let along = (t.x * vx + t.y * vy) / vx.hypot(vy);
                if along.abs() > 1e-6 && centre.is_finite() {
                    clear += 1;
                    assert_eq!(leaves_into_tangent_circle(&arc, end, q, &piece), Some(if along > 0.0 { 1 } else { -1 }));
                }
            }
        }
        assert!(clear > 3500, "{clear}");
    }

    /// The circles through `end` and `q` touching another arc's circle,
    /// found by bisection along the bisector (no quadratic): where the
    /// tangent clearly enters or leaves one, and the other is far, the
    /// exact sign agrees.
    #[test]
    fn leaving_into_a_circle_touching_an_arc_agrees_with_bisection_where_it_is_clear() {
        let mut unit = uniform(0x6a09_e667_f3bc_c908);
        let mut clear = 0;
        for _ in 0..500 {
            let (s, e) = (p(unit() * 4.0, unit() * 4.0), p(unit() * 4.0, unit() * 4.0));
            let arc = CircularArc::from_bulge(s, e, unit() * 4.0 - 2.0).unwrap();
            let (os, oe) = (p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0), p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0));
            let other = CircularArc::from_bulge(os, oe, unit() * 4.0 - 2.0).unwrap();
            let q = p(unit() * 8.0 - 2.0, unit() * 8.0 - 2.0);
            let (c, r) = (other.centre(), other.radius());
            for end in [s, e] {
                let (wx, wy) = (q.x - end.x, q.y - end.y);
                let at = |t: f64| p(end.x + 0.5 * wx - t * wy, end.y + 0.5 * wy + t * wx);
                let mut roots = Vec::new();
                for sigma in [1.0, -1.0] {
                    let f = |t: f64| at(t).distance(c) - (at(t).distance(end) + sigma * r).abs();
                    let grid: Vec<f64> =
                        (-300i32..=300).map(|k| f64::from(k).signum() * 10f64.powf(f64::from(k.abs()) / 50.0 - 3.0)).collect();
                    for pair in grid.windows(2) {
                        let (mut lo, mut hi) = (pair[0], pair[1]);
                        if f(lo) * f(hi) >= 0.0 {
                            continue;
                        }
                        for _ in 0..100 {
                            let mid = 0.5 * (lo + hi);
                            if f(lo) * f(mid) <= 0.0 {
                                hi = mid
                            } else {
                                lo = mid
                            }
                        }
                        roots.push(0.5 * (lo + hi));
                    }
                }
                for &t in &roots {
                    let apart = roots.iter().filter(|&&u| u != t).all(|&u| (u - t).abs() > 0.5 * (1.0 + t.abs()));
                    let centre = at(t);
                    let tangent = arc.tangent_into(end);
                    let (vx, vy) = (centre.x - end.x, centre.y - end.y);
                    let along = (tangent.x * vx + tangent.y * vy) / vx.hypot(vy);
                    if apart && along.abs() > 1e-6 && (centre.distance(c) - r).abs() > 1e-6 {
                        clear += 1;
                        let expected = if along > 0.0 { 1 } else { -1 };
                        assert_eq!(
                            leaves_into_circle_touching(&arc, end, q, &other, centre),
                            Some(expected),
                            "{arc:?} {end:?} {q:?} {other:?} {t}"
                        );
                    }
                }
            }
        }
        assert!(clear > 500, "{clear}");
    }

    /// LibreCAD's t2.dxf minimised: two half circles whose tops lie
    /// 1.8e-15 below the line of a point at height 0. The circle through
    /// the second's top and that point touching the first is 2e15 across;
    /// the second arc leaves its top 3e-16 rad into it, which floating
    /// point took for along it.
    #[test]
    fn a_circle_touching_an_arc_2e15_across_is_entered_exactly() {
        let top = -1.7763568394002505e-15;
        let first = CircularArc::from_bulge(p(4.0, -4.000000000000002), p(4.0, top), 1.0).unwrap();
        let second = CircularArc::from_bulge(p(11.0, top), p(11.0, -4.000000000000002), 1.0).unwrap();
        let (end, q) = (p(11.0, top), p(15.0, 0.0));
        let near = p(12.057190958417937, 2123017224175257.8);
        let t = second.tangent_into(end);
        let (vx, vy) = (near.x - end.x, near.y - end.y);
        assert!(((t.x * vx + t.y * vy) / vx.hypot(vy)).abs() < 1e-12, "a tie to floating point");
        let sign = leaves_into_circle_touching(&second, end, q, &first, near);
        assert!(sign.is_some_and(|s| s != 0), "{sign:?}");
        // mirrored (across the x axis, each arc reversed to keep its side),
        // the answer is the same
        let m = |a: Point| p(a.x, -a.y);
        let first_m = CircularArc::from_bulge(m(first.end()), m(first.start()), 1.0).unwrap();
        let second_m = CircularArc::from_bulge(m(second.end()), m(second.start()), 1.0).unwrap();
        assert_eq!(leaves_into_circle_touching(&second_m, m(end), m(q), &first_m, m(near)), sign);
    }

    #[test]
    fn a_point_against_the_arcs_circle() {
        let arc = CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap();
        let via = CircularArc::through(p(4.0, 0.0), p(5.0, 1.0), p(4.0, 2.0)).unwrap();
        for arc in [arc, via] {
            // on the circle: the vertex is the centre
            assert_eq!(beyond_centre(&arc, &Site::Point(p(3.0, 1.0))), Some(0));
            assert_eq!(beyond_centre(&arc, &Site::Point(p(5.0, 1.0))), Some(0));
            // outside on the middle's side, inside on the other
            assert_eq!(beyond_centre(&arc, &Site::Point(p(5.5, 1.0))), Some(1));
            assert_eq!(beyond_centre(&arc, &Site::Point(p(3.5, 1.0))), Some(1));
            // inside on the middle's side, outside on the other
            assert_eq!(beyond_centre(&arc, &Site::Point(p(4.5, 1.0))), Some(-1));
            assert_eq!(beyond_centre(&arc, &Site::Point(p(2.5, 1.0))), Some(-1));
        }
    }

    #[test]
    fn a_segment_or_an_arc_touching_the_arcs_circle() {
        // the half circle round (4, 1) through (5, 1), radius 1
        let arc = CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap();
        let segment = |x: f64| Site::Segment { a: p(x, -3.0), b: p(x, 5.0) };
        let (ulp_5, ulp_3) = (5.0f64.next_up() - 5.0, 3.0f64.next_up() - 3.0);
        // a line touching the circle on the middle's side: the vertex of
        // the ends and the line is the centre; an ulp out it lies beyond,
        // an ulp in before
        assert_eq!(beyond_centre(&arc, &segment(5.0)), Some(0));
        assert_eq!(beyond_centre(&arc, &segment(5.0 + ulp_5)), Some(1));
        assert_eq!(beyond_centre(&arc, &segment(5.0 - ulp_5)), Some(-1));
        // on the other side the other way round
        assert_eq!(beyond_centre(&arc, &segment(3.0)), Some(0));
        assert_eq!(beyond_centre(&arc, &segment(3.0 - ulp_3)), Some(-1));
        assert_eq!(beyond_centre(&arc, &segment(3.0 + ulp_3)), Some(1));
        // an arc round (x, 1) through (x − 1, 1), touching from outside at
        // (5, 1) for x = 6 (LibreCAD's lamp: two coils touching)
        let outside = |x: f64| Site::Arc(CircularArc::from_bulge(p(x, 0.0), p(x, 2.0), -1.0).unwrap());
        let ulp_6 = 6.0f64.next_up() - 6.0;
        assert_eq!(beyond_centre(&arc, &outside(6.0)), Some(0));
        assert_eq!(beyond_centre(&arc, &outside(6.0 + ulp_6)), Some(1));
        assert_eq!(beyond_centre(&arc, &outside(6.0 - ulp_6)), Some(-1));
        // an arc of radius 1.5 round (x, 1) through (x − 1.5, 1), the
        // arc's circle inside it touching at (3, 1) for x = 4.5: the arc's
        // centre inside that circle
        let around = |x: f64| Site::Arc(CircularArc::from_bulge(p(x, -0.5), p(x, 2.5), -1.0).unwrap());
        let ulp_4 = 4.5f64.next_up() - 4.5;
        assert_eq!(beyond_centre(&arc, &around(4.5)), Some(0));
        assert_eq!(beyond_centre(&arc, &around(4.5 - ulp_4)), Some(-1));
        assert_eq!(beyond_centre(&arc, &around(4.5 + ulp_4)), Some(1));
        // not near the circle, or nearest at an end: not answered here
        assert_eq!(beyond_centre(&arc, &segment(5.5)), None);
        assert_eq!(beyond_centre(&arc, &Site::Segment { a: p(5.0, 1.0), b: p(5.0, 5.0) }), None);
    }
}
