//! Certified big floats: the arithmetic in which the oracle proves that a
//! question's value is exactly zero, instead of taking "below `2^-1150` of
//! the size" for zero.
//!
//! A [`Certified`] value is a ball (a big-float midpoint and a rigorous
//! upper bound on its distance to the exact value of the same expression,
//! every rounding accounted for) together with the quantities of the
//! BFMSS separation bound (Burnikel, Fleischer, Mehlhorn, Schirra, "A
//! separation bound for real algebraic expressions", with the improved
//! rule for roots): for an expression `E` built by `+ − × ÷ √` from
//! rational leaves, numbers `u(E)`, `l(E)` and the product `D(E)` of the
//! degrees of its radicals such that `E ≠ 0` implies
//! `|E| ≥ 1 / (u(E)^(D(E)−1) · l(E))`. A ball that lies within that bound
//! of zero therefore holds an exact zero. The input coordinates are
//! doubles, so every leaf is an integer times a power of two.
//!
//! The bound quantities are kept as base-2 logarithms in `f64`, each
//! rounded up by a margin, so they stay upper bounds. A radical used twice
//! counts twice in `D` (the arithmetic does not see shared
//! subexpressions): the bound is weaker than it could be, never wrong.
//!
//! Comparisons inside the solvers (`signum`) are exact where the ball
//! decides them or proves a zero; otherwise the midpoint's sign is taken
//! and the evaluation is marked unsure (a flag read by
//! [`certified_evaluation`]), because the branch taken may not be the
//! exact expression's.

use std::cell::Cell;

use num_bigint::{BigInt, Sign};

use super::bigfloat::{dyadic, BigFloat};
use super::real::Real;

/// Added to every logarithm of an upper bound, so that the `f64` rounding
/// of the logarithms themselves cannot make a bound too small.
const LOG_MARGIN: f64 = 1e-9;

/// The radicals of one evaluation are told apart by a bit each, so at
/// most this many; a value past them has no separation bound.
const MAX_RADICALS: u32 = 63;

/// Every radical bit: a value of an expression past `MAX_RADICALS`
/// radicals, or of an undecided division.
const ALL_RADICALS: u64 = u64::MAX;

/// A big-float ball with the BFMSS quantities of its expression.
#[derive(Clone, Debug)]
pub(crate) struct Certified {
    mid: BigFloat,
    /// `log2` of an upper bound on `|exact − mid|`; `-inf` when exact.
    log_radius: f64,
    /// `log2 u(E)`; `-inf` for the literal zero.
    log_u: f64,
    /// `log2 l(E)`.
    log_l: f64,
    /// The square roots in the expression's DAG, a bit each (numbered per
    /// evaluation, `certified_evaluation`): `D(E) = 2^(number of bits)`.
    /// A root used twice counts once, as in the bound's DAG form.
    radicals: u64,
}

thread_local! {
    /// Set when a comparison was decided by a midpoint whose ball did not
    /// decide it: the evaluation may have taken a branch the exact
    /// expression does not.
    static UNSURE: Cell<bool> = const { Cell::new(false) };
    /// The number of square roots taken in this evaluation so far.
    static ROOTS_TAKEN: Cell<u32> = const { Cell::new(0) };
}

/// Runs `evaluate` and returns its result with whether every comparison
/// in it was decided exactly (`false`: a branch may be wrong, the result
/// proves nothing).
pub(crate) fn certified_evaluation<R>(evaluate: impl FnOnce() -> R) -> (R, bool) {
    let before = UNSURE.with(|u| u.replace(false));
    let roots_before = ROOTS_TAKEN.with(|r| r.replace(0));
    let result = evaluate();
    let unsure = UNSURE.with(|u| u.replace(before));
    ROOTS_TAKEN.with(|r| r.set(roots_before));
    (result, !unsure)
}

fn mark_unsure() {
    UNSURE.with(|u| u.set(true));
}

