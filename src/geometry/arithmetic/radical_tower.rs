//! Exact arithmetic with square roots: the numbers the closed forms of a
//! vertex and of a question about it produce from `f64` coordinates, kept
//! exactly, so that the sign of a question's value is decided, zero
//! included, without a separation bound.
//!
//! Every input coordinate is a dyadic rational (`m · 2^e`), and the
//! closed forms (`segment_solvers`, `oracle`'s questions) use `+ − × ÷`,
//! square roots and signs. Each square root taken is a new symbol `s_k`
//! with `s_k² = d_k`, its radicand `d_k` a number built from the earlier
//! symbols only (a tower of quadratic extensions, as CGAL's square-root
//! extensions, one level per root). A number is a fraction `P / q`: `P` a
//! polynomial in the symbols, at most linear in each (`s_k²` is replaced
//! by `d_k`), with dyadic coefficients, and `q` a positive integer.
//! Division multiplies by conjugates until the divisor is rational, so no
//! symbol is ever in a denominator.
//!
//! The sign of `a + b·s_k` (`a`, `b` below level `k`, `d_k > 0`) follows
//! from the signs of `a`, `b` and of `a² − b²·d_k`, one level down: exact,
//! and it ends at rational numbers. A ball evaluation (`certified`) at a
//! modest precision answers first wherever it excludes zero; the recursion
//! runs only for values it cannot tell from zero.
//!
//! The symbols need not be independent (two roots of one radicand, a
//! radicand that is a perfect square in the field): every rule used holds
//! for the real numbers the symbols stand for, whatever relations they
//! have. Only a division by `a + b·s` whose conjugate `a − b·s` is zero
//! needs care (then the divisor is `2a`).
//!
//! The cost grows with the number of roots (a polynomial has up to `2^k`
//! terms) and the size of the coefficients. An evaluation that exceeds
//! [`WORK_LIMIT`] or [`MAX_ROOTS`] gives up: [`exact_evaluation`] returns
//! `None` and the caller decides otherwise.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use num_bigint::{BigInt, Sign};

use super::bigfloat::dyadic;
use super::certified::Certified;
use super::real::Real;

/// Precision of the ball evaluations that decide signs before the exact
/// recursion, and of `to_f64`.
const FILTER_BITS: u64 = 256;

/// The work one evaluation may do, in products of 64-bit limbs, before it
/// gives up.
const WORK_LIMIT: u64 = 20_000_000;

/// The square roots one evaluation may take (a polynomial in `k` of them
/// has up to `2^k` terms).
const MAX_ROOTS: usize = 12;

thread_local! {
    /// The radicals of the current evaluation, in the order taken.
    static ROOTS: RefCell<Vec<Rc<Radical>>> = const { RefCell::new(Vec::new()) };
    /// Limb products done in the current evaluation.
    static WORK: Cell<u64> = const { Cell::new(0) };
    /// Set when the current evaluation exceeded a limit or divided by
    /// zero: its result means nothing.
    static GAVE_UP: Cell<bool> = const { Cell::new(false) };
}

/// Runs `evaluate` (which computes in [`Algebraic`] numbers) with fresh
/// radicals and limits; `None` when it gave up.
pub(crate) fn exact_evaluation<R>(evaluate: impl FnOnce() -> R) -> Option<R> {
    let saved_roots = ROOTS.with(|r| r.replace(Vec::new()));
    let saved_work = WORK.with(|w| w.replace(0));
    let saved_gave_up = GAVE_UP.with(|g| g.replace(false));
    let result = evaluate();
    ROOTS.with(|r| r.replace(saved_roots));
    WORK.with(|w| w.set(saved_work));
    let gave_up = GAVE_UP.with(|g| g.replace(saved_gave_up));
    (!gave_up).then_some(result)
}

fn give_up() {
    GAVE_UP.with(|g| g.set(true));
}

fn gave_up() -> bool {
    GAVE_UP.with(|g| g.get())
}

