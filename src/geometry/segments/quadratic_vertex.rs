//! The exact answer, at about the cost of a few `f64` expansions, for the
//! vertex of two point sites `P`, `Q` and a segment's supporting line
//! (the segment ending at neither): the oracle's most common true zero on
//! stacks and hatches of equal parallel segments with aligned ends (the
//! circle through the aligned ends of two neighbouring segments, tangent
//! to a segment beside them, is tangent to the next one too, by symmetry).
//! Refined to 1200 bits and proven zero in the radical tower, each of
//! those cost about 400 µs.
//!
//! The centre lies on the bisector of `P` and `Q`: `2c = M + s·w`, with
//! `M = P + Q`, `d = Q − P` and `w = d⊥`, so that `|2c − 2P|² = |w|²(1 +
//! s²)`. Tangency to the line `a + λu` (`u = b − a`) is `|u|²|c − P|² =
//! cross(u, c − a)²`, that is
//!
//! `A s² − 2 k₀k₁ s + C = 0`, `k₀ = cross(u, M − 2a)`, `k₁ = cross(u, w)`,
//! `A = |u|²|w|² − k₁²`, `C = |u|²|w|² − k₀²`,
//!
//! so `s = (k₀k₁ + ε√Δ) / A` (`s = C / 2k₀k₁` where `A = 0`: the line
//! parallel to `PQ`) with `Δ = k₀²k₁² − AC` and `ε = ±1` the root
//! nearest the rounded centre (the one the solvers and Newton's method
//! find; the answer is refused when the rounded centre does not clearly
//! pick one). Every question the oracle asks is then the sign of a linear
//! function `l₀ + l₁s` of `s` (a linear function of `c`, or the squared
//! distance to a line reduced by the quadratic), which is the sign of `A`
//! times the sign of `X + Y√Δ` with `X = l₀A + l₁k₀k₁`, `Y = εl₁`: from
//! the signs of `X`, `Y` and `X² − Y²Δ`. All of it in Shewchuk's
//! expansions (`expansion`), exact: polynomials of degree at most 24 in
//! the coordinates. Exact as long as no product underflows or overflows:
//! refused (`None`) when the coordinates' lowest set bits lie below
//! `2^-44` (a degree-24 product could underflow) or a value overflows.

use super::reach::Reach;
use crate::geometry::arithmetic::expansion::Expansion;
use crate::geometry::point::Point;
use crate::geometry::predicates::CirclePosition;

/// The lowest binary exponent of a coordinate's set bits for which every
/// product of degree 24 stays above the subnormal range.
const LOWEST_BIT: i64 = -44;

/// The vertex of `p`, `q` and the supporting line of `a → b` (`side`: the
/// sign of `cross(b − a, c − a)` at the centre), its rounded centre
/// `centre`: the exact answer to `question`, or `None` where this
/// arithmetic cannot give it (see the module documentation).
pub(crate) fn answer(
    p: Point,
    q: Point,
    (a, b): (Point, Point),
    side: f64,
    centre: Point,
    question: &Reach,
) -> Option<CirclePosition> {
    let points = [p, q, a, b].into_iter().chain(question.points());
    if !points.flat_map(|p| [p.x, p.y]).all(|x| low_bits_fit(x, LOWEST_BIT)) {
        return None;
    }
    let vertex = Vertex::new(p, q, a, b, centre)?;
    // the root is on the side of the line the system says
    if vertex.sign_at(&vertex.k0, &vertex.k1)? as f64 != side {
        return None;
    }
    let sign = match *question {
        Reach::Entering { from, to } => {
            // −u·(c − from), u = to − from
            let (ux, uy) = (Expansion::difference(to.x, from.x), Expansion::difference(to.y, from.y));
            -vertex.linear_sign(&ux, &uy, &dot(&ux, &uy, from).negated())?
        }
        Reach::Distance { a: ta, b: tb } => {
            let (ux, uy) = (Expansion::difference(tb.x, ta.x), Expansion::difference(tb.y, ta.y));
            // u·(c − a): before a, the distance is to a
            if vertex.linear_sign(&ux, &uy, &dot(&ux, &uy, ta).negated())? <= 0 {
                vertex.endpoint_sign(ta)?
            } else if vertex.linear_sign(&ux, &uy, &dot(&ux, &uy, tb).negated())? >= 0 {
                vertex.endpoint_sign(tb)?
            } else {
                vertex.line_sign(ta, &ux, &uy)?
            }
        }
    };
    Some(match sign {
        -1 => CirclePosition::Inside,
        1 => CirclePosition::Outside,
        _ => CirclePosition::On,
    })
}