/// The bit of a new radical of this evaluation (every bit once there are
/// too many).
fn new_radical() -> u64 {
    ROOTS_TAKEN.with(|r| {
        let k = r.get();
        r.set(k.saturating_add(1));
        if k < MAX_RADICALS {
            1 << k
        } else {
            ALL_RADICALS
        }
    })
}

/// `log2 (2^a + 2^b)`, rounded up.
fn log_add(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        // `-inf + inf`: a zero midpoint times an unbounded ball's radius
        return f64::INFINITY;
    }
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if lo == f64::NEG_INFINITY {
        return hi;
    }
    hi + (1.0 + (lo - hi).exp2()).log2() + LOG_MARGIN
}

/// `log2` of an upper bound on `|x|`.
fn log_magnitude(x: &BigFloat) -> f64 {
    match x.magnitude_exponent() {
        i64::MIN => f64::NEG_INFINITY,
        e => (e + 1) as f64,
    }
}

/// `log2` of an upper bound on the truncation error of an operation whose
/// rounded result is `result` (every `BigFloat` operation truncates to its
/// precision once, after an exact or extra-precise step; a sum of terms
/// far apart keeps a sticky unit instead of the small term).
fn log_rounding(result: &BigFloat) -> f64 {
    match result.magnitude_exponent() {
        i64::MIN => f64::NEG_INFINITY,
        e => (e + 4 - result.precision() as i64) as f64,
    }
}

impl Certified {
    /// `x` exactly (finite `x`), computing at `bits` of precision.
    pub fn from_f64(x: f64, bits: u64) -> Certified {
        let mid = BigFloat::from_f64(x, bits);
        let Some((m, e)) = dyadic(x) else {
            return Certified { mid, log_radius: f64::NEG_INFINITY, log_u: f64::NEG_INFINITY, log_l: 0.0, radicals: 0 };
        };
        // x = m 2^e: u = m 2^max(e,0), l = 2^max(-e,0)
        let log_m = (m as f64).log2() + LOG_MARGIN;
        Certified { mid, log_radius: f64::NEG_INFINITY, log_u: log_m + e.max(0) as f64, log_l: (-e).max(0) as f64, radicals: 0 }
    }

    /// `m · 2^e` (an exact dyadic number), computing at `bits` of
    /// precision: the midpoint truncated, the truncation the radius.
    pub fn from_parts(m: &BigInt, e: i64, bits: u64) -> Certified {
        if m.sign() == Sign::NoSign {
            return Certified::from_f64(0.0, bits);
        }
        let mid = BigFloat::from_parts(m, e, bits);
        let log_radius = if m.bits() > bits { log_rounding(&mid) } else { f64::NEG_INFINITY };
        // |m| < 2^bits(m): u = |m| 2^max(e,0), l = 2^max(-e,0)
        Certified { mid, log_radius, log_u: m.bits() as f64 + e.max(0) as f64, log_l: (-e).max(0) as f64, radicals: 0 }
    }

    /// `log2` of the bound on the distance from the midpoint to the exact
    /// value.
    pub fn log_radius(&self) -> f64 {
        self.log_radius
    }

    /// `log2` of the BFMSS lower bound's reciprocal: a nonzero value of the
    /// expression is at least `2^-separation_bits`; `inf` when the bound
    /// is out of reach.
    pub fn separation_bits(&self) -> f64 {
        if self.log_u == f64::NEG_INFINITY {
            return 0.0;
        }
        let count = self.radicals.count_ones();
        if count > MAX_RADICALS / 2 {
            return f64::INFINITY;
        }
        let d = (1u64 << count) as f64;
        (d - 1.0) * self.log_u.max(0.0) + self.log_l
    }

    /// The exact sign: `Some(0)` when the ball proves a zero, `None` when
    /// it is too wide to tell.
    pub fn exact_sign(&self) -> Option<i32> {
        let log_mid = log_magnitude(&self.mid);
        // |mid| ≥ 2^(log_mid − 1) > radius: the sign of the midpoint
        if self.mid.signum() != 0 && log_mid - 1.0 > self.log_radius {
            return Some(self.mid.signum());
        }
        // |exact| ≤ |mid| + radius below the separation bound: zero
        (log_add(log_mid, self.log_radius) < -self.separation_bits()).then_some(0)
    }