/// Counts the limb products of multiplying numbers of `a` and `b` bits;
/// false (and the evaluation given up) past the limit.
fn charge(a: u64, b: u64) -> bool {
    let cost = (a / 64 + 1) * (b / 64 + 1);
    let total = WORK.with(|w| {
        let t = w.get().saturating_add(cost);
        w.set(t);
        t
    });
    if total > WORK_LIMIT {
        give_up();
    }
    !gave_up()
}

/// `m · 2^e` exactly; `m` odd, or zero with `e = 0`.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    fn zero() -> Dyadic {
        Dyadic { m: BigInt::from(0), e: 0 }
    }

    fn new(m: BigInt, e: i64) -> Dyadic {
        match m.trailing_zeros() {
            None => Dyadic::zero(),
            Some(z) => Dyadic { m: m >> z, e: e + z as i64 },
        }
    }

    fn from_f64(x: f64) -> Dyadic {
        match dyadic(x) {
            None => Dyadic::zero(),
            Some((m, e)) => Dyadic { m: if x < 0.0 { -BigInt::from(m) } else { BigInt::from(m) }, e },
        }
    }

    fn sign(&self) -> i32 {
        match self.m.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }

    fn add(&self, o: &Dyadic) -> Dyadic {
        if o.sign() == 0 {
            return self.clone();
        }
        if self.sign() == 0 {
            return o.clone();
        }
        let e = self.e.min(o.e);
        Dyadic::new((&self.m << (self.e - e) as u64) + (&o.m << (o.e - e) as u64), e)
    }

    fn mul(&self, o: &Dyadic) -> Dyadic {
        if !charge(self.m.bits(), o.m.bits()) || self.sign() == 0 || o.sign() == 0 {
            return Dyadic::zero();
        }
        // a product of odd numbers is odd
        Dyadic { m: &self.m * &o.m, e: self.e + o.e }
    }

    fn neg(&self) -> Dyadic {
        Dyadic { m: -&self.m, e: self.e }
    }

    fn approx(&self) -> Certified {
        Certified::from_parts(&self.m, self.e, FILTER_BITS)
    }
}

/// A square root taken: the symbol `s` with `s² = radicand`, `radicand > 0`.
#[derive(Debug)]
struct Radical {
    /// Position in the evaluation's radicals, from 1: a radicand holds only
    /// symbols of smaller levels.
    level: usize,
    radicand: Poly,
    /// `√radicand` as a ball at `FILTER_BITS`.
    approx: Certified,
}

/// A polynomial in the symbols, at most linear in each.
#[derive(Clone, Debug)]
enum Poly {
    Leaf(Dyadic),
    /// `low + high · s` for the symbol `s` of `root`, the highest in the
    /// polynomial; `high` is not the literal zero.
    Ext {
        root: Rc<Radical>,
        low: Rc<Poly>,
        high: Rc<Poly>,
    },
}

impl PartialEq for Poly {
    fn eq(&self, o: &Poly) -> bool {
        match (self, o) {
            (Poly::Leaf(a), Poly::Leaf(b)) => a == b,
            (Poly::Ext { root: r1, low: l1, high: h1 }, Poly::Ext { root: r2, low: l2, high: h2 }) => {
                r1.level == r2.level && l1 == l2 && h1 == h2
            }
            _ => false,
        }
    }
}

impl Poly {
    fn constant(x: Dyadic) -> Poly {
        Poly::Leaf(x)
    }

    fn is_literal_zero(&self) -> bool {
        matches!(self, Poly::Leaf(d) if d.sign() == 0)
    }

    fn level(&self) -> usize {
        match self {
            Poly::Leaf(_) => 0,
            Poly::Ext { root, .. } => root.level,
        }
    }

    fn ext(root: &Rc<Radical>, low: Poly, high: Poly) -> Poly {
        if high.is_literal_zero() {
            low
        } else {
            Poly::Ext { root: root.clone(), low: Rc::new(low), high: Rc::new(high) }
        }
    }

    /// `(low, high)` of `self` as a polynomial of level `level` or above
    /// its own: `(self, 0)` when its own level is lower.
    fn split(&self, level: usize) -> (Poly, Poly) {
        match self {
            Poly::Ext { root, low, high } if root.level == level => ((**low).clone(), (**high).clone()),
            _ => (self.clone(), Poly::constant(Dyadic::zero())),
        }
    }