/// Whether `x` is zero or finite with its lowest set bit at `2^lowest`
/// or above (not subnormal): then every product of `k` such numbers is a
/// multiple of `2^(k·lowest)`, and exact in expansions while that is at
/// least `2^-1074`.
pub(crate) fn low_bits_fit(x: f64, lowest: i64) -> bool {
    if x == 0.0 {
        return true;
    }
    let raw = x.to_bits();
    let biased = ((raw >> 52) & 0x7ff) as i64;
    if biased == 0 || biased == 0x7ff {
        return false;
    }
    let mantissa = (raw & ((1u64 << 52) - 1)) | (1u64 << 52);
    biased - 1075 + i64::from(mantissa.trailing_zeros()) >= lowest
}

/// `u·p` for `u = (ux, uy)`, exactly.
fn dot(ux: &Expansion, uy: &Expansion, p: Point) -> Expansion {
    ux.times(&Expansion::of(p.x)).plus(&uy.times(&Expansion::of(p.y)))
}

/// The centre `2c = M + s·w` as the root of its quadratic (see the module
/// documentation).
struct Vertex {
    p: Point,
    mx: Expansion,
    my: Expansion,
    wx: Expansion,
    wy: Expansion,
    /// `|w|²`
    ww: Expansion,
    k0: Expansion,
    k1: Expansion,
    /// `k₀k₁`
    k01: Expansion,
    a: Expansion,
    c: Expansion,
    /// The root is `s = (N + ε√Δ) / D`: `N = k₀k₁`, `D = A` for a
    /// quadratic, `N = C`, `D = 2k₀k₁`, `Δ = 0` where `A = 0` (the line
    /// parallel to `PQ`: one root).
    numerator: Expansion,
    denominator: Expansion,
    delta: Expansion,
    /// Which root: `+1`, `−1`, or `0` for a double root or a linear
    /// equation.
    epsilon: i8,
    sign_a: i8,
    sign_denominator: i8,
}

impl Vertex {
    fn new(p: Point, q: Point, la: Point, lb: Point, centre: Point) -> Option<Vertex> {
        let e = Expansion::of;
        let (dx, dy) = (Expansion::difference(q.x, p.x), Expansion::difference(q.y, p.y));
        let (wx, wy) = (dy.negated(), dx);
        let (mx, my) = (e(p.x).plus(&e(q.x)), e(p.y).plus(&e(q.y)));
        let (ux, uy) = (Expansion::difference(lb.x, la.x), Expansion::difference(lb.y, la.y));
        let cross = |x: &Expansion, y: &Expansion| ux.times(y).minus(&uy.times(x));
        // M − 2a
        let (gx, gy) = (mx.minus(&e(2.0 * la.x)), my.minus(&e(2.0 * la.y)));
        let k0 = cross(&gx, &gy);
        let k1 = cross(&wx, &wy);
        let uu = ux.times(&ux).plus(&uy.times(&uy));
        let ww = wx.times(&wx).plus(&wy.times(&wy));
        let uuww = uu.times(&ww);
        let a = uuww.minus(&k1.times(&k1));
        let c = uuww.minus(&k0.times(&k0));
        let k01 = k0.times(&k1);
        let delta = k01.times(&k01).minus(&a.times(&c));
        if !(delta.is_finite() && a.is_finite() && c.is_finite() && k01.is_finite()) || delta.sign() < 0 {
            return None;
        }
        // (numerator, denominator, Δ, ε, sign of A, sign of the denominator)
        let (numerator, denominator, delta, epsilon, sign_a, sign_denominator) = if a.sign() == 0 {
            // linear: −2k₀k₁ s + C = 0
            let denominator = k01.plus(&k01);
            if denominator.sign() == 0 {
                return None;
            }
            let sign_denominator = denominator.sign();
            (c.clone(), denominator, Expansion::default(), 0, 0, sign_denominator)
        } else {
            // the root nearest the rounded centre: s = (2c − M)·w / |w|²
            let (wxf, wyf, wwf) = (wx.approximate(), wy.approximate(), ww.approximate());
            let s = ((2.0 * centre.x - mx.approximate()) * wxf + (2.0 * centre.y - my.approximate()) * wyf) / wwf;
            let (af, mid) = (a.approximate(), k01.approximate() / a.approximate());
            let half = delta.approximate().sqrt() / af.abs();
            let epsilon = if delta.sign() == 0 {
                0
            } else {
                let epsilon: i8 = if s >= mid { 1 } else { -1 };
                // clearly nearer that root than the other: refuse otherwise
                let miss = (s - (mid + f64::from(epsilon) * half)).abs();
                if miss.partial_cmp(&(0.25 * half)) != Some(std::cmp::Ordering::Less) {
                    return None;
                }
                epsilon
            };
            (k01.clone(), a.clone(), delta, epsilon, a.sign(), a.sign())
        };
        Some(Vertex {
            p,
            mx,
            my,
            wx,
            wy,
            ww,
            k0,
            k1,
            k01,
            a,
            c,
            numerator,
            denominator,
            delta,
            epsilon,
            sign_a,
            sign_denominator,
        })
    }