    /// The result of an operation: the rounded midpoint, its radius, the
    /// bound's quantities; snapped to an exact zero where it proves one.
    fn made(mid: BigFloat, log_radius: f64, log_u: f64, log_l: f64, radicals: u64) -> Certified {
        let log_radius = log_add(log_radius, log_rounding(&mid));
        let value = Certified { mid, log_radius, log_u, log_l, radicals };
        if value.log_radius > f64::NEG_INFINITY && value.exact_sign() == Some(0) {
            return value.zero();
        }
        value
    }

    /// The literal zero, at this value's precision.
    fn zero(&self) -> Certified {
        Certified::from_f64(0.0, self.mid.precision())
    }

    fn sum(&self, o: &Certified, mid: BigFloat) -> Certified {
        Certified::made(
            mid,
            log_add(self.log_radius, o.log_radius),
            log_add(self.log_u + o.log_l, o.log_u + self.log_l),
            self.log_l + o.log_l,
            self.radicals | o.radicals,
        )
    }

    /// The ball of `|self|`'s magnitude as `(log |mid| lower, upper)`.
    fn magnitude_bounds(&self) -> (f64, f64) {
        let log_mid = log_magnitude(&self.mid);
        (log_mid - 1.0, log_mid)
    }
}

impl Real for Certified {
    fn add(&self, o: &Certified) -> Certified {
        self.sum(o, &self.mid + &o.mid)
    }

    fn sub(&self, o: &Certified) -> Certified {
        self.sum(o, &self.mid - &o.mid)
    }

    fn mul(&self, o: &Certified) -> Certified {
        let (_, a) = self.magnitude_bounds();
        let (_, b) = o.magnitude_bounds();
        // |xy − x̃ỹ| ≤ |x̃| ry + |ỹ| rx + rx ry
        let radius = log_add(log_add(a + o.log_radius, b + self.log_radius), self.log_radius + o.log_radius);
        Certified::made(&self.mid * &o.mid, radius, self.log_u + o.log_u, self.log_l + o.log_l, self.radicals | o.radicals)
    }

    fn div(&self, o: &Certified) -> Certified {
        let (b_low, b) = o.magnitude_bounds();
        if o.mid.signum() == 0 || b_low - 1.0 <= o.log_radius {
            // the divisor's ball reaches within a factor of two of zero
            mark_unsure();
            let mid = self.mid.div(&o.mid);
            return Certified { mid, log_radius: f64::INFINITY, log_u: 0.0, log_l: 0.0, radicals: ALL_RADICALS };
        }
        let (_, a) = self.magnitude_bounds();
        // |x/y − x̃/ỹ| ≤ (rx |ỹ| + |x̃| ry) / (|ỹ| (|ỹ| − ry)), |ỹ| − ry ≥ |ỹ|/2
        let numerator = log_add(self.log_radius + b, a + o.log_radius);
        let radius = numerator - b_low - (b_low - 1.0);
        Certified::made(self.mid.div(&o.mid), radius, self.log_u + o.log_l, self.log_l + o.log_u, self.radicals | o.radicals)
    }

    fn sqrt(&self) -> Certified {
        // the improved BFMSS rule for square roots
        let (log_u, log_l) = if self.log_u >= self.log_l {
            ((self.log_u + self.log_l) / 2.0 + LOG_MARGIN, self.log_l)
        } else {
            (self.log_u, (self.log_u + self.log_l) / 2.0 + LOG_MARGIN)
        };
        let radicals = self.radicals | new_radical();
        if self.log_u == f64::NEG_INFINITY {
            return self.zero();
        }
        let root = self.mid.sqrt();
        let (low, _) = self.magnitude_bounds();
        let radius = if self.mid.signum() != 0 && low - 1.0 > self.log_radius {
            // |√x − √x̃| ≤ r / √(|x̃| − r) ≤ r / √(|x̃|/2)
            self.log_radius - (low - 1.0) / 2.0
        } else {
            // a ball reaching zero: √ of the whole ball, [0, √(|x̃| + r)]
            log_add(log_magnitude(&self.mid), self.log_radius) / 2.0 + LOG_MARGIN
        };
        Certified::made(root, radius, log_u, log_l, radicals)
    }