    fn top_root<'a>(&'a self, o: &'a Poly) -> Option<&'a Rc<Radical>> {
        let pick = if self.level() >= o.level() { self } else { o };
        match pick {
            Poly::Ext { root, .. } => Some(root),
            Poly::Leaf(_) => None,
        }
    }

    fn add(&self, o: &Poly) -> Poly {
        match self.top_root(o) {
            None => match (self, o) {
                (Poly::Leaf(a), Poly::Leaf(b)) => Poly::Leaf(a.add(b)),
                _ => unreachable!("level 0 is a leaf"),
            },
            Some(root) => {
                let ((a, b), (c, d)) = (self.split(root.level), o.split(root.level));
                Poly::ext(root, a.add(&c), b.add(&d))
            }
        }
    }

    fn neg(&self) -> Poly {
        match self {
            Poly::Leaf(a) => Poly::Leaf(a.neg()),
            Poly::Ext { root, low, high } => Poly::ext(root, low.neg(), high.neg()),
        }
    }

    fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.neg())
    }

    fn mul(&self, o: &Poly) -> Poly {
        if gave_up() || self.is_literal_zero() || o.is_literal_zero() {
            return Poly::constant(Dyadic::zero());
        }
        match self.top_root(o) {
            None => match (self, o) {
                (Poly::Leaf(a), Poly::Leaf(b)) => Poly::Leaf(a.mul(b)),
                _ => unreachable!("level 0 is a leaf"),
            },
            Some(root) => {
                let root = root.clone();
                let ((a, b), (c, d)) = (self.split(root.level), o.split(root.level));
                // (a + b s)(c + d s) = (ac + bd s²) + (ad + bc) s
                let low = a.mul(&c).add(&b.mul(&d).mul(&root.radicand));
                let high = a.mul(&d).add(&b.mul(&c));
                Poly::ext(&root, low, high)
            }
        }
    }

    /// The value as a ball at `FILTER_BITS`.
    fn approx(&self) -> Certified {
        match self {
            Poly::Leaf(a) => a.approx(),
            Poly::Ext { root, low, high } => low.approx().add(&high.approx().mul(&root.approx)),
        }
    }

    /// The exact sign.
    fn sign(&self) -> i32 {
        let (root, low, high) = match self {
            Poly::Leaf(a) => return a.sign(),
            Poly::Ext { root, low, high } => (root, low, high),
        };
        if let Some(sign) = self.approx().exact_sign() {
            return sign;
        }
        if gave_up() {
            return 0;
        }
        let (sl, sh) = (low.sign(), high.sign());
        if sh == 0 || sl == sh {
            return sl;
        }
        if sl == 0 {
            return sh;
        }
        // opposite signs: |low| against |high| s, compared squared
        let norm = low.mul(low).sub(&high.mul(high).mul(&root.radicand));
        sl * norm.sign()
    }
}

/// An exact real number of the tower: `num / den`, `den > 0`.
#[derive(Clone, Debug)]
pub(crate) struct Algebraic {
    num: Poly,
    den: BigInt,
}

impl Algebraic {
    /// `x` exactly (finite `x`).
    pub fn from_f64(x: f64) -> Algebraic {
        Algebraic { num: Poly::constant(Dyadic::from_f64(x)), den: BigInt::from(1) }
    }

    fn zero() -> Algebraic {
        Algebraic::from_f64(0.0)
    }

    fn over(num: Poly, den: BigInt) -> Algebraic {
        Algebraic { num, den }
    }

    fn integer(n: &BigInt) -> Poly {
        Poly::constant(Dyadic::new(n.clone(), 0))
    }