    /// The sign of `l₀ + l₁s` at the root.
    fn sign_at(&self, l0: &Expansion, l1: &Expansion) -> Option<i8> {
        // D (l₀ + l₁ s) = l₀D + l₁N + ε l₁ √Δ
        let x = l0.times(&self.denominator).plus(&l1.times(&self.numerator));
        let y = if self.epsilon < 0 { l1.negated() } else { l1.clone() };
        Some(self.sign_denominator * sign_with_root(&x, &y, &self.delta, self.epsilon != 0)?)
    }

    /// The sign of `α·c + β` at the root, `α = (αx, αy)`.
    fn linear_sign(&self, alpha_x: &Expansion, alpha_y: &Expansion, beta: &Expansion) -> Option<i8> {
        // 2(α·c + β) = α·M + 2β + s α·w
        let l0 = alpha_x.times(&self.mx).plus(&alpha_y.times(&self.my)).plus(&beta.plus(beta));
        let l1 = alpha_x.times(&self.wx).plus(&alpha_y.times(&self.wy));
        self.sign_at(&l0, &l1)
    }

    /// The sign of `|c − e|² − r²`, `r = |c − P|`: linear in `c`,
    /// `2c·(P − e) + |e|² − |P|²`.
    fn endpoint_sign(&self, e: Point) -> Option<i8> {
        let p = self.p;
        let (alpha_x, alpha_y) = (Expansion::difference(p.x, e.x), Expansion::difference(p.y, e.y));
        let (alpha_x, alpha_y) = (alpha_x.plus(&alpha_x), alpha_y.plus(&alpha_y));
        let square = |v: Point| {
            let (x, y) = (Expansion::of(v.x), Expansion::of(v.y));
            x.times(&x).plus(&y.times(&y))
        };
        self.linear_sign(&alpha_x, &alpha_y, &square(e).minus(&square(p)))
    }

    /// The sign of `cross(u, c − a)² − |u|² r²` (the line through `a` along
    /// `u`): times 4, `(g₀ + g₁s)² − |u|²|w|²(1 + s²)`, a quadratic in `s`
    /// reduced by the vertex's own to `f₀ + f₁s` (times `A`).
    fn line_sign(&self, a: Point, ux: &Expansion, uy: &Expansion) -> Option<i8> {
        let e = Expansion::of;
        let cross = |x: &Expansion, y: &Expansion| ux.times(y).minus(&uy.times(x));
        let g0 = cross(&self.mx.minus(&e(2.0 * a.x)), &self.my.minus(&e(2.0 * a.y)));
        let g1 = cross(&self.wx, &self.wy);
        let uuww = ux.times(ux).plus(&uy.times(uy)).times(&self.ww);
        let e2 = g1.times(&g1).minus(&uuww);
        let e1 = g0.times(&g1);
        let e1 = e1.plus(&e1);
        let e0 = g0.times(&g0).minus(&uuww);
        if self.sign_a == 0 {
            // s = N / D: D²(e₂s² + e₁s + e₀) = e₂N² + e₁ND + e₀D²
            let (n, d) = (&self.numerator, &self.denominator);
            let value = e2.times(&n.times(n)).plus(&e1.times(&n.times(d))).plus(&e0.times(&d.times(d)));
            return value.is_finite().then(|| value.sign());
        }
        // A s² = 2k₀k₁ s − C
        let two_k01 = self.k01.plus(&self.k01);
        let f1 = e2.times(&two_k01).plus(&self.a.times(&e1));
        let f0 = self.a.times(&e0).minus(&e2.times(&self.c));
        // sign(A · 4F) = sign(f₀ + f₁s)
        Some(self.sign_at(&f0, &f1)? * self.sign_a)
    }
}