    fn neg(&self) -> Certified {
        Certified { mid: -&self.mid, ..self.clone() }
    }

    fn abs(&self) -> Certified {
        Certified { mid: self.mid.abs(), ..self.clone() }
    }

    fn signum(&self) -> i32 {
        self.exact_sign().unwrap_or_else(|| {
            mark_unsure();
            self.mid.signum()
        })
    }

    fn to_f64(&self) -> f64 {
        self.mid.to_f64()
    }

    fn recip(&self) -> Certified {
        Certified::from_f64(1.0, self.mid.precision()).div(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(x: f64) -> Certified {
        Certified::from_f64(x, 3000)
    }

    #[test]
    fn identities_with_square_roots_are_proven_zero() {
        // √2 √2 − 2
        let two = c(2.0);
        let (e, sure) = certified_evaluation(|| two.sqrt().mul(&two.sqrt()).sub(&two));
        assert!(sure);
        assert_eq!(e.exact_sign(), Some(0));
        // (√x + √y)² − (x + y + 2 √(xy)) for x = 3.25, y = 7e-3
        let (x, y) = (c(3.25), c(7e-3));
        let lhs = x.sqrt().add(&y.sqrt());
        let rhs = x.add(&y).add(&c(2.0).mul(&x.mul(&y).sqrt()));
        assert_eq!(lhs.mul(&lhs).sub(&rhs).exact_sign(), Some(0));
        // the same quantity divided: (√x − √y)(√x + √y) / (x − y) − 1
        let q = x.sqrt().sub(&y.sqrt()).mul(&x.sqrt().add(&y.sqrt())).div(&x.sub(&y)).sub(&c(1.0));
        assert_eq!(q.exact_sign(), Some(0));
    }

    #[test]
    fn tiny_nonzero_values_get_their_sign() {
        // √(2^100 + 1) − 2^50 ≈ 2^-51: positive, far below the operands
        let big = c(2f64.powi(100)).add(&c(1.0));
        let d = big.sqrt().sub(&c(2f64.powi(50)));
        assert_eq!(d.exact_sign(), Some(1));
        // 1/3 − 0.333…: a rational, nonzero
        let third = c(1.0).div(&c(3.0));
        assert_eq!(third.sub(&c(1.0 / 3.0)).exact_sign(), Some(1));
        assert_eq!(c(1.0 / 3.0).sub(&third).exact_sign(), Some(-1));
    }

    #[test]
    fn the_ball_holds_the_value_of_a_finer_evaluation() {
        let coarse = |bits| {
            Certified::from_f64(5.0, bits).sqrt().div(&Certified::from_f64(7.0, bits)).add(&Certified::from_f64(0.1, bits))
        };
        let (low, high) = (coarse(80), coarse(800));
        let gap = (&low.mid - &high.mid).abs();
        assert!(log_magnitude(&gap) <= low.log_radius, "{} > {}", log_magnitude(&gap), low.log_radius);
        assert!(low.log_radius < -70.0);
    }

    #[test]
    fn undecided_comparisons_mark_the_evaluation_unsure() {
        // a difference below the precision that no bound proves zero:
        // √(2^200 + 1) − 2^100 at 60 bits
        let bits = 60;
        let lift = |x: f64| Certified::from_f64(x, bits);
        let (_, sure) = certified_evaluation(|| lift(2f64.powi(200)).add(&lift(1.0)).sqrt().sub(&lift(2f64.powi(100))).signum());
        assert!(!sure);
        let (sign, sure) = certified_evaluation(|| lift(3.0).sub(&lift(2.0)).signum());
        assert!(sure);
        assert_eq!(sign, 1);
    }
}