    /// `√p` of a polynomial `p > 0`: the existing symbol of an equal
    /// radicand, a rational root of a leaf that is a perfect square, or a
    /// new symbol.
    fn root_of(p: Poly) -> Poly {
        if let Poly::Leaf(d) = &p {
            // m 2^e with e even: √m 2^(e/2) where m is a square
            let (m, e) = if d.e % 2 == 0 { (d.m.clone(), d.e) } else { (&d.m << 1u32, d.e - 1) };
            let r = m.sqrt();
            if &r * &r == m {
                return Poly::constant(Dyadic::new(r, e / 2));
            }
        }
        let existing = ROOTS.with(|roots| roots.borrow().iter().find(|r| r.radicand == p).cloned());
        let root = match existing {
            Some(root) => root,
            None => {
                let count = ROOTS.with(|roots| roots.borrow().len());
                if count >= MAX_ROOTS {
                    give_up();
                    return Poly::constant(Dyadic::zero());
                }
                let approx = p.approx().sqrt();
                let root = Rc::new(Radical { level: count + 1, radicand: p, approx });
                ROOTS.with(|roots| roots.borrow_mut().push(root.clone()));
                root
            }
        };
        Poly::ext(&root, Poly::constant(Dyadic::zero()), Poly::constant(Dyadic::new(BigInt::from(1), 0)))
    }
}

impl Real for Algebraic {
    fn add(&self, o: &Algebraic) -> Algebraic {
        if self.den == o.den {
            return Algebraic::over(self.num.add(&o.num), self.den.clone());
        }
        let num = self.num.mul(&Algebraic::integer(&o.den)).add(&o.num.mul(&Algebraic::integer(&self.den)));
        charge(self.den.bits(), o.den.bits());
        Algebraic::over(num, &self.den * &o.den)
    }

    fn sub(&self, o: &Algebraic) -> Algebraic {
        self.add(&o.neg())
    }

    fn mul(&self, o: &Algebraic) -> Algebraic {
        charge(self.den.bits(), o.den.bits());
        Algebraic::over(self.num.mul(&o.num), &self.den * &o.den)
    }

    fn div(&self, o: &Algebraic) -> Algebraic {
        self.mul(&o.recip())
    }

    fn sqrt(&self) -> Algebraic {
        // √(P / q) = √(P q) / q, of |P| (the other arithmetics take √|x|)
        let p = self.num.mul(&Algebraic::integer(&self.den));
        let p = match p.sign() {
            0 => return Algebraic::zero(),
            s if s < 0 => p.neg(),
            _ => p,
        };
        Algebraic::over(Algebraic::root_of(p), self.den.clone())
    }

    fn neg(&self) -> Algebraic {
        Algebraic::over(self.num.neg(), self.den.clone())
    }

    fn abs(&self) -> Algebraic {
        if self.signum() < 0 {
            self.neg()
        } else {
            self.clone()
        }
    }

    fn signum(&self) -> i32 {
        self.num.sign()
    }

    fn to_f64(&self) -> f64 {
        let den = Certified::from_parts(&self.den, 0, FILTER_BITS);
        self.num.approx().div(&den).to_f64()
    }

    fn recip(&self) -> Algebraic {
        // q / P: P times its conjugates until it is rational
        let mut num = Algebraic::integer(&self.den);
        let mut den = self.num.clone();
        while let Poly::Ext { root, low, high } = &den {
            if gave_up() {
                return Algebraic::zero();
            }
            let conjugate = Poly::ext(root, (**low).clone(), high.neg());
            let norm = low.mul(low).sub(&high.mul(high).mul(&root.radicand));
            if norm.sign() == 0 {
                // low − high s = 0: the divisor low + high s is 2 low
                den = low.add(low);
                continue;
            }
            num = num.mul(&conjugate);
            den = norm;
        }
        let Poly::Leaf(d) = den else { unreachable!() };
        if d.sign() == 0 {
            give_up();
            return Algebraic::zero();
        }
        // num / (m 2^e) = (num 2^-e sign(m)) / |m|
        let scale = Dyadic { m: BigInt::from(d.sign()), e: -d.e };
        Algebraic::over(num.mul(&Poly::constant(scale)), d.m.magnitude().clone().into())
    }
}

#[cfg(test)]
mod tests {
    use super::super::bigfloat::BigFloat;
    use super::*;

    fn a(x: f64) -> Algebraic {
        Algebraic::from_f64(x)
    }

    fn sign(f: impl FnOnce() -> Algebraic) -> i32 {
        exact_evaluation(|| f().signum()).expect("within the limits")
    }