/// The sign of `x + y√Δ` (`Δ ≥ 0`; `with_root` false: `Δ = 0`); `None`
/// on overflow.
fn sign_with_root(x: &Expansion, y: &Expansion, delta: &Expansion, with_root: bool) -> Option<i8> {
    if !(x.is_finite() && y.is_finite()) {
        return None;
    }
    let (sx, sy) = (x.sign(), if with_root { y.sign() } else { 0 });
    if sy == 0 || sx == sy {
        return Some(if sx != 0 { sx } else { sy });
    }
    if sx == 0 {
        return Some(sy);
    }
    // opposite signs: the larger of x² and y²Δ wins
    let difference = x.times(x).minus(&y.times(y).times(delta));
    if !difference.is_finite() {
        return None;
    }
    Some(sx * difference.sign())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// The stack's true zero: the circle through (0, 158) and (0, 157)
    /// tangent to y = 159 (centre (√2, 157.5), radius 1.5) touches y = 156.
    #[test]
    fn a_stack_tangency_is_zero() {
        let line = (p(0.0, 159.0), p(40.0, 159.0));
        let centre = p(2f64.sqrt(), 157.5);
        let ask =
            |y: f64| answer(p(0.0, 158.0), p(0.0, 157.0), line, -1.0, centre, &Reach::Distance { a: p(0.0, y), b: p(40.0, y) });
        assert_eq!(ask(156.0), Some(CirclePosition::On));
        assert_eq!(ask(156.0 + 1.0 / 1024.0), Some(CirclePosition::Inside));
        assert_eq!(ask(156.0 - 1.0 / 1024.0), Some(CirclePosition::Outside));
        // the segment ending left of the centre's foot: its end decides
        let short = |x: f64| {
            answer(p(0.0, 158.0), p(0.0, 157.0), line, -1.0, centre, &Reach::Distance { a: p(-5.0, 156.0), b: p(x, 156.0) })
        };
        assert_eq!(short(1.0), Some(CirclePosition::Outside));
        assert_eq!(short(2.0), Some(CirclePosition::On));
    }

    /// The hatch's: the circle through (549, 0) and (552, 0) tangent to the
    /// line y = x − 546 has its centre at (550.5, 1.5); a segment leaving
    /// (552, 0) along that line's direction runs along the tangent.
    #[test]
    fn a_hatch_tangency_is_zero() {
        let line = (p(546.0, 0.0), p(566.0, 20.0));
        let centre = p(550.5, 1.4999999999999993);
        let ask =
            |to: Point| answer(p(549.0, 0.0), p(552.0, 0.0), line, -1.0, centre, &Reach::Entering { from: p(552.0, 0.0), to });
        assert_eq!(ask(p(572.0, 20.0)), Some(CirclePosition::On));
        assert_eq!(ask(p(571.0, 20.0)), Some(CirclePosition::Inside));
        assert_eq!(ask(p(573.0, 20.0)), Some(CirclePosition::Outside));
    }

    #[test]
    fn tiny_low_bits_are_refused() {
        let fit = |x: f64| low_bits_fit(x, LOWEST_BIT);
        assert!(fit(3.0) && fit(0.0) && fit(2f64.powi(-44)));
        assert!(!fit(2f64.powi(-45)) && !fit(1.0 + f64::EPSILON) && !fit(f64::NAN) && !fit(f64::INFINITY));
    }
}