    #[test]
    fn identities_with_square_roots_are_exact_zeros() {
        // √2 · √2 − 2
        assert_eq!(sign(|| a(2.0).sqrt().mul(&a(2.0).sqrt()).sub(&a(2.0))), 0);
        // √2 + √3 − √(5 + 2√6)
        assert_eq!(
            sign(|| {
                let lhs = a(2.0).sqrt().add(&a(3.0).sqrt());
                let rhs = a(5.0).add(&a(2.0).mul(&a(6.0).sqrt())).sqrt();
                lhs.sub(&rhs)
            }),
            0
        );
        // (1 / (1 + √2)) − (√2 − 1)
        assert_eq!(sign(|| a(1.0).div(&a(1.0).add(&a(2.0).sqrt())).sub(&a(2.0).sqrt().sub(&a(1.0)))), 0);
        // √(1/3)·√3 − 1, through a non-dyadic radicand
        assert_eq!(sign(|| a(1.0).div(&a(3.0)).sqrt().mul(&a(3.0).sqrt()).sub(&a(1.0))), 0);
    }

    #[test]
    fn tiny_nonzero_values_get_their_sign() {
        // √(x² + 1) − x for x = 2^60: about 2^-61, positive
        let x = 2f64.powi(60);
        assert_eq!(sign(|| a(x).mul(&a(x)).add(&a(1.0)).sqrt().sub(&a(x))), 1);
        // √(x² + 1) − x − 1/(2x) + 1/(8 x³) > 0 is tiny too, and negative at
        // the next term: √(x²+1) = x + 1/(2x) − 1/(8x³) + 1/(16x⁵) − …
        let y = 2f64.powi(100);
        let value = || {
            let root = a(y).mul(&a(y)).add(&a(1.0)).sqrt();
            let series = a(y).add(&a(1.0).div(&a(2.0 * y))).sub(&a(1.0).div(&a(8.0).mul(&a(y).mul(&a(y)).mul(&a(y)))));
            root.sub(&series)
        };
        assert_eq!(sign(value), 1);
    }

    #[test]
    fn a_divisor_whose_conjugate_vanishes_is_twice_its_rational_part() {
        // √4 is taken as a leaf; force a symbol with a square radicand in
        // the field: s = √(3 + 2√2) = 1 + √2, divisor s − √2 − 1 + 2 = 1
        assert_eq!(
            sign(|| {
                let s = a(3.0).add(&a(2.0).mul(&a(2.0).sqrt())).sqrt();
                let divisor = s.sub(&a(2.0).sqrt()).add(&a(1.0));
                a(2.0).div(&divisor).sub(&a(1.0))
            }),
            0
        );
    }

    #[test]
    fn agrees_with_big_floats_on_random_expressions() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % 2001) as f64 - 1000.0
        };
        for _ in 0..200 {
            let (p, q, r, s) = (next(), next(), next(), next());
            let exact = exact_evaluation(|| {
                let v = a(p).mul(&a(p)).add(&a(q).abs()).sqrt().mul(&a(r)).sub(&a(s).abs().sqrt().div(&a(q.abs() + 1.0)));
                (v.signum(), v.to_f64())
            })
            .expect("within the limits");
            let big = |x: f64| BigFloat::from_f64(x, 400);
            let v = big(p).mul(&big(p)).add(&big(q).abs()).sqrt().mul(&big(r)).sub(&big(s).abs().sqrt().div(&big(q.abs() + 1.0)));
            assert_eq!(exact.0, v.signum(), "{p} {q} {r} {s}");
            assert!((exact.1 - v.to_f64()).abs() <= 1e-12 * v.to_f64().abs().max(1.0), "{p} {q} {r} {s}");
        }
    }

    #[test]
    fn evaluations_past_the_limits_give_up() {
        assert!(exact_evaluation(|| {
            let mut x = a(0.0);
            for k in 0..(MAX_ROOTS + 2) {
                x = x.add(&a(4.0 * k as f64 + 2.0).sqrt()); // never a square
            }
            x.signum()
        })
        .is_none());
    }
}
